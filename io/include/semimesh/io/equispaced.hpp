// Gmsh, VTK and Nektar++ (PolyEvenlySpaced) files expect equispaced high-order nodes.
#pragma once

#include "semimesh/mesh/mesh.hpp"

namespace semimesh::io {

/// A copy of `mesh` whose nodes are the equispaced nodes of the same element maps (same node ids,
/// same entities). Each element is resampled with ho::interpolation_matrix; shared edge and face
/// nodes get the same value from every element (the trace of a Lagrange map on an edge/face
/// depends only on the nodes of that edge/face), up to round-off. CAD attachments are dropped:
/// the resampled nodes are new points. An equispaced mesh is returned as is (copied).
mesh::Mesh to_equispaced(const mesh::Mesh& mesh);

}  // namespace semimesh::io
