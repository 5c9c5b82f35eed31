#include "semimesh/mesh/compact.hpp"

#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

namespace semimesh::mesh {

std::size_t count_unreferenced_nodes(const Mesh& mesh) {
  const std::vector<char> used = mesh.referenced_nodes();
  return static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
}

Mesh without_unreferenced_nodes(Mesh m) {
  std::vector<NodeId> identity(m.num_nodes());
  std::iota(identity.begin(), identity.end(), NodeId{0});
  m.replace_nodes(std::move(identity));
  return m;
}

Mesh with_nodes_replaced(Mesh m, const std::vector<NodeId>& to, const std::function<void(double)>& done) {
  return with_nodes_replaced(std::move(m), to, {}, done);
}

Mesh with_nodes_replaced(Mesh m, const std::vector<NodeId>& to,
                         const std::unordered_map<NodeId, Eigen::Vector3d>& moved,
                         const std::function<void(double)>& done) {
  m.replace_nodes(to, moved, done);
  return m;
}

}  // namespace semimesh::mesh
