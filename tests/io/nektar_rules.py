"""Nektar++'s load-time rules for a 3D XML mesh, re-implemented (Python standard library only).

Nektar++ never reads an element's vertices: it derives them from the element's faces and each
face's edges, then checks what it derived. This module mirrors, per element (the Nektar++ function
named in each check's message):
  - TriGeom/QuadGeom constructors: a face's edges form a loop; face vertex k joins edges k-1, k.
  - {Tet,Pyr,Prism,Hex}Geom::SetUpLocalEdges: each local edge is shared by exactly one edge of the
    two faces that define it (tets: the first edge of faces 1..3 lies on face 0).
  - SetUpLocalVertices: consecutive edges share a vertex; the apex edges close.
  - SetUpEdgeOrientation: every local edge joins its two expected local vertices.
  - SetUpFaceOrientation: a triangle face must not be transposed against the element
    ("Orientation of triangular face ... is inconsistent with face ... since Dir2 is aligned with
    Dir1"), computed from the vertex coordinates as Nektar++ does (tolerance kNekZeroTol = 1e-12);
    and (the stronger form NekMesh guarantees, OrientTet / OrientPrism) its third vertex is the
    element's collapsed vertex for that face.
  - the straight-sided Jacobian at local vertex 0 is positive (NekMesh's jac module reports
    negative ones; a mirrored numbering inverts the element).
  - CURVED: NUMPOINTS matches the points; every edge of a curved face has a curve with as many
    points as the face has along an edge (TriGeom/QuadGeom::v_FillGeom: "Number of edge points does
    not correspond to number of face points"); a triangle's points are a nodal triangle set
    (NodalTri*: (n)(n+1)/2 points) or, with PolyEvenlySpaced, a square number (TriGeom::v_FillGeom
    aborts otherwise); quadrilaterals a square number; an edge's points run from its first vertex
    to its second and a face's vertices come first (nodal) or at the corners (tensor) in face order.
  - EXPANSIONS names every DOMAIN composite; composites refer to existing entities.
Compressed files (COMPRESSED="B64Z-LittleEndian", SpatialDomains/MeshGraphIOXmlCompressed.cpp,
records of MeshEntities.hpp) are decoded to the same structures as plain ones.

usage: nektar_rules.py FILE...            check; prints each violation, exit 1 if any
       nektar_rules.py --equal A B        exit 0 if both files hold the same mesh
"""
import base64
import math
import re
import struct
import sys
import xml.etree.ElementTree as ET
import zlib

TOL = 1e-12  # NekConstants::kNekZeroTol
POINTS_TYPES = {17: "PolyEvenlySpaced", 4: "GaussLobattoLegendre", 22: "NodalTriElec", 23: "NodalTriFekete",
                24: "NodalTriEvenlySpaced"}  # LibUtilities::PointsType enum values
NODAL_TRI = {"NodalTriElec", "NodalTriFekete", "NodalTriEvenlySpaced"}
WITH_END_POINTS = {"PolyEvenlySpaced", "GaussLobattoLegendre"}

# Local faces in local vertex numbers; the third vertex of each triangle is the collapsed one.
FACES = {
    "A": [(0, 1, 2), (0, 1, 3), (1, 2, 3), (0, 2, 3)],
    "P": [(0, 1, 2, 3), (0, 1, 4), (1, 2, 4), (3, 2, 4), (0, 3, 4)],
    "R": [(0, 1, 2, 3), (0, 1, 4), (1, 2, 5, 4), (3, 2, 5), (0, 3, 5, 4)],
    "H": [(0, 1, 2, 3), (0, 1, 5, 4), (1, 2, 6, 5), (3, 2, 6, 7), (0, 3, 7, 4), (4, 5, 6, 7)],
}
EDGES = {  # SetUpEdgeOrientation's edgeVerts
    "A": [(0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)],
    "P": [(0, 1), (1, 2), (3, 2), (0, 3), (0, 4), (1, 4), (2, 4), (3, 4)],
    "R": [(0, 1), (1, 2), (3, 2), (0, 3), (0, 4), (1, 4), (2, 5), (3, 5), (4, 5)],
    "H": [(0, 1), (1, 2), (2, 3), (0, 3), (0, 4), (1, 5), (2, 6), (3, 7), (4, 5), (5, 6), (6, 7), (4, 7)],
}
JACOBIAN_AXES = {"A": (1, 2, 3), "P": (1, 3, 4), "R": (1, 3, 4), "H": (1, 3, 4)}


