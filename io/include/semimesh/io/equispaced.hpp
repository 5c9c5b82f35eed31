// Gmsh, VTK and Nektar++ (PolyEvenlySpaced) files expect equispaced high-order nodes.
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <vector>

namespace semimesh::io {

/// The node positions an equispaced mesh with the same element maps has (same node ids), for the
/// writers: the mesh's own positions when its nodes are equispaced (no copy), else one resampled
/// position per node, 24 bytes a node instead of a copy of the mesh. Each node is resampled once,
/// by the entity that owns it (ho::interpolation_matrix of that edge, face or element): the trace
/// of a Lagrange map on an edge or face depends only on that edge's or face's nodes, so every
/// element sharing it would compute the same point; vertices do not move.
class EquispacedNodes {
 public:
  explicit EquispacedNodes(const mesh::Mesh& mesh);
  EquispacedNodes(const EquispacedNodes&) = delete;
  EquispacedNodes& operator=(const EquispacedNodes&) = delete;

  const Eigen::Vector3d& operator[](mesh::NodeId id) const { return (*nodes_)[id]; }
  const std::vector<Eigen::Vector3d>& all() const { return *nodes_; }

 private:
  std::vector<Eigen::Vector3d> resampled_;  // empty when the mesh's nodes are equispaced already
  const std::vector<Eigen::Vector3d>* nodes_;
};

/// The slow, obviously right reference of EquispacedNodes: a copy of `mesh` whose nodes are the
/// equispaced nodes of the same element maps, every element resampled whole (shared nodes take the
/// last element's value, equal up to round-off). CAD attachments are dropped: the resampled nodes
/// are new points. An equispaced mesh is returned as is (copied).
mesh::Mesh to_equispaced(const mesh::Mesh& mesh);

}  // namespace semimesh::io
