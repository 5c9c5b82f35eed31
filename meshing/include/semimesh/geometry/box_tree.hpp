// A bounding-box tree over triangles (of a far-field boundary, of a body mesh): each node's box
// holds its items', split at the median of the items' centres along the longest side, leaves of at
// most kLeaf items. Used by the far field's crossing search and interior points and the near
// field's crowding test.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <numeric>
#include <vector>

namespace semimesh::geometry {

struct Box {
  Eigen::Vector3d lo, hi;
  bool overlaps(const Box& o) const { return !((o.lo.array() > hi.array()).any() || (lo.array() > o.hi.array()).any()); }
  /// Squared distance from x to the box (0 inside it).
  double squared_distance(const Eigen::Vector3d& x) const {
    return (lo - x).cwiseMax(x - hi).cwiseMax(0.0).squaredNorm();
  }
};

/// [triangles] each triangle's bounding box.
inline std::vector<Box> triangle_boxes(const std::vector<Eigen::Vector3d>& points,
                                       const std::vector<std::array<int, 3>>& triangles) {
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

class BoxTree {
 public:
  /// `boxes` must outlive the tree.
  explicit BoxTree(const std::vector<Box>& boxes) : boxes_(boxes), items_(boxes.size()) {
    std::iota(items_.begin(), items_.end(), 0);
    if (!items_.empty()) build(0, static_cast<int>(items_.size()));
  }

  /// Depth first through the nodes whose box `enter(box)` accepts; `found(item)` on each item of
  /// an accepted leaf whose own box `enter` accepts; stops as soon as `found` returns true.
  /// Returns whether it stopped.
  template <class Enter, class Found>
  bool visit(Enter&& enter, Found&& found) const {
    if (nodes_.empty()) return false;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      if (!enter(node.box)) continue;
      if (node.left < 0) {
        for (int i = node.first; i < node.first + node.count; ++i)
          if (enter(boxes_[items_[i]]) && found(items_[i])) return true;
        continue;
      }
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
    return false;
  }

  /// f(item) for every item whose box overlaps `query`.
  template <class F>
  void visit_overlaps(const Box& query, F&& f) const {
    visit([&](const Box& box) { return box.overlaps(query); },
          [&](int item) {
            f(item);
            return false;
          });
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

}  // namespace semimesh::geometry
