#!/usr/bin/python3
"""Print Gmsh's own reference nodes (in Gmsh's MSH node order) as JSON.

Run with Debian's /usr/bin/python3, which has the gmsh module. Output:
  {"Triangle": {"3": [[x, y, z], ...], ...}, ...}
Only the (family, order) pairs this Gmsh can describe are listed: Gmsh 4.8 knows prisms only up to
order 2 and the other 3D shapes up to order 9 (it raises for the rest). The test that reads this
compares it with semimesh::ho::reference_nodes.
"""
import json
import sys

import gmsh

FAMILIES = ["Line", "Triangle", "Quadrangle", "Tetrahedron", "Pyramid", "Prism", "Hexahedron"]
MAX_ORDER = 10


def main():
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)  # keep Gmsh's "unknown order" errors off stdout
    result = {}
    for family in FAMILIES:
        by_order = {}
        for order in range(1, MAX_ORDER + 1):
            try:
                element_type = gmsh.model.mesh.getElementType(family, order)
                _, dim, _, num_nodes, coords, _ = gmsh.model.mesh.getElementProperties(element_type)
            except Exception:  # Gmsh raises for orders it cannot describe
                continue
            rows = [[0.0, 0.0, 0.0] for _ in range(num_nodes)]
            for node in range(num_nodes):
                for k in range(dim):
                    rows[node][k] = coords[node * dim + k]
            by_order[str(order)] = rows
        result[family] = by_order
    gmsh.finalize()
    json.dump(result, sys.stdout)


if __name__ == "__main__":
    main()
