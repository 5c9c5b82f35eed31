"""Certified bounds of det J of high-order pyramids, evaluated through Gmsh's own basis functions.

Why not Gmsh's Plugin(AnalyseMeshQuality): in Gmsh 4.8 its Jacobian bounds of pyramids are wrong
from order 2 on (order 2: 0.0 for curved pyramids whose det J sampled through Gmsh's basis has
min / max 0.33-0.64, at a swept sharp trailing edge's tip end). The plugin gives min J / max J = 0.0 for an affine pyramid of order 5 (exactly 1),
and on the coarse H-type mesh of order 4 (tests/pipeline/CMakeLists.txt) it reports 61 pyramids
with min J / max J between -2.57 and -0.0, while det J sampled on a 41^3 grid through Gmsh's own
Lagrange basis (getBasisFunctions "GradLagrange" on the same nodes) is positive on every one of
them, with the same ratio as the order-1 pyramid on their vertices, which the plugin itself
certifies (e.g. 0.2431 where it says -2.568), and the bounds below prove them valid.

The exact route, independent of semimesh's element library:
  - Gmsh's pyramid space of order P (Bergot, Cohen & Durufle 2010, "Higher-order finite elements
    for hybrid meshes using new nodal pyramidal elements", J. Sci. Comput. 42) is spanned by
    a^i b^j (1-c)^max(i,j) c^k, k <= P - max(i,j), in the collapsed coordinates
    u = (2a-1)(1-c), v = (2b-1)(1-c), w = c of the reference pyramid (Gmsh's: base [-1,1]^2 at
    w = 0, apex (0,0,1)). Composed with the collapse, the element's map x(a,b,c) is therefore a
    polynomial of degree P in each of a, b, c: it is interpolated from its values at a tensor grid
    of (P+1)^3 points with c < 1 (Gmsh's basis evaluates them), and checked at other points;
  - det[x_a, x_b, x_c] = 4 (1-c)^2 det J(u,v,w); x_a and x_b carry the factor (1-c), removed
    exactly in the Bernstein basis, so det J = det[x_a / 2(1-c), x_b / 2(1-c), x_c] is a polynomial
    of degree (3P-1, 3P-1, 3P-3) in (a, b, c) whose tensor Bernstein coefficients bound it
    (Johnen, Remacle & Geuzaine 2013, J. Comput. Phys. 233: non-negative basis summing to one);
  - a piece whose lowest coefficient is not clearly positive is halved (de Casteljau) along its
    longest side, up to MAX_DEPTH times; a corner coefficient is an exact value, so a negative one
    proves the element invalid.
"""
from math import comb

import gmsh
import numpy as np

MAX_DEPTH = 12
# Coefficients are computed from sampled values through inverse Vandermonde matrices; a lowest
# coefficient within this fraction of the largest one of its element is not taken as a sign.
ROUNDING = 1e-10


def bernstein(degree, t):
    """(len(t), degree + 1): B^degree_k(t)."""
    t = np.asarray(t, dtype=float)[:, None]
    k = np.arange(degree + 1)[None, :]
    binomial = np.array([comb(degree, i) for i in range(degree + 1)], dtype=float)[None, :]
    return binomial * t ** k * (1 - t) ** (degree - k)


def chebyshev(count):
    """count Chebyshev-Gauss points in (0, 1): inside, so c < 1 (the apex, where the basis is 0/0)."""
    return (1 - np.cos(np.pi * (np.arange(count) + 0.5) / count)) / 2


def values_to_bernstein(values, degrees, points):
    """values (E, na, nb, nc, ...) at the tensor grid points[0] x points[1] x points[2] ->
    tensor Bernstein coefficients of the given degrees, same shape."""
    out = values
    for axis, (degree, t) in enumerate(zip(degrees, points)):
        inverse = np.linalg.inv(bernstein(degree, t))
        out = np.moveaxis(np.tensordot(inverse, out, axes=([1], [axis + 1])), 0, axis + 1)
    return out


def bernstein_to_values(coefficients, degrees, points):
    out = coefficients
    for axis, (degree, t) in enumerate(zip(degrees, points)):
        out = np.moveaxis(np.tensordot(bernstein(degree, t), out, axes=([1], [axis + 1])), 0, axis + 1)
    return out


def collapsed_to_reference(a, b, c):
    return np.stack([(2 * a - 1) * (1 - c), (2 * b - 1) * (1 - c), c], axis=-1)


def tensor_grid(points):
    a, b, c = np.meshgrid(*points, indexing="ij")
    return a.ravel(), b.ravel(), c.ravel()


def gmsh_map_values(element_type, nodes, points):
    """(E, n0, n1, n2, 3): the elements' maps at the collapsed tensor grid, through Gmsh's basis."""
    a, b, c = tensor_grid(points)
    uvw = collapsed_to_reference(a, b, c)
    _, basis, _ = gmsh.model.mesh.getBasisFunctions(element_type, uvw.ravel().tolist(), "Lagrange")
    basis = np.asarray(basis).reshape(len(a), nodes.shape[1])
    x = np.einsum("gn,enc->egc", basis, nodes)
    return x.reshape((len(nodes),) + tuple(len(p) for p in points) + (3,))


