// Gmsh, VTK and Nektar++ (PolyEvenlySpaced) files expect equispaced high-order nodes.
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <vector>

namespace semimesh::io {

/// The node positions an equispaced mesh with the same element maps has (same node ids), for the
/// writers. Each node is resampled once, by the entity that owns it (ho::interpolation_matrix of
/// that edge, face or element): the trace of a Lagrange map on an edge or face depends only on that
/// edge's or face's nodes, so every element sharing it would compute the same point; vertices do not
/// move. Element interiors go first, then faces, then edges: each reads only nodes not yet moved,
/// which is what lets the positions be resampled where they are.
class EquispacedNodes {
 public:
  /// The mesh's own positions when its nodes are equispaced (no copy), else a resampled copy (24
  /// bytes a node).
  explicit EquispacedNodes(const mesh::Mesh& mesh);
  struct InPlace {};
  /// No whole copy: `mesh`'s own positions are resampled where they are and moved back when this
  /// object is destroyed: the nodes of element interiors exactly, from a copy of theirs kept
  /// meanwhile (24 bytes an interior node: resampling them back, every element's node list and
  /// its largest matrix, was most of the resampling back), the nodes of faces and edges by
  /// resampling, to round-off (~1e-16 of the coordinates).
  /// Meanwhile `mesh` must be read through this object only (its node set and CAD attachments do
  /// not describe them).
  EquispacedNodes(mesh::Mesh& mesh, InPlace);
  /// In place: the positions stay where they were resampled to when this object is destroyed,
  /// and the mesh is relabelled the equispaced node set and loses its CAD attachments (whose
  /// parameters its nodes no longer match): the mesh the files hold, to round-off, without
  /// resampling back (a caller that reads no position afterwards, e.g. the command line). No effect
  /// when nothing was resampled.
  void leave_resampled() { leave_resampled_ = true; }
  ~EquispacedNodes();
  EquispacedNodes(const EquispacedNodes&) = delete;
  EquispacedNodes& operator=(const EquispacedNodes&) = delete;

  const Eigen::Vector3d& operator[](mesh::NodeId id) const { return (*nodes_)[id]; }
  const std::vector<Eigen::Vector3d>& all() const { return *nodes_; }

 private:
  std::vector<Eigen::Vector3d> resampled_;  // the copy: empty in place or when equispaced already
  const std::vector<Eigen::Vector3d>* nodes_;
  mesh::Mesh* moved_ = nullptr;             // in place: the mesh whose positions go back
  std::vector<Eigen::Vector3d> kept_;       // in place: the interior nodes' positions, in pool order
  bool leave_resampled_ = false;
};

/// The slow, obviously right reference of EquispacedNodes: a copy of `mesh` whose nodes are the
/// equispaced nodes of the same element maps, every element resampled whole (shared nodes take the
/// last element's value, equal up to round-off). CAD attachments are dropped: the resampled nodes
/// are new points. An equispaced mesh is returned as is (copied).
mesh::Mesh to_equispaced(const mesh::Mesh& mesh);

}  // namespace semimesh::io
