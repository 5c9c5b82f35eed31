"""Gmsh's certified Jacobian bounds for every volume element of a .msh file, prisms of order >= 3 included.

Gmsh 4.8 (Debian 12) certifies the Jacobian of tets, pyramids, hexes and prisms of order <= 2
itself (Plugin(AnalyseMeshQuality): Bezier bounds with adaptive subdivision), but it cannot build
prisms of order >= 3 ("FaceClosureFull not implemented"). So each such prism is handed to Gmsh as
three hexahedra of the same order P that tile it exactly:
  - the reference triangle is cut into three convex quadrilaterals (a vertex, the midpoints of its
    two edges, the centroid); the bilinear map of each onto the unit square has degree 1 in s and
    in t, so the prism map, in P_P(x, y) x P_P(z), composed with it lies in Q_P: an order-P hex;
  - det J of a piece = det J of the prism x det of the bilinear map (> 0 on a convex quadrilateral)
    x 1, so the prism is valid iff its three pieces are. The pieces' min J / max J is a different
    ratio from the prism's (the bilinear determinant varies), so only its sign is compared.
Hexes are half the cost of the other exact split (three tets of order 2P) in Gmsh.

Pyramids of order >= 2: Gmsh 4.8's plugin bounds them wrongly (an affine order-5 pyramid gets 0,
valid order-4 pyramids get negative values, and order-2 pyramids 0: five at a swept sharp trailing
edge's tip end whose det J sampled on a 25^3 grid through Gmsh's own basis has min / max 0.33 to
0.64, a wing on a conical hub's 0.0089 for 0.997): they are certified by pyramid_bounds.py instead,
which evaluates them through Gmsh's own basis functions and bounds det J exactly (see its
docstring; on the five it proves 0.0617 and more, our certification's figure).

The prism is evaluated independently of semimesh's element library: Gmsh's prism node layout comes
from PyFR's published Gmsh node maps (PyFR/PyFR, pyfr/readers/nodemaps.py,
GmshNodeMaps.to_pyfr['pri', n], a fact table copied as data in tests/io/verify_msh.py, orders 3..6),
the Lagrange basis from a monomial Vandermonde matrix, the hex nodes from Gmsh's
getElementProperties.
"""
import multiprocessing
import os
import sys

import gmsh
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "io"))
from verify_msh import PYFR_PRI, pyfr_prism_reference  # noqa: E402
import pyramid_bounds  # noqa: E402

# Gmsh element types of prisms of order 3..6 (gmsh.model.mesh.getElementType("Prism", P)).
HIGH_ORDER_PRISM_TYPES = {90: 3, 91: 4, 106: 5, 107: 6}
# ... and of order 3..9: getElementProperties raises for all of them.
UNDESCRIBED_PRISM_TYPES = {90, 91, 106, 107, 108, 109, 110}
_C = (1.0 / 3.0, 1.0 / 3.0)
# The three quadrilaterals (counter-clockwise, like the triangle) tiling the reference triangle.
TRIANGLE_QUADS = (((0, 0), (0.5, 0), _C, (0, 0.5)),
                  ((1, 0), (0.5, 0.5), _C, (0.5, 0)),
                  ((0, 1), (0, 0.5), _C, (0.5, 0.5)))
CHUNK = 2000  # prisms per Gmsh model and task
# Pyramids from this order on go to pyramid_bounds.py (Gmsh 4.8's plugin is wrong for them).
FIRST_WRONG_PYRAMID_ORDER = 2


def prism_monomials(order, points):
    """(len(points), (P+1)^2 (P+2)/2): x^i y^j z^k with i + j <= P and k <= P at the points (n, 3)."""
    x, y, z = points[:, 0], points[:, 1], points[:, 2]
    cols = [x ** i * y ** j * z ** k for k in range(order + 1) for j in range(order + 1)
            for i in range(order + 1 - j)]
    return np.stack(cols, axis=1)


def prism_to_hexes_matrix(order, hex_nodes):
    """(3, hex nodes, prism nodes): Gmsh prism nodes -> Gmsh nodes of its three order-P hexes.
    hex_nodes: (hex nodes, 3) Gmsh reference coordinates in [-1, 1]^3."""
    reference = np.array([pyfr_prism_reference(order, i) for i in PYFR_PRI[order]])
    inverse_vandermonde = np.linalg.inv(prism_monomials(order, reference))
    s, t, w = hex_nodes[:, 0], hex_nodes[:, 1], hex_nodes[:, 2]
    shape = np.stack([(1 - s) * (1 - t), (1 + s) * (1 - t), (1 + s) * (1 + t), (1 - s) * (1 + t)], axis=1) / 4
    matrices = []
    for quad in TRIANGLE_QUADS:
        uv = shape @ np.array(quad)
        points = np.column_stack([uv, w])
        matrices.append(prism_monomials(order, points) @ inverse_vandermonde)
    return np.stack(matrices)


