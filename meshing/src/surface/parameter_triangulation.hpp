// Constrained Delaunay triangulation of a surface's boundary loops in parameter space, refined by
// the size field measured in 3D. The only file that sees CGAL.
#pragma once

#include "semimesh/surface/surface_mesh.hpp"

#include <vector>

namespace semimesh::surface::detail {

/// `mesh` holds the boundary nodes; `loops` ([loops][nodes]) chains them. Appends the interior
/// nodes and the triangles, counter-clockwise in (u, v). Boundary segments are never split.
/// Nodes are inserted in (u, v) order and new nodes snapped to the grid of `grid_step`, so the
/// result depends only on the boundary's positions, not on the order the loops list them in.
/// Throws SurfaceMeshError when loops intersect or coincide in parameter space.
void triangulate_parameter_space(const cad::Model& model, int surface, const std::vector<std::vector<int>>& loops,
                                 const SizeField& size, double split_factor, double grid_step, SurfaceMesh& mesh);

}  // namespace semimesh::surface::detail