class Mesh:
    def __init__(self):
        self.vertices = {}   # id -> (x, y, z)
        self.edges = {}      # id -> (v0, v1)
        self.faces = {}      # id -> ("T"|"Q", [edge ids])
        self.elements = {}   # id -> (letter, [face ids])
        self.curves = {}     # ("E"|"F", entity id) -> (type, [points])
        self.composites = {}  # id -> (name or None, text)
        self.domain = ""
        self.expansions = []  # composite texts

    def same_as(self, other):
        return all(getattr(self, k) == getattr(other, k) for k in
                   ("vertices", "edges", "faces", "elements", "curves", "composites", "domain", "expansions"))


def _decode(text, fmt):
    raw = zlib.decompress(base64.b64decode("".join(text.split())))
    size = struct.calcsize(fmt)
    return [struct.unpack_from(fmt, raw, k) for k in range(0, len(raw) - len(raw) % size, size)]


def _is_compressed(node):
    c = node.get("COMPRESSED")
    if c is None:
        return False
    if c.upper() != "B64Z-LITTLEENDIAN":
        raise ValueError(f"unknown COMPRESSED={c}")
    return True


def read(path):
    geom = ET.parse(path).getroot().find("GEOMETRY")
    if geom is None:
        raise ValueError(f"{path}: no GEOMETRY")
    m = Mesh()
    vert = geom.find("VERTEX")
    if _is_compressed(vert):
        for i, x, y, z in _decode(vert.text, "<q3d"):
            m.vertices[i] = (x, y, z)
    else:
        for v in vert:
            m.vertices[int(v.get("ID"))] = tuple(float(t) for t in v.text.split())
    edge = geom.find("EDGE")
    if _is_compressed(edge):
        for i, a, b in _decode(edge.text, "<3q"):
            m.edges[i] = (a, b)
    else:
        for e in edge:
            m.edges[int(e.get("ID"))] = tuple(int(t) for t in e.text.split())
    for f in geom.find("FACE"):
        n = 3 if f.tag == "T" else 4
        if _is_compressed(f):
            for rec in _decode(f.text, f"<{n + 1}q"):
                m.faces[rec[0]] = (f.tag, list(rec[1:]))
        else:
            m.faces[int(f.get("ID"))] = (f.tag, [int(t) for t in f.text.split()])
    for el in geom.find("ELEMENT"):
        n = len(FACES[el.tag])
        if _is_compressed(el):
            for rec in _decode(el.text, f"<{n + 1}q"):
                m.elements[rec[0]] = (el.tag, list(rec[1:]))
        else:
            m.elements[int(el.get("ID"))] = (el.tag, [int(t) for t in el.text.split()])
    curved = geom.find("CURVED")
    if curved is not None and _is_compressed(curved):
        infos = {c.tag: _decode(c.text, "<6q") for c in curved if c.tag in ("E", "F")}
        data = curved.find("DATAPOINTS")
        index = [r[0] for r in _decode(data.find("INDEX").text, "<q")]
        pts = [r[1:] for r in _decode(data.find("POINTS").text, "<q3d")]
        for tag, recs in infos.items():
            for _, entity, npoints, _, offset, ptype in recs:
                points = [pts[index[offset + j]] for j in range(npoints)]
                m.curves[(tag, entity)] = (POINTS_TYPES.get(ptype, f"type{ptype}"), points)
    elif curved is not None:
        for c in curved:
            key = "EDGEID" if c.tag == "E" else "FACEID"
            nums = [float(t) for t in c.text.split()]
            points = [tuple(nums[k:k + 3]) for k in range(0, len(nums), 3)]
            if len(points) != int(c.get("NUMPOINTS")):
                raise ValueError(f"{path}: curve {c.attrib}: NUMPOINTS {c.get('NUMPOINTS')} but {len(points)} points")
            m.curves[(c.tag, int(c.get(key)))] = (c.get("TYPE"), points)
    for c in geom.find("COMPOSITE"):
        if c.tag == "C":
            m.composites[int(c.get("ID"))] = (c.get("NAME"), " ".join(c.text.split()))
    m.domain = " ".join(geom.find("DOMAIN").text.split()) if geom.find("DOMAIN") is not None else ""
    exp = ET.parse(path).getroot().find("EXPANSIONS")
    if exp is not None:
        m.expansions = [e.get("COMPOSITE") for e in exp if e.tag == "E"]
    return m


