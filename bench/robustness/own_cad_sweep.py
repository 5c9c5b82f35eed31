#!/usr/bin/env python3
"""Issue #23's acceptance sweep: every generated wing variant and every file of ../shared/testdata/cad
through `semimesh init --cad FILE -o c.toml` then `semimesh run c.toml --set highorder.order=P`, with
init's own sizes and nothing else set (the CTests `cli.init_cad_*_run` run the same files at coarse
sizes). Prints, per file: init's topology, the run's exit status, elements, invalid elements, the
smallest scaled Jacobian, init's and the run's wall time and peak memory; with --gmsh, Gmsh's certified
smallest ratio of the order-P mesh too (tests/pipeline/gmsh_validity.py: slow on large meshes).

usage: own_cad_sweep.py SEMIMESH WRITE_WING_VARIANT OUT [--orders 2,4] [--gmsh] [--only NAME,...]
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SHARED = os.path.join(HERE, "..", "..", "..", "shared", "testdata", "cad")

# name: (write_wing_variant kind, file extension, its naca.* parameters); as the CTests write them.
VARIANTS = {
    "nurbs_walls": ("nurbs", "step", ["naca.span=1", "naca.box=-3,-3,0,4,3,3"]),
    "open_root": ("asis", "step", ["naca.span=1", "naca.farfield=false"]),
    "capped_root": ("capped", "step", ["naca.span=1", "naca.farfield=false"]),
    "open_tip": ("open_tip", "step", ["naca.span=1", "naca.farfield=false"]),
    "unsewn_iges": ("unsewn", "igs", ["naca.span=1", "naca.farfield=false"]),
    "hemisphere": ("hemisphere", "step", ["naca.span=1", "naca.farfield=false"]),
    "bezier_patches": ("bezier_patches", "step", ["naca.span=1", "naca.farfield=false"]),
    "split_base": ("split_base", "step", ["naca.span=1", "naca.farfield=false"]),
    "fuselage": ("fuselage", "step", ["naca.span=1", "naca.farfield=false"]),
    "fuselage_bspline": ("fuselage_bspline", "step", ["naca.span=1", "naca.farfield=false"]),
    "fuselage_dihedral": ("fuselage_dihedral", "step", ["naca.span=1", "naca.farfield=false"]),
    "fuselage_unjoined": ("fuselage_unjoined", "step", ["naca.span=1", "naca.farfield=false"]),
    "fuselage_bspline_unjoined": ("fuselage_bspline_unjoined", "step", ["naca.span=1", "naca.farfield=false"]),
    "fuselage_nosed_unjoined": ("fuselage_nosed_unjoined", "step", ["naca.span=1", "naca.farfield=false"]),
    "fuselage_through": ("fuselage_through", "step", ["naca.span=1", "naca.farfield=false"]),
    "seam_skin": ("seam_skin", "step", []),
    "cranked": ("cranked", "step", []),
    "cranked_split_base": ("cranked_split_base", "step", []),
    "cranked_sharp": ("cranked", "step", ["naca.te=sharp"]),
    "cranked_mm": ("cranked_mm", "step", []),
    "cranked_m": ("cranked_m", "step", []),
}


def timed(cmd):
    start = time.monotonic()
    done = subprocess.run(cmd, capture_output=True, text=True)
    return done, time.monotonic() - start


def summary_value(stdout, label):
    m = re.search(r"^\s*" + re.escape(label) + r"\s+(\S+)", stdout, re.M)
    return m.group(1) if m else "-"


def sweep_one(args, name, cad, order, out):
    work = os.path.join(out, name)
    config = os.path.join(work, "c.toml")
    if os.path.exists(config):
        os.remove(config)  # init refuses to overwrite a file
    init, init_s = timed([args.semimesh, "init", "--cad", cad, "-o", config])
    if init.returncode != 0:
        return [name, "-", f"init {init.returncode}", "", "", "", f"{init_s:.1f}", "", "", init.stderr.strip()[:160]]
    topology = re.search(r'^topology\s*=\s*"(\w)"', open(config).read(), re.M)
    run_out = os.path.join(work, f"o{order}")
    run, run_s = timed([args.semimesh, "run", config, "-o", run_out, "--set", f"highorder.order={order}"])
    row = [name, topology.group(1) if topology else "?", str(run.returncode)]
    if run.returncode != 0:
        return row + ["", "", "", f"{init_s:.1f}", f"{run_s:.1f}", "", run.stderr.strip()[-200:]]
    with open(os.path.join(run_out, "report.json")) as f:
        report = json.load(f)
    gmsh = ""
    if args.gmsh:
        sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "pipeline"))
        from gmsh_validity import certified_ratios
        msh = [f for f in os.listdir(run_out) if f.endswith(".msh")]
        ratios = certified_ratios(os.path.join(run_out, msh[0]))
        gmsh = "%.3g" % min(ratios["direct"] + ratios["prisms"] + ratios["pyramids"])
    row += [str(report["elements"]), summary_value(run.stdout, "invalid elements"),
            summary_value(run.stdout, "min scaled Jacobian"), f"{init_s:.1f}", f"{run_s:.1f}",
            "%.0f" % report.get("peak_memory_mb", 0), gmsh]
    if not args.keep:
        shutil.rmtree(run_out, ignore_errors=True)
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("semimesh")
    parser.add_argument("writer", help="build/tests/occ/write_wing_variant")
    parser.add_argument("out")
    parser.add_argument("--orders", default="2,4")
    parser.add_argument("--gmsh", action="store_true")
    parser.add_argument("--only", default="", help="comma-separated names")
    parser.add_argument("--keep", action="store_true", help="keep the meshes")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    files = {}
    for name, (kind, ext, naca) in VARIANTS.items():
        files[name] = (kind, ext, naca)
    for shared in sorted(os.listdir(SHARED)) if os.path.isdir(SHARED) else []:
        if shared.endswith((".stp", ".step", ".igs", ".iges")):
            files[os.path.splitext(shared)[0]] = (None, os.path.join(SHARED, shared), [])
    only = set(filter(None, args.only.split(",")))
    header = ["file", "topology", "exit", "elements", "invalid", "min scaled J", "init s", "run s", "peak MB",
              "gmsh min J/maxJ" if args.gmsh else ""]
    print(" | ".join(header), flush=True)
    for order in [int(o) for o in args.orders.split(",")]:
        print(f"-- order {order}", flush=True)
        for name, (kind, ext, naca) in files.items():
            if only and name not in only:
                continue
            work = os.path.join(args.out, name)
            os.makedirs(work, exist_ok=True)
            if kind is None:
                cad = ext
            else:
                cad = os.path.join(work, "wing." + ext)
                if not os.path.exists(cad):
                    done = subprocess.run([args.writer, kind, cad] + naca, capture_output=True, text=True)
                    if done.returncode != 0:
                        print(f"{name} | write_wing_variant exited {done.returncode}: {done.stderr.strip()[:200]}")
                        continue
            print(" | ".join(sweep_one(args, name, cad, order, args.out)), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
