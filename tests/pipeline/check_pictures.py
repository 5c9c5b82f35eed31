"""`semimesh run --pictures` on the coarse wing, its SVG files checked by independent readers.

Each picture listed in report.json must parse as SVG (xml.etree). The spanwise cut must draw one
element path per volume element that the plane crosses inside the picture's window, counted here
from the mesh as Gmsh reads it (order 1: an element crosses z = s iff its vertices straddle s), the
plane and window placed by the documented rule (station 0.4 of the body's height; x from 0.3
chord before to 0.3 chord behind the body, y within 0.35 chord of its middle). The planform must
draw one outline per "wing" boundary face.

  check_pictures.py --exe SEMIMESH --config CASE.toml --workdir DIR
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

import gmsh

SVG = "{http://www.w3.org/2000/svg}"


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def paths(svg_file, css_class):
    root = ET.parse(svg_file).getroot()
    if root.tag != SVG + "svg":
        fail("%s: root element is %s, not svg" % (svg_file, root.tag))
    return [p for p in root.iter(SVG + "path") if p.get("class") == css_class]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", required=True)
    parser.add_argument("--config", required=True)
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    shutil.rmtree(args.workdir, ignore_errors=True)
    run = subprocess.run([args.exe, "run", args.config, "-o", args.workdir, "--pictures",
                          "--set", "output.formats=[\"msh41\"]"], capture_output=True, text=True, timeout=300)
    if run.returncode != 0:
        fail("semimesh run exited %d: %s" % (run.returncode, run.stderr))
    with open(os.path.join(args.workdir, "report.json")) as f:
        report = json.load(f)
    pictures = report["pictures"]
    if len(pictures) < 6:
        fail("expected at least 6 pictures, report.json lists %r" % pictures)
    for picture in pictures:
        ET.parse(picture)  # raises on malformed XML

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    msh = [f for f in report["files"] if f.endswith(".msh")][0]
    gmsh.open(msh)
    wing = [tag for dim, tag in gmsh.model.getPhysicalGroups(2) if gmsh.model.getPhysicalName(2, tag) == "wing"]
    if not wing:
        fail("no physical surface named wing")
    coords = {}
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    for i, t in enumerate(tags):
        coords[int(t)] = xyz[3 * i:3 * i + 3]
    wing_nodes = set()
    wing_faces = 0
    for entity in gmsh.model.getEntitiesForPhysicalGroup(2, wing[0]):
        types, _, nodes = gmsh.model.mesh.getElements(2, entity)
        for etype, node_list in zip(types, nodes):
            wing_nodes.update(int(n) for n in node_list)
            wing_faces += len(node_list) // gmsh.model.mesh.getElementProperties(etype)[3]
    lo = [min(coords[n][k] for n in wing_nodes) for k in range(3)]
    hi = [max(coords[n][k] for n in wing_nodes) for k in range(3)]
    station = lo[2] + 0.4 * (hi[2] - lo[2])
    chord, middle = hi[0] - lo[0], 0.5 * (lo[1] + hi[1])
    window = (lo[0] - 0.3 * chord, middle - 0.35 * chord, hi[0] + 0.3 * chord, middle + 0.35 * chord)
    crossed = 0
    types, _, nodes = gmsh.model.mesh.getElements(3)
    for etype, node_list in zip(types, nodes):
        per = gmsh.model.mesh.getElementProperties(etype)[3]
        for e in range(len(node_list) // per):
            pts = [coords[int(n)] for n in node_list[e * per:(e + 1) * per]]
            z = [p[2] for p in pts]
            if min(z) > station or max(z) < station:
                continue
            x, y = [p[0] for p in pts], [p[1] for p in pts]
            if max(x) < window[0] or min(x) > window[2] or max(y) < window[1] or min(y) > window[3]:
                continue
            crossed += 1
    gmsh.finalize()

    cut = [p for p in pictures if p.endswith("_cut.svg")][0]
    drawn = len(paths(cut, "element"))
    if drawn != crossed:
        fail("the cut draws %d elements; the mesh has %d crossing z = %g in the window" % (drawn, crossed, station))
    planform = [p for p in pictures if p.endswith("_body_planform.svg")][0]
    outlines = len(paths(planform, "face"))
    if outlines != wing_faces:
        fail("the planform draws %d faces; the mesh has %d wing faces" % (outlines, wing_faces))
    print("pictures: %d files; cut: %d elements at z = %.4g; planform: %d faces" % (len(pictures), drawn, station, outlines))


if __name__ == "__main__":
    main()
