#include "face_nodes.hpp"

#include "semimesh/mesh/node_layout.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
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

namespace {

// Whether `values` are 0, 1, ..., count - 1 in some order.
bool is_run(std::vector<int> values, int count) {
  std::sort(values.begin(), values.end());
  if (static_cast<int>(values.size()) != count) return false;
  for (int k = 0; k < count; ++k)
    if (values[k] != k) return false;
  return true;
}

// The sources of the face with local vertices `vertices` whose nodes are `positions` (canonical).
FaceSources sources_of(const mesh::NodeLayout& layout, const std::vector<int>& positions, int face,
                       const std::vector<int>& vertices) {
  const int P = layout.order, n = static_cast<int>(vertices.size());
  const int codes = static_cast<int>(mesh::face_permutations(n).size());
  FaceSources out;
  std::map<int, std::array<std::vector<int>, 2>> edge_slots;  // local edge -> slots as stored, backwards
  std::vector<std::vector<int>> face_slots(static_cast<std::size_t>(codes));
  bool only_these = true;
  for (int position : positions) {
    const mesh::NodeSlot& s = layout.slots[static_cast<std::size_t>(position)];
    switch (s.kind) {
      case mesh::NodeSlot::Vertex:
        only_these = only_these && std::find(vertices.begin(), vertices.end(), s.local) != vertices.end();
        break;
      case mesh::NodeSlot::Edge:
        for (int way = 0; way < 2; ++way) edge_slots[s.local][static_cast<std::size_t>(way)].push_back(s.slot[way]);
        break;
      case mesh::NodeSlot::Face:
        only_these = only_these && s.local == face;
        for (int c = 0; c < codes; ++c) face_slots[static_cast<std::size_t>(c)].push_back(s.slot[c]);
        break;
      case mesh::NodeSlot::Interior: only_these = false; break;
    }
  }
  out.whole = only_these;
  for (const auto& [edge, slots] : edge_slots) {
    out.edges.push_back(edge);
    for (const std::vector<int>& way : slots) out.whole = out.whole && is_run(way, mesh::edge_interior_count(P));
  }
  for (const std::vector<int>& code : face_slots) out.whole = out.whole && is_run(code, mesh::face_interior_count(n, P));
  return out;
}

}  // namespace

const std::vector<FaceSources>& face_sources(ho::Shape shape, int order, ho::NodeSet set) {
  using Key = std::tuple<ho::Shape, int, ho::NodeSet>;
  const Key key = std::make_tuple(shape, order, set);
  thread_local std::map<Key, const std::vector<FaceSources>*> known;  // as nodes_on_faces
  if (const auto found = known.find(key); found != known.end()) return *found->second;
  static std::mutex mutex;
  static std::map<Key, std::vector<FaceSources>> cache;
  std::vector<FaceSources> result;
  const mesh::NodeLayout& layout = mesh::node_layout(shape, order);
  if (ho::dimension(shape) == 2) {
    std::vector<int> all(layout.slots.size()), vertices(static_cast<std::size_t>(ho::num_vertices(shape)));
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    for (std::size_t v = 0; v < vertices.size(); ++v) vertices[v] = static_cast<int>(v);
    result.push_back(sources_of(layout, all, 0, vertices));
  } else {
    const std::vector<std::vector<int>>& on_faces = nodes_on_faces(shape, order, set);
    for (std::size_t f = 0; f < on_faces.size(); ++f)
      result.push_back(sources_of(layout, on_faces[f], static_cast<int>(f), ho::faces(shape)[f]));
  }
  std::lock_guard<std::mutex> lock(mutex);
  const auto [it, fresh] = cache.emplace(key, std::move(result));
  return *(known[key] = &it->second);
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
