// Points of a surface sampled once on a grid over its parameter box. Unguided projections start
// their Newton solves from the grid's local minima of the distance to the query point, which is
// both cheaper and more robust than a global extremum search per query.
#pragma once

#include "semimesh/cad/types.hpp"

#include <array>
#include <functional>
#include <vector>

namespace semimesh::occ {

struct GridSeed {
  cad::Vec2 uv;
  double distance = 0.0;  ///< |S(uv) - x|
};

class SampleGrid {
 public:
  /// `nu` x `nv` nodes (each >= 2) spanning `box`, ends included.
  SampleGrid(const std::array<cad::Interval, 2>& box, int nu, int nv,
             const std::function<cad::Vec3(const cad::Vec2&)>& point);

  /// The nodes where |S - x| is no larger than at any of their (up to 8) neighbours, nearest
  /// first, at most `count` of them.
  std::vector<GridSeed> local_minima(const cad::Vec3& x, int count) const;

  /// The longest cell diagonal in space: a local minimum further than this beyond a distance
  /// already found is unlikely to lead to a closer foot.
  double cell_reach() const { return cell_reach_; }

 private:
  cad::Vec2 uv_of(int i, int j) const;

  std::array<cad::Interval, 2> box_;
  int nu_, nv_;
  std::vector<cad::Vec3> points_;  // [nu_ * nv_], node (i, j) at i * nv_ + j
  double cell_reach_ = 0.0;
};

}  // namespace semimesh::occ
