"""Structural check of the Nektar++ XML writer (no Nektar++ is installed), with Python's XML parser.

For each sample element (orders 1..9): VERTEX/EDGE/FACE/ELEMENT ids are consistent; each face's
edges form a closed loop; each element's faces have the types of Nektar's local faces (e.g. a
prism is Q T Q T Q) and a right-handed numbering of its vertices exists that gives exactly
Nektar's local faces (TetGeom/PyrGeom/PrismGeom/HexGeom face-vertex tables); every CURVED point
lies on the known map at the reference point that Nektar's point order implies (edges v0->v1,
PolyEvenlySpaced; triangles NodalTriEvenlySpaced: vertices, edges, interior row by row; quads
PolyEvenlySpaced, tensor order); Nektar++'s own load rules are checked by verify_nektar_rules.py;
composites and domain are present.

usage: verify_nektar.py IO_WRITE_SAMPLES IO_CHECK
"""
import itertools
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from nektar_rules import ids_in
from sample_map import SHAPES, Failures, curved_map, reference_of_vertex, write_samples

NEKTAR = {  # tag -> (number of vertices, local faces in Nektar vertex numbers, right-handed axes)
    "A": (4, [(0, 1, 2), (0, 1, 3), (1, 2, 3), (0, 2, 3)], (1, 2, 3)),
    "P": (5, [(0, 1, 2, 3), (0, 1, 4), (1, 2, 4), (3, 2, 4), (0, 3, 4)], (1, 3, 4)),
    "R": (6, [(0, 1, 2, 3), (0, 1, 4), (1, 2, 5, 4), (3, 2, 5), (0, 3, 5, 4)], (1, 3, 4)),
    "H": (8, [(0, 1, 2, 3), (0, 1, 5, 4), (1, 2, 6, 5), (3, 2, 6, 7), (0, 3, 7, 4), (4, 5, 6, 7)], (1, 3, 4)),
}
TAG = {"tet": "A", "pyr": "P", "pri": "R", "hex": "H"}


def numbers(text):
    return [float(t) for t in text.split()]


def face_vertices(edges, edge_ids):
    """Vertex cycle of a face from its edge list (vertex k joins edges k-1 and k), or None."""
    n = len(edge_ids)
    out = []
    for k in range(n):
        common = set(edges[edge_ids[k - 1]]) & set(edges[edge_ids[k]])
        if len(common) != 1:
            return None
        out.append(common.pop())
    return out


def tri_lattice(p):
    pts = [(0, 0), (p, 0), (0, p)]
    pts += [(i, 0) for i in range(1, p)] + [(p - i, i) for i in range(1, p)] + [(0, p - i) for i in range(1, p)]
    pts += [(i, j) for j in range(1, p) for i in range(1, p - j)]
    return pts


