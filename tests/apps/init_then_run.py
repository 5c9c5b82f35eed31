"""`semimesh init --cad FILE` output run by `semimesh run` unchanged but for the given --set keys.

  init_then_run.py --exe SEMIMESH --cad FILE --workdir DIR [--set KEY=VALUE ...] [--regions A,B,...]
                   [--writer WRITE_WING_VARIANT --variant NAME [--naca KEY=VALUE ...]] [--gmsh]
                   [--init-says TEXT ...] [--init-refuses-with TEXT] [--run-says TEXT ...]
                   [--config TOML] [--group-on-plane GROUP=AXIS:VALUE] [--min-jacobian REGION=VALUE ...]
                   [--solver-rules]

With --writer, FILE is first written by tests/occ/write_wing_variant (the occ backend's B-spline
NACA wing as a file of the named kind). Writes DIR/wing.toml with init, runs it into DIR/out, and
fails unless the run exits 0 with 0 invalid elements (and elements in each of the given regions, by
report.json); with --gmsh, Gmsh's own certified Jacobian bounds of every element of the written
.msh must be positive too (tests/pipeline/gmsh_validity.py). --init-says: init's output (the
config's header comments and its warnings) must hold TEXT. --init-refuses-with: init must exit 1
with TEXT on stderr and write no config (nothing is run). --run-says: the run's summary must hold TEXT.
--config: run TOML (copied to DIR/wing.toml, its geometry.source set to FILE) instead of init's
config: a file init refuses but a user's own config meshes (an assembly joined by geometry.join).
--group-on-plane (with --gmsh): read by Gmsh, the .msh's boundary group GROUP has faces, every node
of them on the plane AXIS = VALUE, and no face of another group lies on that plane (a half model's
symmetry plane, farfield.symmetry).
--min-jacobian: the region's min scaled Jacobian (report.json) must be at least VALUE.
--solver-rules: every Nektar++ XML written meets Nektar++'s load-time rules (tests/io/nektar_rules.py)
and every ASCII MSH PyFR's reader's (tests/io/pyfr_rules.py); at least one file is checked.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys


def group_alone_on_plane(msh, spec):
    """Whether GROUP of GROUP=AXIS:VALUE has faces all on the plane and no other group's face lies on it."""
    import gmsh
    group, plane = spec.split("=")
    axis, value = "xyz".index(plane.split(":")[0]), float(plane.split(":")[1])
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(msh)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        position = dict(zip(tags, coords.reshape(-1, 3)[:, axis]))
        size = max(abs(c) for c in coords) or 1.0
        on_plane = lambda nodes: all(abs(position[n] - value) <= 1e-9 * size for n in nodes)
        faces_on_plane = {}
        for dim, tag in gmsh.model.getPhysicalGroups(2):
            name = gmsh.model.getPhysicalName(dim, tag)
            on, off = 0, 0
            for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
                types, _, nodes = gmsh.model.mesh.getElements(dim, entity)
                for element_type, element_nodes in zip(types, nodes):
                    per = gmsh.model.mesh.getElementProperties(element_type)[3]
                    for k in range(0, len(element_nodes), per):
                        if on_plane(element_nodes[k:k + per]):
                            on += 1
                        else:
                            off += 1
            faces_on_plane[name] = (on, off)
    finally:
        gmsh.finalize()
    print("faces on the plane, off it, by group: %s" % faces_on_plane)
    on, off = faces_on_plane.get(group, (0, 0))
    if on == 0 or off != 0:
        print("FAIL: group '%s' has %d faces on the plane %s and %d off it" % (group, on, plane, off))
        return False
    others = [name for name, (n, _) in faces_on_plane.items() if name != group and n > 0]
    if others:
        print("FAIL: groups %s have faces on the plane %s too" % (others, plane))
        return False
    return True


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", required=True)
    parser.add_argument("--cad", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--set", action="append", default=[], help="config override for the run")
    parser.add_argument("--regions", default="", help="comma-separated regions the mesh must hold elements in")
    parser.add_argument("--writer", help="write_wing_variant, to write FILE first")
    parser.add_argument("--variant", help="the variant write_wing_variant writes")
    parser.add_argument("--naca", action="append", default=[], help="naca.KEY=VALUE for write_wing_variant")
    parser.add_argument("--gmsh", action="store_true", help="certify the .msh with Gmsh too")
    parser.add_argument("--init-says", action="append", default=[], help="text init must write or warn")
    parser.add_argument("--init-refuses-with", help="init must exit 1 with this text on stderr")
    parser.add_argument("--run-refuses-with", help="run must exit 1 with this text on stderr, writing no mesh")
    parser.add_argument("--run-says", action="append", default=[], help="text the run's summary must hold")
    parser.add_argument("--config", help="a config to run instead of init's (its source set to FILE)")
    parser.add_argument("--group-on-plane", help="GROUP=AXIS:VALUE: the .msh group lying on that plane, alone")
    parser.add_argument("--min-jacobian", action="append", default=[], help="REGION=VALUE: its least scaled Jacobian")
    parser.add_argument("--solver-rules", action="store_true", help="Nektar++'s and PyFR's rules on the files")
    args = parser.parse_args()
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    if args.writer:
        done = subprocess.run([args.writer, args.variant, args.cad] + args.naca, capture_output=True, text=True)
        if done.returncode != 0:
            print("FAIL: write_wing_variant exited with %d\n%s" % (done.returncode, done.stderr))
            return 1
    config = os.path.join(args.workdir, "wing.toml")
    if args.config:
        shutil.copyfile(args.config, config)
        args.set.insert(0, "geometry.source=" + os.path.abspath(args.cad))
        done = subprocess.CompletedProcess([], 0, "", "")
    else:
        done = subprocess.run([args.exe, "init", "--cad", args.cad, "-o", config], capture_output=True, text=True)
    if args.init_refuses_with is not None:
        print(done.stderr)
        if done.returncode != 1 or args.init_refuses_with not in done.stderr:
            print("FAIL: expected init to exit 1 saying '%s'; it exited %d" % (args.init_refuses_with, done.returncode))
            return 1
        if os.path.exists(config):
            print("FAIL: init refused but wrote %s" % config)
            return 1
        print("ok")
        return 0
    if done.returncode != 0:
        print("FAIL: init exited with %d\n%s" % (done.returncode, done.stderr))
        return 1
    with open(config) as f:
        said = f.read() + done.stderr
    for text in args.init_says:
        if text not in said:
            print("FAIL: init's config and warnings do not say '%s':\n%s" % (text, said[:3000]))
            return 1
    overrides = [a for kv in args.set for a in ("--set", kv)]
    done = subprocess.run([args.exe, "run", config, "-o", os.path.join(args.workdir, "out")] + overrides,
                          capture_output=True, text=True)
    print(done.stdout)
    if args.run_refuses_with is not None:
        print(done.stderr)
        if done.returncode != 1 or args.run_refuses_with not in done.stderr:
            print("FAIL: expected run to exit 1 saying '%s'; it exited %d" % (args.run_refuses_with, done.returncode))
            return 1
        if os.path.exists(os.path.join(args.workdir, "out")) and os.listdir(os.path.join(args.workdir, "out")):
            print("FAIL: run refused but wrote into %s" % os.path.join(args.workdir, "out"))
            return 1
        print("ok")
        return 0
    if done.returncode != 0:
        print("FAIL: run exited with %d\n%s" % (done.returncode, done.stderr))
        return 1
    if "invalid elements                        0" not in done.stdout:
        print("FAIL: the run reports invalid elements")
        return 1
    for text in args.run_says:
        if text not in done.stdout:
            print("FAIL: the run's summary does not say '%s'" % text)
            return 1
    with open(os.path.join(args.workdir, "out", "report.json")) as f:
        report = json.load(f)
    regions = report["elements_by_region"]
    for bound in args.min_jacobian:
        region, value = bound.split("=")
        least = report["min_scaled_jacobian_by_region"].get(region)
        if least is None or least < float(value):
            print("FAIL: region '%s' has min scaled Jacobian %s, below %s" % (region, least, value))
            return 1
    for region in filter(None, args.regions.split(",")):
        if regions.get(region, 0) <= 0:
            print("FAIL: no elements in region '%s': %s" % (region, regions))
            return 1
    if args.gmsh:
        sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pipeline"))
        from gmsh_validity import certified_ratios
        meshes = [f for f in os.listdir(os.path.join(args.workdir, "out")) if f.endswith(".msh")]
        if not meshes:
            print("FAIL: --gmsh, but the run wrote no .msh file")
            return 1
        ratios = certified_ratios(os.path.join(args.workdir, "out", meshes[0]))
        worst = min(ratios["direct"] + ratios["prisms"] + ratios["pyramids"])
        print("gmsh: %d elements certified, min J / max J %.3g" % (sum(ratios["counts"].values()), worst))
        if worst <= 0:
            print("FAIL: Gmsh finds elements with a Jacobian that is not positive")
            return 1
        if args.group_on_plane and not group_alone_on_plane(os.path.join(args.workdir, "out", meshes[0]),
                                                            args.group_on_plane):
            return 1
    if args.solver_rules and not meets_solver_rules(os.path.join(args.workdir, "out")):
        return 1
    print("ok")
    return 0


def meets_solver_rules(out):
    """Whether the written .xml meet Nektar++'s rules and the ASCII .msh PyFR's (one file at least)."""
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "io"))
    import nektar_rules
    import pyfr_rules
    checked = 0
    for name in sorted(os.listdir(out)):
        path = os.path.join(out, name)
        with open(path, "rb") as f:
            ascii_msh = name.endswith(".msh") and f.read(64).startswith(b"$MeshFormat\n4.1 0")
        rules = nektar_rules if name.endswith(".xml") else pyfr_rules if ascii_msh else None
        if rules is None:
            continue
        checked += 1
        if rules.main(["rules", path]) != 0:
            print("FAIL: %s breaks %s" % (name, rules.__name__))
            return False
    if checked == 0:
        print("FAIL: --solver-rules, but no Nektar++ XML or ASCII MSH was written")
        return False
    return True


if __name__ == "__main__":
    sys.exit(main())
