#include "trim_raster.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace semimesh::occ {

TrimRaster::TrimRaster(const std::array<cad::Interval, 2>& box, int n)
    : box_(box), n_(n), cell_(box[0].length() / n, box[1].length() / n), cells_(static_cast<std::size_t>(n) * n, kUnknown) {
  if (n < 2 || !(cell_.x() > 0.0) || !(cell_.y() > 0.0))
    throw std::invalid_argument("TrimRaster: a box of positive size and n >= 2 needed");
}

std::optional<std::array<int, 2>> TrimRaster::cell_of(const cad::Vec2& uv) const {
  const double fu = (uv.x() - box_[0].lo) / cell_.x(), fv = (uv.y() - box_[1].lo) / cell_.y();
  if (!(fu >= 0.0 && fv >= 0.0 && fu <= n_ && fv <= n_)) return std::nullopt;  // also NaN
  return std::array<int, 2>{std::min(static_cast<int>(fu), n_ - 1), std::min(static_cast<int>(fv), n_ - 1)};
}

void TrimRaster::mark_loop(const std::vector<cad::Vec2>& samples, int margin) {
  for (const cad::Vec2& uv : samples) {
    // A sample outside the box (a pcurve may stray a little): its nearest cell.
    const int ci = std::clamp(static_cast<int>(std::floor((uv.x() - box_[0].lo) / cell_.x())), 0, n_ - 1);
    const int cj = std::clamp(static_cast<int>(std::floor((uv.y() - box_[1].lo) / cell_.y())), 0, n_ - 1);
    for (int j = std::max(0, cj - margin); j <= std::min(n_ - 1, cj + margin); ++j)
      for (int i = std::max(0, ci - margin); i <= std::min(n_ - 1, ci + margin); ++i) cells_[i + n_ * j] = kNear;
  }
}

void TrimRaster::classify(const std::function<bool(const cad::Vec2&)>& exact) {
  std::vector<int> stack;
  for (int start = 0; start < n_ * n_; ++start) {
    if (cells_[start] != kUnknown) continue;
    const cad::Vec2 centre(box_[0].lo + (start % n_ + 0.5) * cell_.x(), box_[1].lo + (start / n_ + 0.5) * cell_.y());
    const Cell kind = exact(centre) ? kInside : kOutside;
    cells_[start] = kind;
    stack.assign(1, start);
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      const int i = c % n_, j = c / n_;
      for (const int next : {i > 0 ? c - 1 : -1, i < n_ - 1 ? c + 1 : -1, j > 0 ? c - n_ : -1, j < n_ - 1 ? c + n_ : -1})
        if (next >= 0 && cells_[next] == kUnknown) {
          cells_[next] = kind;
          stack.push_back(next);
        }
    }
  }
}

std::optional<bool> TrimRaster::lookup(const cad::Vec2& uv) const {
  const auto c = cell_of(uv);
  if (!c) return std::nullopt;
  const Cell cell = cells_[(*c)[0] + n_ * (*c)[1]];
  if (cell == kInside) return true;
  if (cell == kOutside) return false;
  return std::nullopt;
}

std::array<int, 3> TrimRaster::census() const {
  std::array<int, 3> count{0, 0, 0};
  for (Cell c : cells_) ++count[c == kNear ? 0 : c == kInside ? 1 : 2];
  return count;
}

}  // namespace semimesh::occ
