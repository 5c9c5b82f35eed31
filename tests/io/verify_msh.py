"""Independent check of the MSH writers with gmsh's own reader and basis functions (python3-gmsh).

For every shape and order 1..6, io_write_samples writes one element curved by a degree-P
polynomial map (sample_map.curved_map). gmsh opens the file, and its Lagrange basis evaluated at
random reference points, combined with the element's node coordinates, must reproduce the map
(exactly up to round-off: a wrong node order gives errors of order 0.01-1). Boundary faces are
checked the same way with their own basis. gmsh 4.8 cannot build prisms of order >= 3
("FaceClosureFull not implemented"), so those are checked node by node against PyFR's published
Gmsh prism ordering table (pyfr/readers/nodemaps.py, GmshNodeMaps, 'pri' 40/75/126/196 nodes: a
fact table, copied as data). Finally `semimesh check` must agree with gmsh's
Jacobian determinants on a valid and a folded element of every shape and order.
Binary MSH 4.1 (_bin.msh) must read back in gmsh with the same nodes, elements and physical groups
as the ASCII file, and physical tags must be unique across dimensions (PyFR's rule).

usage: verify_msh.py IO_WRITE_SAMPLES IO_CHECK
"""
import json
import os
import subprocess
import sys

import gmsh
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sample_map import SHAPES, Failures, curved_map, face_point, inside_points, reference_of_vertex, write_samples

# Equispaced interpolation of order 9 loses ~1e-9 to round-off; a wrong node order costs >= 1e-3.
INTERPOLATION_TOLERANCE = 1e-8

# PyFR GmshNodeMaps.to_pyfr['pri', n]: Gmsh node i -> PyFR node index. PyFR's prism nodes are
# layer by layer in z, each layer a triangle row by row (x fastest).
PYFR_PRI = {
    3: [0, 3, 9, 30, 33, 39, 1, 2, 4, 7, 10, 20, 6, 8, 13, 23, 19, 29, 31, 32, 34, 37, 36, 38, 5, 35,
        11, 12, 22, 21, 14, 24, 27, 17, 16, 18, 28, 26, 15, 25],
    4: [0, 4, 14, 60, 64, 74, 1, 2, 3, 5, 9, 12, 15, 30, 45, 8, 11, 13, 19, 34, 49, 29, 44, 59, 61,
        62, 63, 65, 69, 72, 68, 71, 73, 6, 10, 7, 66, 67, 70, 16, 18, 48, 46, 17, 33, 47, 31, 32, 20,
        50, 57, 27, 35, 54, 42, 24, 39, 23, 28, 58, 53, 26, 43, 56, 38, 41, 21, 51, 36, 22, 52, 37, 25,
        55, 40],
    5: [0, 5, 20, 105, 110, 125, 1, 2, 3, 4, 6, 11, 15, 18, 21, 42, 63, 84, 10, 14, 17, 19, 26,
        47, 68, 89, 41, 62, 83, 104, 106, 107, 108, 109, 111, 116, 120, 123, 115, 119, 122, 124,
        7, 16, 9, 12, 13, 8, 112, 114, 121, 113, 118, 117, 22, 25, 88, 85, 23, 24, 46, 67, 87, 86,
        64, 43, 44, 45, 66, 65, 27, 90, 102, 39, 48, 69, 95, 99, 81, 60, 36, 32, 53, 74, 78, 57,
        31, 40, 103, 94, 35, 38, 61, 82, 101, 98, 73, 52, 56, 59, 80, 77, 28, 91, 49, 70, 30, 93,
        51, 72, 37, 100, 58, 79, 29, 92, 50, 71, 34, 97, 55, 76, 33, 96, 54, 75],
    6: [0, 6, 27, 168, 174, 195, 1, 2, 3, 4, 5, 7, 13, 18, 22, 25, 28, 56, 84, 112, 140, 12, 17, 21,
        24, 26, 34, 62, 90, 118, 146, 55, 83, 111, 139, 167, 169, 170, 171, 172, 173, 175, 181,
        186, 190, 193, 180, 185, 189, 192, 194, 8, 23, 11, 14, 19, 20, 16, 10, 9, 15, 176, 179, 191,
        177, 178, 184, 188, 187, 182, 183, 29, 33, 145, 141, 30, 31, 32, 61, 89, 117, 144, 143,
        142, 113, 85, 57, 58, 60, 116, 114, 59, 88, 115, 86, 87, 35, 147, 165, 53, 63, 91, 119,
        153, 158, 162, 137, 109, 81, 50, 46, 41, 69, 125, 134, 78, 97, 130, 106, 74, 102, 40, 54,
        166, 152, 45, 49, 52, 82, 110, 138, 164, 161, 157, 124, 96, 68, 73, 80, 136, 129, 77, 108,
        133, 101, 105, 36, 148, 64, 92, 120, 39, 151, 67, 95, 123, 51, 163, 79, 107, 135, 37, 149,
        65, 93, 121, 38, 150, 66, 94, 122, 44, 156, 72, 100, 128, 48, 160, 76, 104, 132, 47, 159,
        75, 103, 131, 42, 154, 70, 98, 126, 43, 155, 71, 99, 127],
}


