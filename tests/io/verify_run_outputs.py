"""The files `semimesh run` writes, checked by independent readers and the solvers' own rules.

Runs the CLI on a config at one order, then:
  - Nektar++ (compressed, and plain when asked): nektar_rules.py finds no violation of Nektar++'s
    load-time rules, and both encodings hold the same mesh; only the curved edges (the wing's,
    not the straight far field's) have a CURVED entry;
  - MSH: gmsh reads the binary file (`msh41`, the default: coarse.msh) with the same nodes, elements
    and physical groups as the ASCII one (`msh41-ascii`: coarse.ascii.msh); every node gmsh reads is used by an element (no orphan nodes); the ASCII file meets PyFR's
    reader rules (pyfr_rules.py) up to order 4, and a copy with the old per-dimension physical tags
    ("3 1 fluid" beside "2 1 ...") does not;
  - VTU: VTK reads the compressed binary file with the same points, cells and cell data as ASCII.
With --every-format (order 8: MSH ASCII and binary, VTU, compressed Nektar++, one run): the stages'
progress lines are printed, and gmsh reads the ASCII MSH with the element counts of report.json,
at the order asked for.

usage: verify_run_outputs.py --exe SEMIMESH --config CONFIG --workdir DIR --order P
                             [--all-formats | --every-format] [--pyfr-refuses-pyramids] [--set key=value ...]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import nektar_rules
import pyfr_rules
from sample_map import Failures

PYFR_PYRAMIDS = "Pyramids with non-parallelogram bases are currently unsupported"


def gmsh_content(path):
    import gmsh
    gmsh.open(path)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    types, etags, enodes = gmsh.model.mesh.getElements()
    groups = sorted((d, t, gmsh.model.getPhysicalName(d, t)) for d, t in gmsh.model.getPhysicalGroups())
    return list(tags), list(coords), {int(t): (list(a), list(b)) for t, a, b in zip(types, etags, enodes)}, groups


def vtu_arrays(path):
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    g = reader.GetOutput()
    cd = g.GetCellData()
    out = {"points": vtk_to_numpy(g.GetPoints().GetData()).copy(),
           "connectivity": vtk_to_numpy(g.GetCells().GetConnectivityArray()).copy(),
           "offsets": vtk_to_numpy(g.GetCells().GetOffsetsArray()).copy(),
           "types": vtk_to_numpy(g.GetCellTypesArray()).copy()}
    for k in range(cd.GetNumberOfArrays()):
        out[cd.GetArrayName(k)] = vtk_to_numpy(cd.GetArray(k)).copy()
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--config", required=True)
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--order", type=int, required=True)
    ap.add_argument("--all-formats", action="store_true")
    ap.add_argument("--every-format", action="store_true",
                    help="one file per format (msh41, msh41-binary, vtu, nektar) and gmsh's counts against report.json")
    ap.add_argument("--pyfr-refuses-pyramids", action="store_true",
                    help="the mesh has pyramids on non-parallelogram bases: PyFR must refuse them, and nothing else")
    ap.add_argument("--set", action="append", default=[])
    a = ap.parse_args()
    formats = ["msh41-ascii", "msh41", "vtu", "vtu-ascii", "nektar", "nektar-xml"] if a.all_formats else \
        ["msh41-ascii", "msh41", "vtu", "nektar"] if a.every_format else ["msh41", "nektar"]
    binary_msh, ascii_msh = "coarse.msh", "coarse.ascii.msh"
    shutil.rmtree(a.workdir, ignore_errors=True)
    cmd = [a.exe, "run", a.config, "-o", a.workdir, "--set", f"highorder.order={a.order}",
           "--set", "output.formats=[" + ",".join(f'"{f}"' for f in formats) + "]"]
    for s in a.set:
        cmd += ["--set", s]
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout[-3000:], run.stderr[-3000:])
        sys.exit(f"semimesh run failed with code {run.returncode}")
    path = lambda name: os.path.join(a.workdir, name)
    f = Failures()

    nek = nektar_rules.read(path("coarse.xml"))
    bad = nektar_rules.check(nek)
    f.check(not bad, f"coarse.xml breaks Nektar++'s rules: {bad[:5]} ({len(bad)} in all)")
    curved = sum(1 for kind, _ in nek.curves if kind == "E")
    f.check(0 < curved < len(nek.edges), f"{curved} of {len(nek.edges)} edges curved: the straight far field "
                                         "needs no CURVED entry, the wing does")
    if a.all_formats:
        f.check(nektar_rules.read(path("coarse.xml")).same_as(nektar_rules.read(path("coarse.plain.xml"))),
                "compressed and plain Nektar++ files differ")

    import gmsh
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    binary = gmsh_content(path(binary_msh))
    used = {int(n) for _, nodes in binary[2].values() for n in nodes}
    f.check(used == {int(t) for t in binary[0]}, f"{len(set(map(int, binary[0])) - used)} node(s) used by no element")
    if a.all_formats:
        f.check(gmsh_content(path(ascii_msh)) == binary, "binary MSH differs from ASCII MSH in gmsh")
    gmsh.finalize()

    if a.every_format:
        # (was pipeline_order8_every_format, which ran the same case a second time)
        import json
        sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pipeline"))
        from gmsh_validity import gmsh_counts
        for stage in ("load CAD", "surface mesh", "near field", "far field", "checks", "write"):
            f.check(stage in run.stdout, f"no progress line for stage '{stage}'")
        with open(path("report.json")) as fh:
            report = json.load(fh)
        f.check(report["order"] == report["requested_order"] == a.order,
                f"report.json: order {report['order']}, requested {report['requested_order']}")
        counts = gmsh_counts(path(ascii_msh))
        f.check(counts == report["elements_by_type"], f"{ascii_msh}: gmsh counts {counts}, report.json {report['elements_by_type']}")
        f.check(os.path.getsize(path("coarse.vtu")) > 0, "coarse.vtu is empty")

    if a.all_formats:
        import numpy as np
        z, text = vtu_arrays(path("coarse.vtu")), vtu_arrays(path("coarse.ascii.vtu"))
        f.check(z.keys() == text.keys() and all(np.array_equal(z[k], text[k]) for k in z),
                "compressed VTU differs from ASCII VTU in VTK")
        if a.order <= 4:
            bad = pyfr_rules.check(path(ascii_msh))
            f.check(any("binary file" in b for b in pyfr_rules.check(path(binary_msh))),
                    "PyFR's rules accept the binary coarse.msh")
            if a.pyfr_refuses_pyramids:
                # A hex block whose exposed quads are trapezoids (the H-type wake, its ratio falling
                # downstream) stands on pyramids PyFR cannot take: that refusal, and only it.
                f.check(bad == [PYFR_PYRAMIDS], f"expected PyFR's pyramid refusal alone, got {bad}")
            else:
                f.check(not bad, f"{ascii_msh} breaks PyFR's reader rules: {bad}")
            with open(path(ascii_msh)) as fh:
                text = fh.read()
            old = re.sub(r'\n3 \d+ "', '\n3 1 "', text, count=1)  # the old writer's volume tag
            with open(path("old_tags.msh"), "w") as fh:
                fh.write(old)
            f.check(any("Duplicate physical entity ID" in b for b in pyfr_rules.check(path("old_tags.msh"))),
                    "PyFR's rules accept duplicate physical tags")
            # The face rule can fail: one tetrahedron (type 4) alone, with three of its four faces
            # (type 2 triangles) as boundary, leaves one face unpaired; all four pair it.
            tet, faces = (4, [[1, 2, 3, 4]]), [[1, 2, 3], [1, 2, 4], [1, 3, 4], [2, 3, 4]]
            f.check(pyfr_rules.unpaired_faces([tet, (2, faces[:3])]) == ["Unpaired faces in mesh (1)"] and
                    not pyfr_rules.unpaired_faces([tet, (2, faces)]), "PyFR's face pairing rule does not pair")
    f.finish(f"verify_run_outputs order {a.order}")


if __name__ == "__main__":
    main()
