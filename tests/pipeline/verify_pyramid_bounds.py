"""The pyramid route of gmsh_validity.py (pyramid_bounds.py) against values known without it:
  - affine pyramids of orders 2..6: det J constant, min J / max J = 1;
  - the map w -> w + 0.3 w^2 (det J = 1 + 0.6 w): min J / max J = 1 / 1.6 exactly;
  - the map w -> w - 1.5 w^2 (det J = 1 - 3 w changes sign): proven invalid;
  - random curved pyramids of order 4: the certified ratio has the sign of det J sampled on a dense
    grid through Gmsh's own basis (getBasisFunctions "GradLagrange") and, when valid, is at most the
    sampled ratio and close to it.
It also prints what Gmsh 4.8's own plugin says of some of them (wrong from order 2 on; not asserted).

usage: verify_pyramid_bounds.py
"""
import os
import sys

import gmsh
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
sys.path.insert(0, os.path.join(here, "..", "io"))
import pyramid_bounds  # noqa: E402
from gmsh_validity import analyse  # noqa: E402
from sample_map import Failures  # noqa: E402


def reference(order):
    element_type = gmsh.model.mesh.getElementType("Pyramid", order)
    _, _, _, count, nodes, _ = gmsh.model.mesh.getElementProperties(element_type)
    return element_type, np.asarray(nodes).reshape(count, 3)


def basis_gradients(element_type, count, n=30):
    """Gmsh's basis gradients (points, nodes, 3) on a dense grid of the reference pyramid."""
    points = [((-1 + 2 * i / n) * (1 - z), (-1 + 2 * j / n) * (1 - z), z)
              for z in np.linspace(0, 1 - 1e-6, n + 1) for j in range(n + 1) for i in range(n + 1)]
    _, grads, _ = gmsh.model.mesh.getBasisFunctions(element_type, np.ravel(points).tolist(), "GradLagrange")
    return np.asarray(grads).reshape(len(points), count, 3)


def sampled_ratio(gradients, nodes):
    """min det J / max det J at the sample points."""
    det = np.linalg.det(np.einsum("gnk,nc->gck", gradients, nodes))
    return det.min() / det.max()


def plugin_ratio(element_type, nodes):
    gmsh.model.add("one")
    volume = gmsh.model.addDiscreteEntity(3)
    gmsh.model.mesh.addNodes(3, volume, list(range(1, len(nodes) + 1)), nodes.ravel().tolist())
    gmsh.model.mesh.addElementsByType(volume, element_type, [1], list(range(1, len(nodes) + 1)))
    ratio = analyse()[1][1]
    gmsh.model.remove()
    return ratio


def main():
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    f = Failures()
    for order in range(2, 7):
        element_type, r = reference(order)
        affine = r @ np.array([[0.03, 0.01, 0.0], [0.0, 0.005, 0.001], [0.002, 0.0, 0.02]]).T
        w = r[:, 2:3] * np.array([[0.0, 0.0, 1.0]])
        valid, folded = r + 0.3 * w ** 2, r - 1.5 * w ** 2
        (a, pa), (v, pv), (i, pi) = pyramid_bounds.certify(element_type, order, np.array([affine, valid, folded]))
        f.check(pa and abs(a - 1) < 1e-9, "order %d affine: %g (proven %s), expected 1" % (order, a, pa))
        f.check(pv and abs(v - 1 / 1.6) < 1e-9, "order %d w + 0.3 w^2: %g (proven %s), expected 0.625" % (order, v, pv))
        f.check(pi and i < 0, "order %d w - 1.5 w^2: %g (proven %s), expected proven invalid" % (order, i, pi))
        print("order %d: affine %.12f, curved %.12f, folded %.3g" % (order, a, v, i)
              + ("; gmsh's plugin on the affine one: %.6g" % plugin_ratio(element_type, affine) if order < 6 else ""))

    element_type, r = reference(4)
    rng = np.random.default_rng(12)
    base = np.array([[-1, -1, 0], [1, -1, 0.2], [1, 1, 0], [-1, 1, -0.1], [0.2, 0.1, 0.8]]) * [0.03, 0.006, 0.02]
    _, linear, _ = gmsh.model.mesh.getBasisFunctions(7, r.ravel().tolist(), "Lagrange")
    straight = np.asarray(linear).reshape(len(r), 5) @ base
    size = np.ptp(straight, axis=0).max()
    gradients = basis_gradients(element_type, len(r))
    for trial in range(40):
        amplitude = size * (0.003 if trial < 20 else 0.01)
        nodes = straight + amplitude * rng.standard_normal(straight.shape)
        nodes[:5] = base
        (bound, proven), = pyramid_bounds.certify(element_type, 4, nodes[None])
        sampled = sampled_ratio(gradients, nodes)
        if sampled > 0:  # (for an invalid element the two ratios have different denominators)
            f.check(bound <= sampled + 1e-9, "trial %d: certified %g above the sampled ratio %g" % (trial, bound, sampled))
        if sampled > 0.02:
            f.check(proven and bound > 0 and bound > sampled - 0.25,
                    "trial %d: sampled %g, certified %g (proven %s)" % (trial, sampled, bound, proven))
        if sampled < 0:
            f.check(proven and bound < 0, "trial %d: sampled %g < 0, certified %g (proven %s)" % (trial, sampled, bound, proven))
        if trial % 10 == 0:
            print("order 4 curved pyramid %d: sampled %.4f, certified %.4f, gmsh's plugin %.4f"
                  % (trial, sampled, bound, plugin_ratio(element_type, nodes)))
    gmsh.finalize()
    f.finish("verify_pyramid_bounds")


if __name__ == "__main__":
    main()