def analyse():
    """Runs AnalyseMeshQuality on the current model: {element tag: (min J, min J / max J)}."""
    gmsh.plugin.setNumber("AnalyseMeshQuality", "JacobianDeterminant", 1)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "CreateView", 1)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "DimensionOfElements", 3)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "Recompute", 1)  # it caches its last model's results
    gmsh.plugin.run("AnalyseMeshQuality")
    values = {}
    for view in gmsh.view.getTags():
        name = gmsh.option.getString("View[%d].Name" % gmsh.view.getIndex(view))
        column = 1 if name.startswith("minJ/maxJ") else 0 if name.startswith("minJ") else None
        if column is not None:
            _, tags, data, _, _ = gmsh.view.getModelData(view, 0)
            for tag, d in zip(tags, data):
                values.setdefault(tag, [0.0, 0.0])[column] = d[0]
        gmsh.view.remove(view)
    return values


# Points of the reference pyramid (Gmsh's: base [-1, 1]^2 at z = 0, apex at z = 1) where det J is
# sampled: a grid in each of 8 layers below the apex.
def _pyramid_samples(per_side=8):
    points = []
    for k in range(per_side):
        z = 0.999 * k / per_side
        for i in range(per_side + 1):
            for j in range(per_side + 1):
                points += [(-1 + 2 * i / per_side) * (1 - z), (-1 + 2 * j / per_side) * (1 - z), z]
    return points


def pyramids_sampled(certified):
    """certified: analyse()'s result on the current model. Returns one ratio per element: the
    certified one, except for pyramids, whose ratio det J min / max is sampled on Gmsh's own basis
    (an upper bound of the true ratio, as any sample is). Gmsh 4.8's AnalyseMeshQuality bounds
    some curved order-2 pyramids far below their true ratio (0.0089 for one sampled at 0.997 on the
    same basis, a wing on a conical hub), so its pyramid figure is no bound to compare ours with."""
    ratios = dict((tag, v[1]) for tag, v in certified.items())
    points = _pyramid_samples()
    for order in range(1, FIRST_WRONG_PYRAMID_ORDER):
        element_type = gmsh.model.mesh.getElementType("Pyramid", order)
        tags, _ = gmsh.model.mesh.getElementsByType(element_type)
        if len(tags) == 0:
            continue
        _, det, _ = gmsh.model.mesh.getJacobians(element_type, points)
        det = np.asarray(det).reshape(len(tags), -1)
        for tag, d in zip(tags, det):
            ratios[tag] = d.min() / d.max()
    return list(ratios.values())


def _certify_pieces(task):
    """task: (hex type, (n, 3, hex nodes, 3) piece nodes). Min over the three pieces of Gmsh's
    min J / max J, per prism (runs in a worker with its own Gmsh)."""
    hex_type, pieces = task
    n, count, per_hex, _ = pieces.shape
    gmsh.model.add("prism_pieces")
    volume = gmsh.model.addDiscreteEntity(3)
    node_tags = np.arange(1, n * count * per_hex + 1)
    gmsh.model.mesh.addNodes(3, volume, node_tags.tolist(), pieces.reshape(-1).tolist())
    element_tags = np.arange(1, n * count + 1)
    gmsh.model.mesh.addElementsByType(volume, hex_type, element_tags.tolist(), node_tags.tolist())
    values = analyse()
    gmsh.model.remove()
    return np.array([values[t][1] for t in element_tags]).reshape(n, count).min(axis=1).tolist()


def _start_worker():
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)


def element_counts(types, tags):
    """{'tetrahedron': n, 'prism': n, ...} of the elements of these Gmsh types."""
    counts = {}
    for t, tg in zip(types, tags):
        name = "prism" if t in UNDESCRIBED_PRISM_TYPES else gmsh.model.mesh.getElementProperties(t)[0].split(" ")[0]
        counts[name.lower()] = counts.get(name.lower(), 0) + len(tg)
    return counts


def gmsh_counts(path):
    """Element counts of the .msh file as Gmsh reads it (any order)."""
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(path)
        types, tags, _ = gmsh.model.mesh.getElements(3)
        return element_counts(types, tags)
    finally:
        gmsh.finalize()


