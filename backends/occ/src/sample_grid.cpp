#include "sample_grid.hpp"

#include <algorithm>
#include <cmath>

namespace semimesh::occ {

SampleGrid::SampleGrid(const std::array<cad::Interval, 2>& box, int nu, int nv,
                       const std::function<cad::Vec3(const cad::Vec2&)>& point)
    : box_(box), nu_(std::max(nu, 2)), nv_(std::max(nv, 2)) {
  points_.reserve(static_cast<std::size_t>(nu_) * nv_);
  for (int i = 0; i < nu_; ++i)
    for (int j = 0; j < nv_; ++j) points_.push_back(point(uv_of(i, j)));
  for (int i = 0; i + 1 < nu_; ++i)
    for (int j = 0; j + 1 < nv_; ++j) {
      const cad::Vec3& p00 = points_[i * nv_ + j];
      const cad::Vec3& p01 = points_[i * nv_ + j + 1];
      const cad::Vec3& p10 = points_[(i + 1) * nv_ + j];
      const cad::Vec3& p11 = points_[(i + 1) * nv_ + j + 1];
      cell_reach_ = std::max({cell_reach_, (p11 - p00).norm(), (p10 - p01).norm()});
    }
}

cad::Vec2 SampleGrid::uv_of(int i, int j) const {
  return {box_[0].lo + box_[0].length() * i / (nu_ - 1), box_[1].lo + box_[1].length() * j / (nv_ - 1)};
}

std::vector<GridSeed> SampleGrid::local_minima(const cad::Vec3& x, int count) const {
  std::vector<double> d2(points_.size());  // [nu_ * nv_]
  for (std::size_t k = 0; k < points_.size(); ++k) d2[k] = (points_[k] - x).squaredNorm();
  std::vector<GridSeed> minima;
  for (int i = 0; i < nu_; ++i)
    for (int j = 0; j < nv_; ++j) {
      const double here = d2[i * nv_ + j];
      bool lowest = true;
      for (int di = -1; di <= 1 && lowest; ++di)
        for (int dj = -1; dj <= 1 && lowest; ++dj) {
          const int a = i + di, b = j + dj;
          if (a >= 0 && a < nu_ && b >= 0 && b < nv_) lowest = d2[a * nv_ + b] >= here;
        }
      if (lowest) minima.push_back({uv_of(i, j), std::sqrt(here)});
    }
  const auto nearer = [](const GridSeed& a, const GridSeed& b) { return a.distance < b.distance; };
  const std::size_t kept = std::min<std::size_t>(minima.size(), static_cast<std::size_t>(std::max(count, 0)));
  std::partial_sort(minima.begin(), minima.begin() + kept, minima.end(), nearer);
  minima.resize(kept);
  return minima;
}

}  // namespace semimesh::occ