def check_file(f, path, name, p):
    root = ET.parse(path).getroot()
    geom = root.find("GEOMETRY")
    f.check(geom is not None and geom.get("DIM") == "3" and geom.get("SPACE") == "3", f"{path}: GEOMETRY header")
    verts = {int(v.get("ID")): np.array(numbers(v.text)) for v in geom.find("VERTEX")}
    edges = {int(e.get("ID")): [int(t) for t in e.text.split()] for e in geom.find("EDGE")}
    faces = {int(fc.get("ID")): (fc.tag, [int(t) for t in fc.text.split()]) for fc in geom.find("FACE")}
    f.check(all(a in verts and b in verts and a != b for a, b in edges.values()), f"{path}: edge with unknown vertex")
    fverts = {}
    for fid, (tag, eids) in faces.items():
        f.check(len(eids) == (3 if tag == "T" else 4) and all(e in edges for e in eids), f"{path}: face {fid} edges")
        cyc = face_vertices(edges, eids)
        f.check(cyc is not None and len(set(cyc)) == len(eids), f"{path}: face {fid} edges do not form a loop")
        fverts[fid] = cyc
    elements = list(geom.find("ELEMENT"))
    f.check(len(elements) == 1 and elements[0].tag == TAG[name], f"{path}: expected one {TAG[name]} element")
    el = elements[0]
    nv, local_faces, axes = NEKTAR[el.tag]
    fids = [int(t) for t in el.text.split()]
    f.check([faces[x][0] for x in fids] == ["T" if len(lf) == 3 else "Q" for lf in local_faces],
            f"{path}: face types {[faces[x][0] for x in fids]}")
    all_v = sorted({v for x in fids for v in fverts[x]})
    f.check(len(all_v) == nv, f"{path}: element has {len(all_v)} vertices")
    found = False
    for perm in itertools.permutations(all_v):
        if all(set(fverts[x]) == {perm[k] for k in lf} for x, lf in zip(fids, local_faces)):
            x0 = verts[perm[0]]
            jac = np.array([verts[perm[a]] - x0 for a in axes])
            if np.linalg.det(jac) > 0:
                found = True
                break
    f.check(found, f"{path}: no right-handed Nektar vertex numbering matches the faces")

    ref = {v: reference_of_vertex(name, p, x) for v, x in verts.items()}
    curved = geom.find("CURVED")
    f.check((curved is not None) == (p >= 2), f"{path}: CURVED section presence")
    curved_edges, curved_faces = set(), set()
    for c in (curved if curved is not None else []):
        want_type = "NodalTriEvenlySpaced" if c.tag == "F" and faces[int(c.get("FACEID"))][0] == "T" else "PolyEvenlySpaced"
        f.check(c.get("TYPE") == want_type, f"{path}: curve TYPE {c.get('TYPE')}")
        pts = np.array(numbers(c.text)).reshape(-1, 3)
        f.check(len(pts) == int(c.get("NUMPOINTS")), f"{path}: NUMPOINTS")
        if c.tag == "E":
            eid = int(c.get("EDGEID"))
            curved_edges.add(eid)
            a, b = (ref[v] for v in edges[eid])
            want = curved_map([a + (b - a) * k / p for k in range(p + 1)], p)
        else:
            fid = int(c.get("FACEID"))
            curved_faces.add(fid)
            r = [ref[v] for v in fverts[fid]]
            if faces[fid][0] == "T":
                want = curved_map([r[0] + (r[1] - r[0]) * i / p + (r[2] - r[0]) * j / p for i, j in tri_lattice(p)], p)
            else:
                lat = [(i / p, j / p) for j in range(p + 1) for i in range(p + 1)]
                want = curved_map([(1 - s) * (1 - t) * r[0] + s * (1 - t) * r[1] + s * t * r[2] + (1 - s) * t * r[3]
                                   for s, t in lat], p)
        f.check(want.shape == pts.shape and np.abs(want - pts).max() < 1e-9,
                f"{path}: curve {c.tag} {c.attrib} points off the map")
    if p >= 2:
        f.check(curved_edges == set(edges), f"{path}: edges without CURVED entry")
        need = {x for x, (tag, _) in faces.items() if tag == "Q" or p >= 3}
        f.check(curved_faces == need, f"{path}: curved faces {sorted(curved_faces)} != {sorted(need)}")
    comps = {int(c.get("ID")): c.text.strip() for c in geom.find("COMPOSITE")}
    f.check(f"{el.tag}[0]" in comps.values(), f"{path}: no element composite ({comps})")
    listed = []
    for text in comps.values():
        listed += ids_in(text).get("F", [])
    f.check(sorted(listed) == sorted(faces), f"{path}: boundary composites list {sorted(listed)}")
    f.check(geom.find("DOMAIN") is not None and geom.find("DOMAIN").text.strip().startswith("C["), f"{path}: DOMAIN")


def main():
    d = write_samples(sys.argv[1])
    f = Failures()
    for name in SHAPES:
        for p in range(1, 10):
            check_file(f, os.path.join(d, f"{name}_{p}.xml"), name, p)
    f.finish("verify_nektar")


if __name__ == "__main__":
    main()
