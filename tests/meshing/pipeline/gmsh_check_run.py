"""End-to-end check of `semimesh run` through the CLI, read back by an independent program.

Runs the CLI on a coarse case, checks the exit code, opens the produced .msh files (4.1 and 2.2)
with Gmsh (Debian's /usr/bin/python3 has the module), counts the elements by type against
report.json, and asks Gmsh's own AnalyseMeshQuality plugin (certified Jacobian bounds) for the
min J / max J of every element: all must be positive. Then checks exit codes of bad inputs.

  gmsh_check_run.py --exe SEMIMESH --config CASE.toml --workdir DIR [--set KEY=VALUE ...]

--set options go to the main run only (e.g. highorder.order=2 for a curved mesh).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

import gmsh

GMSH_TYPE_NAMES = {"Tetrahedron": "tetrahedron", "Prism": "prism", "Pyramid": "pyramid", "Hexahedron": "hexahedron"}


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run_cli(exe, args):
    done = subprocess.run([exe] + args, capture_output=True, text=True, timeout=240)
    return done.returncode, done.stdout, done.stderr


def gmsh_counts_and_quality(path):
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(path)
        counts = {}
        types, tags, _ = gmsh.model.mesh.getElements(3)
        for element_type, element_tags in zip(types, tags):
            name = gmsh.model.mesh.getElementProperties(element_type)[0].split(" ")[0]
            counts[GMSH_TYPE_NAMES.get(name, name)] = len(element_tags)
        gmsh.plugin.setNumber("AnalyseMeshQuality", "JacobianDeterminant", 1)
        gmsh.plugin.setNumber("AnalyseMeshQuality", "CreateView", 1)
        gmsh.plugin.setNumber("AnalyseMeshQuality", "DimensionOfElements", 3)
        gmsh.plugin.run("AnalyseMeshQuality")
        ratios = []
        for view in gmsh.view.getTags():
            name = gmsh.option.getString("View[%d].Name" % gmsh.view.getIndex(view))
            if name.startswith("minJ/maxJ"):
                _, _, data, _, _ = gmsh.view.getModelData(view, 0)
                ratios = [d[0] for d in data]
        return counts, ratios
    finally:
        gmsh.finalize()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", required=True)
    parser.add_argument("--config", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--set", action="append", default=[], help="config override for the main run")
    args = parser.parse_args()
    shutil.rmtree(args.workdir, ignore_errors=True)
    out = os.path.join(args.workdir, "out")

    overrides = [a for kv in args.set for a in ("--set", kv)]
    code, stdout, stderr = run_cli(args.exe, ["run", args.config, "-o", out] + overrides)
    if code != 0:
        fail("semimesh run exited with %d\n%s\n%s" % (code, stdout, stderr))
    for stage in ("load CAD", "surface mesh", "near field", "far field", "checks", "write"):
        if stage not in stdout:
            fail("no progress line for stage '%s' in:\n%s" % (stage, stdout))
    with open(os.path.join(out, "report.json")) as f:
        report = json.load(f)

    written = sorted(f for f in os.listdir(out) if f.endswith(".msh"))
    if not written:
        fail("no .msh file written in %s: %s" % (out, os.listdir(out)))
    for msh in written:
        counts, ratios = gmsh_counts_and_quality(os.path.join(out, msh))
        if counts != report["elements_by_type"]:
            fail("%s: gmsh counts %s, report.json %s" % (msh, counts, report["elements_by_type"]))
        if len(ratios) != report["elements"]:
            fail("%s: gmsh measured %d elements, report.json has %d" % (msh, len(ratios), report["elements"]))
        worst = min(ratios)
        if worst <= 0.0:
            fail("%s: gmsh finds an invalid element (min J / max J = %g)" % (msh, worst))
        # Ours is a certified lower bound of the same ratio: it may not exceed Gmsh's.
        if report["min_scaled_jacobian"] > worst + 1e-9:
            fail("%s: report min scaled Jacobian %g above gmsh's %g" % (msh, report["min_scaled_jacobian"], worst))
        if report["order"] != report["requested_order"]:
            fail("report.json: order %d, requested %d" % (report["order"], report["requested_order"]))
        print("%s: %s, gmsh min J/max J = %.4g, report %.4g" % (msh, counts, worst, report["min_scaled_jacobian"]))

    bad = os.path.join(args.workdir, "bad")
    for override, expected in (("nearfield.topology=C", "not implemented yet"),
                               ("boundary_layer.ratio=0.5", "boundary_layer.ratio = 0.5: expected >= 1"),
                               ("geometry.wall=floor", "no surface named 'floor'")):
        code, _, stderr = run_cli(args.exe, ["run", args.config, "-o", bad, "--set", override])
        if code != 1 or expected not in stderr:
            fail("--set %s: exit %d (expected 1), stderr:\n%s" % (override, code, stderr))
        if os.path.exists(bad) and os.listdir(bad):
            fail("--set %s: files written: %s" % (override, os.listdir(bad)))
    print("ok")


if __name__ == "__main__":
    main()
