#include "semimesh/pipeline/weld_nodes.hpp"

#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace semimesh::pipeline {
namespace {

// Points hashed by cells of size `tolerance`: an equal point lies in the same or a neighbouring cell.
class PointIndex {
 public:
  PointIndex(const mesh::Mesh& mesh, double tolerance) : mesh_(mesh), tolerance_(tolerance) {}

  /// The node already indexed within tolerance of v's point (v itself if none), then indexes v.
  mesh::NodeId find_or_add(mesh::NodeId v) {
    const Eigen::Vector3d& x = mesh_.node(v);
    const Cell c = cell_of(x);
    for (long long i = -1; i <= 1; ++i)
      for (long long j = -1; j <= 1; ++j)
        for (long long k = -1; k <= 1; ++k) {
          const auto it = cells_.find({c[0] + i, c[1] + j, c[2] + k});
          if (it == cells_.end()) continue;
          for (mesh::NodeId w : it->second)
            if (w == v || (mesh_.node(w) - x).norm() <= tolerance_) return w;
        }
    cells_[c].push_back(v);
    return v;
  }

 private:
  using Cell = std::array<long long, 3>;
  struct CellHash {
    std::size_t operator()(const Cell& c) const {
      return static_cast<std::size_t>(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
    }
  };
  Cell cell_of(const Eigen::Vector3d& x) const {
    return {static_cast<long long>(std::floor(x.x() / tolerance_)), static_cast<long long>(std::floor(x.y() / tolerance_)),
            static_cast<long long>(std::floor(x.z() / tolerance_))};
  }
  const mesh::Mesh& mesh_;
  double tolerance_;
  std::unordered_map<Cell, std::vector<mesh::NodeId>, CellHash> cells_;
};

}  // namespace

Welded weld_coincident_nodes(const mesh::Mesh& mesh, double tolerance) {
  const std::size_t n = mesh.num_nodes();
  std::vector<mesh::NodeId> to(n);
  for (std::size_t v = 0; v < n; ++v) to[v] = static_cast<mesh::NodeId>(v);
  Welded out{mesh::Mesh(mesh.order(), mesh.node_set()), 0};

  // Coincident vertices first (few nodes); then all nodes of the elements touching one of them.
  std::vector<char> seen(n, 0), merged_vertex(n, 0);
  PointIndex vertices(mesh, tolerance);
  for (const mesh::Element& e : mesh.elements())
    for (int k = 0; k < ho::num_vertices(e.shape); ++k) {
      const mesh::NodeId v = e.vertices[k];
      if (seen[v]) continue;
      seen[v] = 1;
      const mesh::NodeId w = vertices.find_or_add(v);
      if (w != v) merged_vertex[v] = merged_vertex[w] = 1;
    }
  PointIndex nodes(mesh, tolerance);
  std::vector<mesh::NodeId> list;
  std::fill(seen.begin(), seen.end(), 0);
  for (std::size_t e = 0; e < mesh.elements().size(); ++e) {
    const mesh::Element& el = mesh.elements()[e];
    bool touches = false;
    for (int k = 0; k < ho::num_vertices(el.shape); ++k) touches = touches || merged_vertex[el.vertices[k]];
    if (!touches) continue;
    mesh.element_nodes(e, list);
    for (mesh::NodeId v : list)
      if (!seen[v]) {
        seen[v] = 1;
        to[v] = nodes.find_or_add(v);
        if (to[v] != v) ++out.merged;
      }
  }

  out.mesh.copy_regions_from(mesh);
  for (std::size_t v = 0; v < n; ++v)
    out.mesh.add_node(mesh.node(static_cast<mesh::NodeId>(v)), mesh.cad_attachment(static_cast<mesh::NodeId>(v)));
  for (std::size_t e = 0; e < mesh.elements().size(); ++e) {
    mesh.element_nodes(e, list);
    for (mesh::NodeId& v : list) v = to[v];
    out.mesh.add_element(mesh.elements()[e].shape, list, mesh.elements()[e].region);
  }
  for (std::size_t b = 0; b < mesh.boundary_faces().size(); ++b) {
    std::vector<mesh::NodeId> face = mesh.boundary_face_nodes(b);
    for (mesh::NodeId& v : face) v = to[v];
    out.mesh.add_boundary_face(mesh.group_names()[mesh.boundary_faces()[b].group], mesh.boundary_faces()[b].shape, face);
  }
  return out;
}

}  // namespace semimesh::pipeline