def pyfr_prism_reference(p, index):
    per_layer = (p + 1) * (p + 2) // 2
    k, t = divmod(index, per_layer)
    j = 0
    while t >= p + 1 - j:
        t -= p + 1 - j
        j += 1
    return np.array([t / p, j / p, -1 + 2 * k / p])


# Gmsh's prism edges (gmsh.info, "Node ordering"): the nodes of edge (a, b) follow the vertices,
# edge by edge, from a to b.
GMSH_PRISM_EDGES = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 4), (2, 5), (3, 4), (3, 5), (4, 5)]


def prism_vertices_edges_and_node_set_error(x, p):
    """Prisms of order > 6, which neither Gmsh 4.8 nor PyFR's table describe: the vertex and edge
    nodes must sit where Gmsh's documented layout puts them, and the whole node set must be the
    image of the equispaced prism lattice (face and interior order stay unchecked)."""
    vertices = np.array(SHAPES["pri"][1], dtype=float)
    want = [vertices[i] for i in range(6)]
    for a, b in GMSH_PRISM_EDGES:
        want += [vertices[a] + (vertices[b] - vertices[a]) * k / p for k in range(1, p)]
    err = np.abs(x[:len(want)] - curved_map(np.array(want), p)).max()
    lattice = np.array([(i / p, j / p, -1 + 2 * k / p) for k in range(p + 1) for j in range(p + 1)
                        for i in range(p + 1 - j)])
    image = curved_map(lattice, p)
    nearest = np.min(np.linalg.norm(x[:, None, :] - image[None, :, :], axis=2), axis=1)
    matched = len(set(np.argmin(np.linalg.norm(x[:, None, :] - image[None, :, :], axis=2), axis=1)))
    return max(err, nearest.max(), 0.0 if matched == len(image) == len(x) else 1.0)


def element_nodes(dim):
    """[(type, [node coordinate arrays (nn, 3) per element])] of all elements of dimension dim."""
    tags, coords, _ = gmsh.model.mesh.getNodes()
    xyz = dict(zip(tags, np.asarray(coords).reshape(-1, 3)))
    out = []
    types, elements, nodes = gmsh.model.mesh.getElements(dim)
    for t, et, nt in zip(types, elements, nodes):
        # (getElementProperties fails for prisms of order >= 3 in gmsh 4.8)
        nt = np.asarray(nt).reshape(len(et), -1)
        out.append((t, [np.array([xyz[n] for n in row]) for row in nt]))
    return out


def interpolate(t, x, uvw):
    _, bf, _ = gmsh.model.mesh.getBasisFunctions(int(t), np.asarray(uvw).flatten().tolist(), "Lagrange")
    return np.asarray(bf).reshape(len(uvw), -1) @ x


def gmsh_can_evaluate(name, p):
    return not (name == "pri" and p >= 3)


def check_file(f, path, name, p):
    gmsh.clear()
    gmsh.open(path)
    family = SHAPES[name][0]
    vols = element_nodes(3)
    f.check(len(vols) == 1 and len(vols[0][1]) == 1, f"{path}: expected one volume element")
    t, [x] = vols[0]
    f.check(t == gmsh.model.mesh.getElementType(family, p), f"{path}: element type {t}")
    if gmsh_can_evaluate(name, p):
        uvw = inside_points(name)
        err = np.abs(interpolate(t, x, uvw) - curved_map(uvw, p)).max()
        f.check(err < INTERPOLATION_TOLERANCE, f"{path}: gmsh interpolation differs from the map by {err:.3g}")
    elif p in PYFR_PRI:
        ref = np.array([pyfr_prism_reference(p, i) for i in PYFR_PRI[p]])
        err = np.abs(x - curved_map(ref, p)).max()
        f.check(err < INTERPOLATION_TOLERANCE, f"{path}: nodes differ from PyFR's Gmsh prism table by {err:.3g}")
    else:
        err = prism_vertices_edges_and_node_set_error(x, p)
        f.check(err < INTERPOLATION_TOLERANCE, f"{path}: prism vertices, edges or node set off the map by {err:.3g}")
    groups = {gmsh.model.getPhysicalName(d, tag) for d, tag in gmsh.model.getPhysicalGroups()}
    f.check("fluid" in groups, f"{path}: no 'fluid' physical group (got {groups})")
    nfaces = 0
    for t2, faces in element_nodes(2):
        quad = gmsh.model.mesh.getElementProperties(t2)[0].startswith("Quad")
        f.check(("quad" if quad else "tri") in groups, f"{path}: missing boundary group")
        for y in faces:
            nfaces += 1
            nv = 4 if quad else 3
            refv = [reference_of_vertex(name, p, y[k]) for k in range(nv)]
            uv = [(-0.3, 0.2), (0.5, -0.6), (0.1, 0.7)] if quad else [(0.2, 0.3), (0.6, 0.1), (0.1, 0.15)]
            if gmsh_can_evaluate(name, p):
                got = interpolate(t2, y, [(u, v, 0.0) for u, v in uv])
                want = curved_map([face_point(refv, q, quad) for q in uv], p)
                err = np.abs(got - want).max()
                f.check(err < INTERPOLATION_TOLERANCE, f"{path}: boundary {'quad' if quad else 'tri'} off the map by {err:.3g}")
    f.check(nfaces == {"tet": 4, "pyr": 5, "pri": 5, "hex": 6}[name], f"{path}: {nfaces} boundary faces")


