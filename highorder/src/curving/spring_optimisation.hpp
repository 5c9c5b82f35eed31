// Spring optimisation of the free nodes of an edge or face on a CAD surface (see curve_mesh.hpp).
#pragma once

#include "semimesh/cad/surface.hpp"
#include "semimesh/ho/element_type.hpp"

#include <Eigen/Core>

namespace semimesh::ho::detail {

/// shape: Segment, Triangle or Quadrilateral of order `order` and node set `set`; its lattice
/// boundary nodes are fixed at the rows of `x`, the others are free and start at the rows of `uv`.
/// uv, x: (num_nodes, 2) and (num_nodes, 3) in canonical order. On success (converged: no free node
/// moved more than `tolerance` in the last iteration, all inside the trimmed face) the free rows of
/// uv and x hold the optimum and true is returned; otherwise uv is unchanged, the free rows of x are
/// S(uv) of the start, and false is returned.
bool optimise_on_surface(const cad::Surface& surface, Shape shape, int order, NodeSet set, Eigen::MatrixX2d& uv,
                         Eigen::MatrixX3d& x, int iterations, double tolerance);

}  // namespace semimesh::ho::detail