# ---- geometry helpers -------------------------------------------------------------------------

def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def ids_in(text):
    """Entity ids of a composite or domain body like "A[0-3,7] F[2]" -> {letter: [ids]}."""
    out = {}
    for letter, body in re.findall(r"([A-Z])\[([^\]]*)\]", text):
        ids = []
        for part in body.split(","):
            part = part.strip()
            if "-" in part:
                a, b = part.split("-")
                ids += range(int(a), int(b) + 1)
            elif part:
                ids.append(int(part))
        out.setdefault(letter, []).extend(ids)
    return out


class Violations(list):
    def add(self, where, what):
        self.append(f"{where}: {what}")


def face_vertices(m, fid, bad):
    """TriGeom/QuadGeom: vertex k joins edges k-1 and k."""
    tag, eids = m.faces[fid]
    if len(eids) != (3 if tag == "T" else 4) or any(e not in m.edges for e in eids):
        bad.add(f"face {fid}", "TriGeom/QuadGeom: wrong number of edges or unknown edge")
        return None
    out = []
    for k in range(len(eids)):
        common = set(m.edges[eids[k - 1]]) & set(m.edges[eids[k]])
        if len(common) != 1:
            bad.add(f"face {fid}", f"TriGeom/QuadGeom: edges {eids[k - 1]} and {eids[k]} do not share one vertex")
            return None
        out.append(common.pop())
    return out


def shared_edge(m, fa, fb, where, bad, first_of_b=False):
    """SetUpLocalEdges: the one edge that faces fa and fb share (or fb's first edge, on fa)."""
    ea, eb = m.faces[fa][1], m.faces[fb][1]
    common = [e for e in ea if e == eb[0]] if first_of_b else [e for e in ea if e in eb]
    if len(common) != 1:
        what = "does not hold the first edge of" if first_of_b else "does not share exactly one edge with"
        bad.add(where, f"SetUpLocalEdges: face {fa} {what} face {fb}")
        return None
    return common[0]


def local_edges(m, letter, f, where, bad):
    """{Tet,Pyr,Prism,Hex}Geom::SetUpLocalEdges."""
    s = lambda a, b, first=False: shared_edge(m, f[a], f[b], where, bad, first)
    if letter == "A":
        e = [s(0, 1, True), s(0, 2, True), s(0, 3, True), s(1, 3), s(1, 2), s(2, 3)]
    elif letter in ("P", "R"):
        e = [s(0, 1), s(0, 2), s(0, 3), s(0, 4), s(1, 4), s(1, 2), s(2, 3), s(3, 4)]
        if letter == "R":
            e.append(s(2, 4))
    else:
        e = [s(0, 1), s(0, 2), s(0, 3), s(0, 4), s(1, 4), s(1, 2), s(2, 3), s(3, 4),
             s(5, 1), s(5, 2), s(5, 3), s(5, 4)]
    return None if None in e else e