def certified_ratios(path, processes=2, progress=None):
    """Gmsh's certified min J / max J for the volume elements of the .msh file `path`:
    {'counts': {'tetrahedron': n, 'prism': n, ...}, 'direct': [one per element Gmsh certifies
    itself], 'prisms': [min over the three hex pieces of each prism of order >= 3],
    'pyramids': [pyramid_bounds' certified ratio of each pyramid of order >= 2],
    'comparable': [an upper bound of each directly certified element's true min J / max J: Gmsh's
    certified ratio, or for a pyramid its ratio sampled on Gmsh's basis (pyramids_sampled)]}.
    Opens its own Gmsh sessions (gmsh must not be initialised by the caller)."""
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(path)
        types, tags, nodes = gmsh.model.mesh.getElements(3)
        counts = element_counts(types, tags)
        beyond = [int(t) for t in types if t in UNDESCRIBED_PRISM_TYPES and t not in HIGH_ORDER_PRISM_TYPES]
        if beyond:
            raise RuntimeError("%s: prisms of Gmsh type %s (order > 6): no node table to certify them with" % (path, beyond))
        high_order = [(t, np.asarray(nd)) for t, nd in zip(types, nodes) if t in HIGH_ORDER_PRISM_TYPES]
        wrong_pyramids = {gmsh.model.mesh.getElementType("Pyramid", p): p
                          for p in range(FIRST_WRONG_PYRAMID_ORDER, 10)}
        pyramid_blocks = [(t, np.asarray(nd)) for t, nd in zip(types, nodes) if t in wrong_pyramids]
        node_tags, coords, _ = gmsh.model.mesh.getNodes()
        position = np.empty((int(np.max(node_tags)) + 1, 3))
        position[np.asarray(node_tags, dtype=np.int64)] = np.asarray(coords).reshape(-1, 3)
        direct, comparable = [], []
        if len(high_order) + len(pyramid_blocks) < len(types):
            if high_order or pyramid_blocks:  # the plugin stops at the first prism it cannot build: the others alone
                gmsh.model.add("direct")
                volume = gmsh.model.addDiscreteEntity(3)
                gmsh.model.mesh.addNodes(3, volume, np.asarray(node_tags).tolist(), np.asarray(coords).tolist())
                for t, tg, nd in zip(types, tags, nodes):
                    if t not in HIGH_ORDER_PRISM_TYPES and t not in wrong_pyramids:
                        gmsh.model.mesh.addElementsByType(volume, t, np.asarray(tg).tolist(), np.asarray(nd).tolist())
            certified = analyse()
            direct = list(v[1] for v in certified.values())
            comparable = pyramids_sampled(certified)
        pyramids = []
        for element_type, element_nodes in pyramid_blocks:
            order = wrong_pyramids[element_type]
            connectivity = element_nodes.reshape(-1, (order + 1) * (order + 2) * (2 * order + 3) // 6).astype(np.int64)
            for ratio, proven in pyramid_bounds.certify(element_type, order, position[connectivity]):
                pyramids.append(ratio if proven else min(ratio, 0.0))  # unproven counts as invalid
        tasks = []
        if high_order:
            for element_type, element_nodes in high_order:
                order = HIGH_ORDER_PRISM_TYPES[element_type]
                hex_type = gmsh.model.mesh.getElementType("Hexahedron", order)
                _, _, _, per_hex, hex_nodes, _ = gmsh.model.mesh.getElementProperties(hex_type)
                to_hexes = prism_to_hexes_matrix(order, np.asarray(hex_nodes).reshape(per_hex, 3))
                connectivity = element_nodes.reshape(-1, len(PYFR_PRI[order])).astype(np.int64)
                for start in range(0, len(connectivity), CHUNK):
                    x = position[connectivity[start:start + CHUNK]]  # (n, prism nodes, 3)
                    tasks.append((hex_type, np.einsum("tqp,npc->ntqc", to_hexes, x)))
    finally:
        gmsh.finalize()
    prisms = []
    if tasks:
        with multiprocessing.get_context("fork").Pool(processes, initializer=_start_worker) as pool:
            for done, result in enumerate(pool.imap(_certify_pieces, tasks), 1):
                prisms.extend(result)
                if progress:
                    progress(done, len(tasks))
    return {"counts": counts, "direct": direct, "comparable": comparable, "prisms": prisms, "pyramids": pyramids}