def map_coefficients(element_type, order, nodes):
    """Tensor Bernstein coefficients (E, P+1, P+1, P+1, 3) of x(a, b, c), checked against Gmsh's
    basis at points off the interpolation grid (the premise that the composed map is in Q_P)."""
    grid = [chebyshev(order + 1)] * 3
    coefficients = values_to_bernstein(gmsh_map_values(element_type, nodes, grid), [order] * 3, grid)
    check = [np.array([0.0, 0.37, 1.0]), np.array([0.0, 0.61, 1.0]), np.array([0.0, 0.29, 0.9])]
    expected = gmsh_map_values(element_type, nodes, check)
    found = bernstein_to_values(coefficients, [order] * 3, check)
    error = np.abs(found - expected).reshape(len(nodes), -1).max(axis=1)
    if np.any(error > 1e-9 * np.ptp(nodes, axis=1).max(axis=1)):
        raise RuntimeError("pyramid_bounds: Gmsh's pyramid map of order %d is not a tensor polynomial of the "
                           "collapsed coordinates (the premise of this check)" % order)
    return coefficients


def divide_by_one_minus_c(p):
    """Exact quotient q = p / (1 - c) of a Bernstein polynomial of degree n in c (the last axis
    before the components) with p(c = 1) = 0: (1-c) B^{n-1}_k = (n-k)/n B^n_k."""
    n = p.shape[3] - 1
    k = np.arange(n)
    return p[:, :, :, :n, :] * (n / (n - k))[None, None, None, :, None]


def scaled(coefficients):
    """Tensor Bernstein coefficients times the binomials C(n0, i) C(n1, j) C(n2, k): in these the
    product of two polynomials is the convolution of the coefficients."""
    out = coefficients
    for axis in range(3):
        n = out.shape[axis + 1] - 1
        shape = [1] * out.ndim
        shape[axis + 1] = n + 1
        out = out * np.array([comb(n, i) for i in range(n + 1)], dtype=float).reshape(shape)
    return out


def product(f, g):
    """Tensor Bernstein coefficients (E, ...) of f g, exactly (Farin, "Curves and surfaces for
    CAGD", the product of Bernstein polynomials), without sampling."""
    sf, sg = scaled(f), scaled(g)
    degrees = [f.shape[a] + g.shape[a] - 2 for a in (1, 2, 3)]
    out = np.zeros((len(f),) + tuple(d + 1 for d in degrees))
    for i, j, k in np.ndindex(*f.shape[1:4]):
        out[:, i:i + g.shape[1], j:j + g.shape[2], k:k + g.shape[3]] += sf[:, i, j, k, None, None, None] * sg
    for axis, n in enumerate(degrees):
        shape = [1] * out.ndim
        shape[axis + 1] = n + 1
        out = out / np.array([comb(n, i) for i in range(n + 1)], dtype=float).reshape(shape)
    return out


def jacobian_coefficients(element_type, order, nodes):
    """(E, 3P, 3P, 3P-2): Bernstein coefficients of det J(u, v, w) over the collapsed cube."""
    x = map_coefficients(element_type, order, nodes)
    p = order
    xa = divide_by_one_minus_c(p * (x[:, 1:] - x[:, :-1])) / 2      # degrees (P-1, P, P-1)
    xb = divide_by_one_minus_c(p * (x[:, :, 1:] - x[:, :, :-1])) / 2  # (P, P-1, P-1)
    xc = p * (x[:, :, :, 1:] - x[:, :, :, :-1])                       # (P, P, P-1)
    det = 0.0
    for i, j, k in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
        cross = product(xa[..., j], xb[..., k]) - product(xa[..., k], xb[..., j])
        det = det + product(cross, xc[..., i])
    return det


def halve(coefficients, axis):
    """de Casteljau at 1/2 along `axis` of one tensor Bernstein polynomial: its two halves."""
    left, right = [], []
    row = np.moveaxis(coefficients, axis, 0)
    while len(row):
        left.append(row[0])
        right.append(row[-1])
        row = (row[1:] + row[:-1]) / 2
    return np.moveaxis(np.array(left), 0, axis), np.moveaxis(np.array(right[::-1]), 0, axis)


def refine(coefficients):
    """(min det J lower bound, proven): subdivides the pieces whose coefficients are not clearly
    positive. proven is True when the sign is proven either way."""
    scale = np.abs(coefficients).max()
    pending = [(coefficients, np.ones(3))]
    lower = np.inf
    for _ in range(MAX_DEPTH * 3):
        unsettled = []
        for piece, extent in pending:
            low = piece.min()
            if low > ROUNDING * scale:
                lower = min(lower, low)
                continue
            corners = piece[np.ix_(*[[0, n - 1] for n in piece.shape])]
            if corners.min() <= 0:
                return min(lower, corners.min()), True
            unsettled.append((piece, extent))
        if not unsettled:
            return lower, True
        pending = []
        for piece, extent in unsettled:
            axis = int(np.argmax(extent))
            half = extent.copy()
            half[axis] /= 2
            for part in halve(piece, axis):
                pending.append((part, half))
    return min(lower, min(p.min() for p, _ in pending)), False


def certify(element_type, order, nodes, chunk=500):
    """nodes (E, nodes per pyramid, 3), Gmsh order -> list of (min J lower bound / max J upper
    bound, proven) per pyramid. Needs an initialised Gmsh (for the basis functions)."""
    out = []
    for start in range(0, len(nodes), chunk):
        coefficients = jacobian_coefficients(element_type, order, nodes[start:start + chunk])
        for c in coefficients:
            upper = c.max()
            if c.min() > ROUNDING * np.abs(c).max():
                out.append((c.min() / upper, True))
                continue
            lower, proven = refine(c)
            out.append((lower / max(abs(upper), abs(lower)), proven))
    return out
