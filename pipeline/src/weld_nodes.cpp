#include "semimesh/pipeline/weld_nodes.hpp"

#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace semimesh::pipeline {

Welded weld_coincident_nodes(const mesh::Mesh& mesh, double tolerance) {
  const std::size_t n = mesh.num_nodes();
  std::vector<char> used(n, 0);
  std::vector<mesh::NodeId> nodes;
  for (std::size_t e = 0; e < mesh.elements().size(); ++e) {
    mesh.element_nodes(e, nodes);
    for (mesh::NodeId v : nodes) used[v] = 1;
  }
  // Cells of size `tolerance`: a node's equal lies in its cell or a neighbouring one.
  using Cell = std::array<long long, 3>;
  auto cell_of = [&](const Eigen::Vector3d& x) {
    return Cell{std::llround(std::floor(x.x() / tolerance)), std::llround(std::floor(x.y() / tolerance)),
                std::llround(std::floor(x.z() / tolerance))};
  };
  std::map<Cell, std::vector<mesh::NodeId>> cells;
  std::vector<mesh::NodeId> to(n);
  Welded out{mesh::Mesh(mesh.order(), mesh.node_set()), 0};
  for (std::size_t v = 0; v < n; ++v) {
    to[v] = static_cast<mesh::NodeId>(v);
    if (!used[v]) continue;
    const Eigen::Vector3d& x = mesh.node(static_cast<mesh::NodeId>(v));
    const Cell c = cell_of(x);
    for (long long i = -1; i <= 1 && to[v] == v; ++i)
      for (long long j = -1; j <= 1 && to[v] == v; ++j)
        for (long long k = -1; k <= 1 && to[v] == v; ++k) {
          const auto it = cells.find({c[0] + i, c[1] + j, c[2] + k});
          if (it == cells.end()) continue;
          for (mesh::NodeId w : it->second)
            if ((mesh.node(w) - x).norm() <= tolerance) {
              to[v] = w;
              ++out.merged;
              break;
            }
        }
    if (to[v] == v) cells[c].push_back(static_cast<mesh::NodeId>(v));
  }

  out.mesh.copy_regions_from(mesh);
  for (std::size_t v = 0; v < n; ++v)
    out.mesh.add_node(mesh.node(static_cast<mesh::NodeId>(v)), mesh.cad_attachment(static_cast<mesh::NodeId>(v)));
  for (std::size_t e = 0; e < mesh.elements().size(); ++e) {
    mesh.element_nodes(e, nodes);
    for (mesh::NodeId& v : nodes) v = to[v];
    out.mesh.add_element(mesh.elements()[e].shape, nodes, mesh.elements()[e].region);
  }
  for (std::size_t b = 0; b < mesh.boundary_faces().size(); ++b) {
    std::vector<mesh::NodeId> face = mesh.boundary_face_nodes(b);
    for (mesh::NodeId& v : face) v = to[v];
    out.mesh.add_boundary_face(mesh.group_names()[mesh.boundary_faces()[b].group], mesh.boundary_faces()[b].shape, face);
  }
  return out;
}

}  // namespace semimesh::pipeline