def local_vertices(m, letter, e, where, bad):
    """SetUpLocalVertices: vertices 0..3 around the first edges, then the apex / top."""
    E = [m.edges[i] for i in e]
    if E[0][0] in E[1]:
        v = [E[0][1], E[0][0]]
    elif E[0][1] in E[1]:
        v = [E[0][0], E[0][1]]
    else:
        bad.add(where, "SetUpLocalVertices: edges 0 and 1 do not share a vertex")
        return None
    chain = 1 if letter == "A" else 2
    for i in range(1, chain + 1):
        if v[i] not in E[i]:
            bad.add(where, f"SetUpLocalVertices: edge {i} does not start at vertex {i}")
            return None
        v.append(E[i][1] if E[i][0] == v[i] else E[i][0])
    if letter == "A":
        v.append(E[3][1] if E[3][0] == v[0] else E[3][0])
    elif letter == "P":
        v.append(E[4][1] if E[4][0] == v[0] else E[4][0])
    elif letter == "R":  # vertex 4: the end of edge 8 on edge 4
        if E[8][0] in E[4]:
            v += [E[8][0], E[8][1]]
        elif E[8][1] in E[4]:
            v += [E[8][1], E[8][0]]
        else:
            bad.add(where, "SetUpLocalVertices: edges 4 and 8 do not share a vertex")
            return None
    else:  # hex: the top ends of the vertical edges 4..7
        for k in range(4):
            a, b = E[4 + k]
            v.append(b if a == v[k] else a)
    return v


def orientation_transposed(m, letter, fidx, fid, v, fverts):
    """SetUpFaceOrientation: True if the face's first axis is not along the element's."""
    fv = FACES[letter][fidx]
    X = lambda k: m.vertices[v[k]]
    base = fverts[0]
    tri = len(fv) == 3
    if base == v[fv[0]]:
        A = sub(X(fv[1]), X(fv[0]))
    elif base == v[fv[1]]:
        A = sub(X(fv[1]), X(fv[0]))
    elif base == v[fv[2]]:
        A = sub(X(fv[1]), X(fv[2])) if tri else sub(X(fv[2]), X(fv[3]))
    elif not tri and base == v[fv[3]]:
        A = sub(X(fv[2]), X(fv[3]))
    else:
        return None
    fa = sub(m.vertices[fverts[1]], m.vertices[fverts[0]])
    return abs(abs(dot(A, fa)) / norm(A) / norm(fa) - 1.0) >= TOL


def check_element(m, eid, bad):
    letter, fids = m.elements[eid]
    where = f"element {letter} {eid}"
    if len(fids) != len(FACES[letter]) or any(f not in m.faces for f in fids):
        bad.add(where, "unknown face or wrong number of faces")
        return
    kinds = [m.faces[f][0] for f in fids]
    if kinds != ["T" if len(fv) == 3 else "Q" for fv in FACES[letter]]:
        bad.add(where, f"face types {kinds} are not those of Nektar++'s local faces")
        return
    fverts = {}
    for f in fids:
        fverts[f] = face_vertices(m, f, bad)
        if fverts[f] is None:
            return
    e = local_edges(m, letter, fids, where, bad)
    if e is None:
        return
    v = local_vertices(m, letter, e, where, bad)
    if v is None:
        return
    for k, (a, b) in enumerate(EDGES[letter]):
        if set(m.edges[e[k]]) != {v[a], v[b]}:
            bad.add(where, f"SetUpEdgeOrientation: local edge {k} does not join local vertices {a} and {b}")
            return
    for k, f in enumerate(fids):
        if set(fverts[f]) != {v[i] for i in FACES[letter][k]}:
            bad.add(where, f"local face {k} (face {f}) does not hold local vertices {FACES[letter][k]}")
            return
        if m.faces[f][0] != "T":
            continue
        transposed = orientation_transposed(m, letter, k, f, v, fverts[f])
        if transposed is None:
            bad.add(where, f"SetUpFaceOrientation: could not find matching vertex for face {f}")
        elif transposed:
            bad.add(where, f"SetUpFaceOrientation: orientation of triangular face (id = {f}) is inconsistent "
                           f"with face {k} (Dir2 aligned with Dir1)")
        elif fverts[f][2] != v[FACES[letter][k][2]]:
            bad.add(where, f"OrientTet/OrientPrism: triangle {f}'s third vertex is not the collapsed vertex "
                           f"{FACES[letter][k][2]} of face {k}")
    o, (a, b, c) = m.vertices[v[0]], JACOBIAN_AXES[letter]
    jac = dot(sub(m.vertices[v[a]], o), cross(sub(m.vertices[v[b]], o), sub(m.vertices[v[c]], o)))
    if not jac > 0:
        bad.add(where, f"straight-sided Jacobian at local vertex 0 is {jac:.3g} (not positive)")


