#include "semimesh/farfield/detail/boundary_crossing.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <numeric>
#include <utility>

namespace semimesh::farfield {
namespace {

using Eigen::Vector3d;

// Where segment pq passes strictly through the interior of triangle abc, if it does.
std::optional<Vector3d> pierce(const Vector3d& p, const Vector3d& q, const Vector3d& a, const Vector3d& b,
                               const Vector3d& c) {
  const Vector3d n = (b - a).cross(c - a);
  const double dp = n.dot(p - a), dq = n.dot(q - a);
  if ((dp >= 0 && dq >= 0) || (dp <= 0 && dq <= 0)) return std::nullopt;
  const Vector3d x = p + dp / (dp - dq) * (q - p);
  if (n.dot((b - a).cross(x - a)) > 0 && n.dot((c - b).cross(x - b)) > 0 && n.dot((a - c).cross(x - c)) > 0) return x;
  return std::nullopt;
}

bool share_a_point(const std::array<int, 3>& s, const std::array<int, 3>& t) {
  for (int a : s)
    for (int b : t)
      if (a == b) return true;
  return false;
}

// Whether an edge of triangle s passes through the interior of triangle t (or one of t's through
// s), for triangles sharing no point.
std::optional<Crossing> crossing_of(const std::vector<Vector3d>& points, const std::vector<std::array<int, 3>>& triangles,
                                    int s, int t) {
  if (share_a_point(triangles[s], triangles[t])) return std::nullopt;
  for (const auto& [e, f] : {std::pair{s, t}, std::pair{t, s}}) {
    const auto& edge = triangles[e];
    const auto& face = triangles[f];
    for (int k = 0; k < 3; ++k)
      if (auto x = pierce(points[edge[k]], points[edge[(k + 1) % 3]], points[face[0]], points[face[1]], points[face[2]]))
        return Crossing{e, f, *x};
  }
  return std::nullopt;
}

struct Box {
  Vector3d lo, hi;
  bool overlaps(const Box& o) const { return !((o.lo.array() > hi.array()).any() || (lo.array() > o.hi.array()).any()); }
};

std::vector<Box> triangle_boxes(const std::vector<Vector3d>& points, const std::vector<std::array<int, 3>>& triangles) {
  std::vector<Box> boxes(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    boxes[i].lo = boxes[i].hi = points[triangles[i][0]];
    for (int k = 1; k < 3; ++k) {
      boxes[i].lo = boxes[i].lo.cwiseMin(points[triangles[i][k]]);
      boxes[i].hi = boxes[i].hi.cwiseMax(points[triangles[i][k]]);
    }
  }
  return boxes;
}

// A bounding-box tree over the triangles: each node's box holds its items', split at the median
// of the items' centres along the longest side, leaves of at most kLeaf items.
class BoxTree {
 public:
  explicit BoxTree(const std::vector<Box>& boxes) : boxes_(boxes), items_(boxes.size()) {
    std::iota(items_.begin(), items_.end(), 0);
    if (!items_.empty()) build(0, static_cast<int>(items_.size()));
  }

  // f(item) for every item whose box overlaps `query`.
  template <class F>
  void visit_overlaps(const Box& query, F&& f) const {
    if (nodes_.empty()) return;
    std::vector<int> stack{0};
    while (!stack.empty()) {
      const Node& node = nodes_[stack.back()];
      stack.pop_back();
      if (!node.box.overlaps(query)) continue;
      if (node.left < 0) {
        for (int i = node.first; i < node.first + node.count; ++i)
          if (boxes_[items_[i]].overlaps(query)) f(items_[i]);
        continue;
      }
      stack.push_back(node.left);
      stack.push_back(node.right);
    }
  }

 private:
  static constexpr int kLeaf = 8;
  struct Node {
    Box box;
    int first = 0, count = 0, left = -1, right = -1;
  };

  int build(int first, int count) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.push_back({boxes_[items_[first]], first, count});
    Box box = boxes_[items_[first]];
    Box centres{box.lo + box.hi, box.lo + box.hi};
    for (int i = first + 1; i < first + count; ++i) {
      const Box& b = boxes_[items_[i]];
      box.lo = box.lo.cwiseMin(b.lo), box.hi = box.hi.cwiseMax(b.hi);
      centres.lo = centres.lo.cwiseMin(b.lo + b.hi), centres.hi = centres.hi.cwiseMax(b.lo + b.hi);
    }
    nodes_[id].box = box;
    if (count <= kLeaf) return id;
    int axis = 0;
    (centres.hi - centres.lo).maxCoeff(&axis);
    const auto begin = items_.begin() + first, middle = begin + count / 2, end = begin + count;
    std::nth_element(begin, middle, end, [&](int a, int b) {
      return boxes_[a].lo[axis] + boxes_[a].hi[axis] < boxes_[b].lo[axis] + boxes_[b].hi[axis];
    });
    const int left = build(first, count / 2);
    const int right = build(first + count / 2, count - count / 2);
    nodes_[id].left = left, nodes_[id].right = right;
    return id;
  }

  const std::vector<Box>& boxes_;
  std::vector<int> items_;
  std::vector<Node> nodes_;
};

}  // namespace

std::optional<Crossing> find_crossing(const std::vector<Vector3d>& points, const std::vector<std::array<int, 3>>& triangles) {
  const std::vector<Box> boxes = triangle_boxes(points, triangles);
  const BoxTree tree(boxes);
  for (int s = 0; s < static_cast<int>(triangles.size()); ++s) {
    std::optional<Crossing> found;
    tree.visit_overlaps(boxes[s], [&](int t) {
      if (!found && t > s) found = crossing_of(points, triangles, s, t);
    });
    if (found) return found;
  }
  return std::nullopt;
}

std::optional<Crossing> find_crossing_by_sweep(const std::vector<Vector3d>& points,
                                               const std::vector<std::array<int, 3>>& triangles) {
  const int n = static_cast<int>(triangles.size());
  const std::vector<Box> boxes = triangle_boxes(points, triangles);
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return boxes[a].lo.x() < boxes[b].lo.x(); });
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n && boxes[order[b]].lo.x() <= boxes[order[a]].hi.x(); ++b) {
      const int s = order[a], t = order[b];
      if (!boxes[s].overlaps(boxes[t])) continue;
      if (auto c = crossing_of(points, triangles, s, t)) return c;
    }
  return std::nullopt;
}

}  // namespace semimesh::farfield
