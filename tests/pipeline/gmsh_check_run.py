"""End-to-end check of `semimesh run` through the CLI, read back by an independent program.

Runs the CLI on a coarse case, checks the exit code, opens the produced .msh files (4.1 and 2.2)
with Gmsh (Debian's /usr/bin/python3 has the module), counts the elements by type against
report.json, and asks Gmsh's own AnalyseMeshQuality plugin (certified Jacobian bounds) for the
min J / max J of every element, prisms of order >= 3 through their exact hex pieces, pyramids of
order >= 4 through exact bounds on Gmsh's own basis (Gmsh 4.8's plugin is wrong for them; see
gmsh_validity.py and pyramid_bounds.py): all must be positive. Then checks exit codes of bad inputs.

  gmsh_check_run.py --exe SEMIMESH --config CASE.toml --workdir DIR [--set KEY=VALUE ...]
                    [--timeout SECONDS] [--skip-bad-input] [--regions NAME,NAME,...]

--set options go to the main run only (e.g. highorder.order=2 for a curved mesh).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gmsh_validity import certified_ratios, gmsh_counts  # noqa: E402


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run_cli(exe, args, timeout=240):
    done = subprocess.run([exe] + args, capture_output=True, text=True, timeout=timeout)
    return done.returncode, done.stdout, done.stderr


def progress(done, total):
    if done == total or done % 10 == 0:
        print("gmsh: prism pieces, chunk %d of %d" % (done, total), flush=True)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", required=True)
    parser.add_argument("--config", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--set", action="append", default=[], help="config override for the main run")
    parser.add_argument("--skip-bad-input", action="store_true", help="only the main run and its check")
    parser.add_argument("--counts-only", action="store_true",
                        help="gmsh reads and counts the elements but does not certify them (order > 6: Gmsh's "
                             "Bezier matrices for the Jacobian of an order-8 hex take minutes per element type)")
    parser.add_argument("--timeout", type=float, default=240, help="seconds for the main run")
    parser.add_argument("--regions", default="",
                        help="comma-separated regions report.json must hold elements in (e.g. the H-type's wake)")
    args = parser.parse_args()
    shutil.rmtree(args.workdir, ignore_errors=True)
    out = os.path.join(args.workdir, "out")

    overrides = [a for kv in args.set for a in ("--set", kv)]
    code, stdout, stderr = run_cli(args.exe, ["run", args.config, "-o", out] + overrides, args.timeout)
    if code != 0:
        fail("semimesh run exited with %d\n%s\n%s" % (code, stdout, stderr))
    for stage in ("load CAD", "surface mesh", "near field", "far field", "checks", "write"):
        if stage not in stdout:
            fail("no progress line for stage '%s' in:\n%s" % (stage, stdout))
    with open(os.path.join(out, "report.json")) as f:
        report = json.load(f)
    for region in filter(None, args.regions.split(",")):
        if report["elements_by_region"].get(region, 0) <= 0:
            fail("report.json: no elements in region '%s': %s" % (region, report["elements_by_region"]))

    written = sorted(f for f in os.listdir(out) if f.endswith(".msh"))
    if not written:
        fail("no .msh file written in %s: %s" % (out, os.listdir(out)))
    for msh in written:
        started = time.time()
        if args.counts_only:
            counts = gmsh_counts(os.path.join(out, msh))
            if counts != report["elements_by_type"]:
                fail("%s: gmsh counts %s, report.json %s" % (msh, counts, report["elements_by_type"]))
            print("%s: gmsh reads %s (order %d)" % (msh, counts, report["order"]))
            continue
        gmsh_says = certified_ratios(os.path.join(out, msh), progress=progress)
        counts, direct, prisms = gmsh_says["counts"], gmsh_says["direct"], gmsh_says["prisms"]
        pyramids = gmsh_says["pyramids"]
        if counts != report["elements_by_type"]:
            fail("%s: gmsh counts %s, report.json %s" % (msh, counts, report["elements_by_type"]))
        if len(direct) + len(prisms) + len(pyramids) != report["elements"]:
            fail("%s: gmsh certified %d elements, report.json has %d"
                 % (msh, len(direct) + len(prisms) + len(pyramids), report["elements"]))
        worst = min(direct + prisms + pyramids)
        if worst <= 0.0:
            fail("%s: gmsh finds an invalid element (min J / max J = %g)" % (msh, worst))
        # Ours is a certified lower bound of the true ratio: it may not exceed Gmsh's upper bound
        # of it (its certified ratio where that converges, a sampled one for pyramids). (The hex
        # pieces of high-order prisms have another ratio: only their sign is compared.)
        comparable = gmsh_says["comparable"]
        if comparable and report["min_scaled_jacobian"] > min(comparable) + 1e-9:
            fail("%s: report min scaled Jacobian %g above gmsh's %g" % (msh, report["min_scaled_jacobian"], min(comparable)))
        if report["order"] != report["requested_order"]:
            fail("report.json: order %d, requested %d" % (report["order"], report["requested_order"]))
        print("%s: %s; gmsh certified %d elements directly (min J/max J %.4g) and %d prisms of order >= 3 "
              "as hex pieces (min %.4g); %d pyramids of order >= 4 bounded on gmsh's basis (min %.4g); "
              "report min scaled Jacobian %.4g; %.0f s"
              % (msh, counts, len(direct), min(direct) if direct else float("nan"), len(prisms),
                 min(prisms) if prisms else float("nan"), len(pyramids), min(pyramids) if pyramids else float("nan"),
                 report["min_scaled_jacobian"], time.time() - started))

    if args.skip_bad_input:
        print("ok")
        return
    bad = os.path.join(args.workdir, "bad")
    c_type = ["nearfield.topology=C", "wall_layer.thickness=0.04"]
    # A fragment of each message, or several that must all be there.
    for overrides, expected in ((["nearfield.topology=H", "wall_layer.thickness=0"], "stands a gap above the wall layer"),
                                (["boundary_layer.ratio=0.5"], "boundary_layer.ratio = 0.5: expected >= 1"),
                                (["geometry.wall=floor"], "no surface named 'floor'"),
                                (c_type + ["nearfield.junction_min_angle=100"],
                                 ("meets the wall at 90 degrees (seen from the fluid) at (", "nearfield.junction_min_angle")),
                                (c_type + ["wall_layer.thickness=0.6"], "wall layer thickness 0.6")):
        sets = [a for kv in overrides for a in ("--set", kv)]
        code, _, stderr = run_cli(args.exe, ["run", args.config, "-o", bad] + sets)
        fragments = expected if isinstance(expected, tuple) else (expected,)
        if code != 1 or any(f not in stderr for f in fragments):
            fail("--set %s: exit %d (expected 1), stderr:\n%s" % (" ".join(overrides), code, stderr))
        if os.path.exists(bad) and os.listdir(bad):
            fail("--set %s: files written: %s" % (" ".join(overrides), os.listdir(bad)))
    print("ok")


if __name__ == "__main__":
    main()