def gmsh_valid(paths, name, p):
    """Whether det J > 0 at 100 random points of the one element of each file, by gmsh's own basis
    gradients (GradLagrange) and the nodes gmsh reads. The files hold elements of one type, so the
    gradients are evaluated once for all of them: that evaluation is what costs (~13 s for the
    order-9 hex's 1000 functions at 100 points, as much as gmsh's getJacobians, which gives the same
    determinants but evaluates them again for each file). Hexes of order >= 7 get 25 points: their
    gradients cost ~70 ms a point, and the folded sample is negative on a third of the element, so
    25 points miss it with probability (2/3)^25 < 1e-4 (and the seed is fixed)."""
    pts = inside_points(name, n=25 if (name == "hex" and p >= 7) else 100, seed=7)
    grads, valid = None, []
    for path in paths:
        gmsh.clear()
        gmsh.open(path)
        (t, [x]), = element_nodes(3)
        if grads is None:
            _, g, _ = gmsh.model.mesh.getBasisFunctions(int(t), pts.flatten().tolist(), "GradLagrange")
            grads = np.asarray(g).reshape(len(pts), len(x), 3)  # [point, node, d/du d/dv d/dw]
        jacobians = np.einsum("pnk,ni->pik", grads, x)  # [point, x y z, u v w]
        valid.append(float(np.min(np.linalg.det(jacobians))) > 0)
    return valid


def gmsh_content(path):
    """Nodes, elements per type, physical groups (dim, tag, name) of a file as gmsh reads it."""
    gmsh.open(path)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    types, etags, enodes = gmsh.model.mesh.getElements()
    groups = sorted((dim, tag, gmsh.model.getPhysicalName(dim, tag)) for dim, tag in gmsh.model.getPhysicalGroups())
    elements = {int(t): (list(et), list(en)) for t, et, en in zip(types, etags, enodes)}
    return list(tags), list(coords), elements, groups


def main():
    writer, checker = sys.argv[1], sys.argv[2]
    d = write_samples(writer)
    f = Failures()
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    for name in SHAPES:
        for p in range(1, 10):
            base = os.path.join(d, f"{name}_{p}")
            for path in [base + ".msh", base + "_v22.msh"] + ([base + "_gll.msh"] if p >= 2 else []):
                check_file(f, path, name, p)
            ascii_content = gmsh_content(base + ".msh")
            f.check(gmsh_content(base + "_bin.msh") == ascii_content, f"{base}_bin.msh: differs from the ASCII file")
            physical_tags = [tag for _, tag, _ in ascii_content[3]]
            f.check(len(set(physical_tags)) == len(physical_tags), f"{base}.msh: physical tags {ascii_content[3]}")
            if p < 2:
                continue
            samples = [(base + ".msh", True), (base + "_invalid.msh", False)]
            gmsh_says = gmsh_valid([path for path, _ in samples], name, p) if gmsh_can_evaluate(name, p) else None
            for (path, expect_valid), gmsh_ok in zip(samples, gmsh_says or [None] * len(samples)):
                run = subprocess.run([checker, "check", path, "--json"], capture_output=True, text=True)
                report = json.loads(run.stdout) if run.returncode in (0, 2) else None
                ours = run.returncode == 0
                f.check(report is not None, f"{path}: semimesh check failed: {run.stderr}")
                f.check(ours == expect_valid, f"{path}: semimesh check says valid={ours}")
                if report is not None:
                    f.check(len(report["invalid"]) == (0 if expect_valid else 1), f"{path}: invalid list {report['invalid']}")
                if gmsh_ok is not None:
                    f.check(gmsh_ok == ours, f"{path}: gmsh and semimesh check disagree")
    gmsh.finalize()
    f.finish("verify_msh")


if __name__ == "__main__":
    main()