def close(p, q, scale):
    return max(abs(a - b) for a, b in zip(p, q)) <= 1e-9 * scale


def check_curves(m, bad, scale):
    for (tag, entity), (ptype, pts) in m.curves.items():
        where = f"curve {tag} {entity}"
        n = len(pts)
        if tag == "E":
            if entity not in m.edges:
                bad.add(where, "unknown edge")
                continue
            a, b = m.edges[entity]
            if ptype in WITH_END_POINTS and not (close(pts[0], m.vertices[a], scale) and
                                                 close(pts[-1], m.vertices[b], scale)):
                bad.add(where, "points do not run from the edge's first vertex to its second")
            continue
        if entity not in m.faces:
            bad.add(where, "unknown face")
            continue
        fverts = face_vertices(m, entity, bad)
        if fverts is None:
            continue
        corners = [m.vertices[x] for x in fverts]
        tri = m.faces[entity][0] == "T"
        per_edge = (math.isqrt(8 * n + 1) - 1) // 2 if tri and ptype in NODAL_TRI else math.isqrt(n)
        for e in m.faces[entity][1]:
            if len(m.curves.get(("E", e), (None, [None, None]))[1]) != per_edge:
                bad.add(where, f"Tri/QuadGeom::v_FillGeom: edge {e} has not the face's {per_edge} points per edge")
        if tri:
            if ptype in NODAL_TRI:
                k = (math.isqrt(8 * n + 1) - 1) // 2
                if k * (k + 1) // 2 != n:
                    bad.add(where, f"{ptype} with {n} points (not a triangular number)")
                elif not all(close(pts[i], corners[i], scale) for i in range(3)):
                    bad.add(where, "the first three points are not the face's vertices in order")
            elif ptype == "PolyEvenlySpaced":
                if math.isqrt(n) ** 2 != n:
                    bad.add(where, f"TriGeom::v_FillGeom: PolyEvenlySpaced triangle with {n} points (not a square)")
            else:
                bad.add(where, f"point type {ptype} on a triangle")
        else:
            q = math.isqrt(n)
            if q * q != n:
                bad.add(where, f"quadrilateral with {n} points (not a square)")
            elif ptype in WITH_END_POINTS and not all(
                    close(pts[i], c, scale) for i, c in zip((0, q - 1, n - 1, n - q), corners)):
                bad.add(where, "the corner points are not the face's vertices in order")


def check(m):
    bad = Violations()
    for eid in m.edges:
        if any(v not in m.vertices for v in m.edges[eid]):
            bad.add(f"edge {eid}", "unknown vertex")
    for eid in sorted(m.elements):
        check_element(m, eid, bad)
    coords = list(m.vertices.values()) or [(0, 0, 0)]
    scale = max(max(abs(c) for c in p) for p in coords) or 1.0
    check_curves(m, bad, scale)
    domain = ids_in(m.domain).get("C", [])
    if not domain:
        bad.add("DOMAIN", "empty")
    for c in domain:
        if c not in m.composites:
            bad.add("DOMAIN", f"unknown composite {c}")
    expanded = {c for text in m.expansions for c in ids_in(text).get("C", [])}
    for c in domain:
        if c not in expanded:
            bad.add("EXPANSIONS", f"composite {c} of the domain has no expansion")
    for cid, (_, text) in m.composites.items():
        for letter, ids in ids_in(text).items():
            pool = m.faces if letter == "F" else m.edges if letter == "E" else m.elements
            missing = [i for i in ids if i not in pool or (letter in FACES and m.elements[i][0] != letter)]
            if missing:
                bad.add(f"composite {cid}", f"{letter}{missing[:5]} do not exist")
    return bad


def main(argv):
    if len(argv) == 4 and argv[1] == "--equal":
        same = read(argv[2]).same_as(read(argv[3]))
        print(f"{argv[2]} {'==' if same else '!='} {argv[3]}")
        return 0 if same else 1
    status = 0
    for path in argv[1:]:
        bad = check(read(path))
        for line in bad[:20]:
            print(f"{path}: {line}")
        if bad:
            print(f"{path}: {len(bad)} violation(s)")
            status = 1
        else:
            print(f"{path}: ok")
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))
