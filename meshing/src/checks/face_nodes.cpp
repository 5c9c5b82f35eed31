#include "face_nodes.hpp"

#include <Eigen/Geometry>

#include <map>
#include <mutex>
#include <tuple>

namespace semimesh::checks::detail {

const std::vector<std::vector<int>>& nodes_on_faces(ho::Shape shape, int order, ho::NodeSet set) {
  // Each thread remembers what it was given (map entries never move): the conformity check asks
  // once per use of every face, and the lock alone cost more than the lookup.
  using Key = std::tuple<ho::Shape, int, ho::NodeSet>;
  const Key key = std::make_tuple(shape, order, set);
  thread_local std::map<Key, const std::vector<std::vector<int>>*> known;
  if (const auto found = known.find(key); found != known.end()) return *found->second;
  static std::mutex mutex;
  static std::map<Key, std::vector<std::vector<int>>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(key);
  if (it != cache.end()) return *(known[key] = &it->second);

  const Eigen::MatrixX3d vertices = ho::reference_vertices(shape);
  const Eigen::MatrixX3d nodes = ho::reference_nodes(shape, order, set);
  std::vector<std::vector<int>> result;
  for (const std::vector<int>& face : ho::faces(shape)) {
    const Eigen::Vector3d v0 = vertices.row(face[0]);
    const Eigen::Vector3d normal =
        (Eigen::Vector3d(vertices.row(face[1])) - v0).cross(Eigen::Vector3d(vertices.row(face[2])) - v0).normalized();
    std::vector<int> on_face;
    for (int i = 0; i < nodes.rows(); ++i)
      if (std::abs(normal.dot(Eigen::Vector3d(nodes.row(i)) - v0)) < 1e-9) on_face.push_back(i);
    result.push_back(std::move(on_face));
  }
  return *(known[key] = &cache.emplace(key, std::move(result)).first->second);
}

bool same_cycle(const std::vector<unsigned>& a, const std::vector<unsigned>& b) {
  const std::size_t n = a.size();
  if (b.size() != n) return false;
  for (std::size_t shift = 0; shift < n; ++shift) {
    bool equal = true;
    for (std::size_t i = 0; i < n && equal; ++i) equal = a[i] == b[(i + shift) % n];
    if (equal) return true;
  }
  return false;
}

}  // namespace semimesh::checks::detail
