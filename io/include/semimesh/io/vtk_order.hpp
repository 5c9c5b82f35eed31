// Node order of VTK Lagrange cells, derived from VTK's rules (VTK 9.1 sources:
// vtkHigherOrderTriangle / vtkHigherOrderTetra (recursive: vertices, edges, faces, interior as a
// lower-order cell), vtkHigherOrderQuadrilateral::PointIndexFromIJK,
// vtkHigherOrderHexahedron::PointIndexFromIJK (file version 2.2 edge order: vertical edges
// 0-4, 1-5, 2-6, 3-7), vtkHigherOrderWedge::PointIndexFromIJK (triangle faces and interior layers
// row by row)), and checked against vtkLagrange*::GetParametricCoords by tests/io/verify_vtu.py.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <vector>

namespace semimesh::io {

/// VTK cell type of a Lagrange cell (69 triangle, 70 quadrilateral, 71 tetrahedron,
/// 72 hexahedron, 73 wedge); 14 (linear VTK_PYRAMID) for pyramids of any order: VTK 9.1 has no
/// Lagrange pyramid, so pyramids are written straight-sided on their 5 vertices.
int vtk_cell_type(ho::Shape shape);

/// perm[i] = canonical (Gmsh) index of the i-th VTK point of the cell; for pyramids the 5 vertices.
const std::vector<int>& vtk_from_canonical(ho::Shape shape, int order);

}  // namespace semimesh::io
