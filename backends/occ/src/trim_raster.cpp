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

std::array<int, 2> TrimRaster::sub_cell_of(const cad::Vec2& uv, const std::array<int, 2>& c) const {
  const double fu = ((uv.x() - box_[0].lo) / cell_.x() - c[0]) * m_, fv = ((uv.y() - box_[1].lo) / cell_.y() - c[1]) * m_;
  return {std::clamp(static_cast<int>(std::floor(fu)), 0, m_ - 1), std::clamp(static_cast<int>(std::floor(fv)), 0, m_ - 1)};
}

bool TrimRaster::refine(int m, const std::vector<std::vector<cad::Vec2>>& loops, int margin,
                        const std::function<bool(const cad::Vec2&)>& exact) {
  if (m < 2 || (m & (m - 1)) != 0 || margin < 1 || margin > m)
    throw std::invalid_argument("TrimRaster::refine: m a power of 2 >= 2 and 1 <= margin <= m needed");
  int shift = 0;  // m = 2^shift: sub-cell coordinates split into cell and offset by shifts and masks
  while ((1 << shift) < m) ++shift;
  const long mask = m - 1;
  m_ = m;
  block_.assign(cells_.size(), -1);
  sub_cells_.clear();
  int blocks = 0;
  for (std::size_t c = 0; c < cells_.size(); ++c)
    if (cells_[c] == kNear) block_[c] = blocks++;
  sub_cells_.assign(static_cast<std::size_t>(blocks) * m * m, kUnknown);
  const auto give_up = [&] {
    m_ = 0;
    block_.clear();
    sub_cells_.clear();
    return false;
  };
  // Sub-cells in global coordinates over the whole box: (i m + a, j m + b), N x N of them.
  const long N = static_cast<long>(n_) * m;
  const auto sub = [&](long I, long J) -> Cell* {  // null in a cell that is not refined
    const int b = block_[static_cast<std::size_t>((I >> shift) + n_ * (J >> shift))];
    return b < 0 ? nullptr : &sub_cells_[(static_cast<std::size_t>(b) << (2 * shift)) + (I & mask) + ((J & mask) << shift)];
  };
  for (const std::vector<cad::Vec2>& loop : loops) {
    long last_I = -1, last_J = -1;
    for (const cad::Vec2& uv : loop) {
      // The sample's cell as mark_loop finds it (nearest when outside the box), then its sub-cell.
      const std::array<int, 2> c{std::clamp(static_cast<int>(std::floor((uv.x() - box_[0].lo) / cell_.x())), 0, n_ - 1),
                                 std::clamp(static_cast<int>(std::floor((uv.y() - box_[1].lo) / cell_.y())), 0, n_ - 1)};
      const std::array<int, 2> s = sub_cell_of(uv, c);
      const long I0 = static_cast<long>(c[0]) * m + s[0], J0 = static_cast<long>(c[1]) * m + s[1];
      if (I0 == last_I && J0 == last_J) continue;  // consecutive samples often share a sub-cell
      last_I = I0, last_J = J0;
      for (long J = std::max(0L, J0 - margin); J <= std::min(N - 1, J0 + margin); ++J)
        for (long I = std::max(0L, I0 - margin); I <= std::min(N - 1, I0 + margin); ++I) {
          Cell* cell = sub(I, J);
          if (!cell) return give_up();  // a loop this close to a classified cell: that cell was wrong
          *cell = kNear;
        }
    }
  }
  std::vector<long> region, stack;
  for (long c = 0; c < static_cast<long>(cells_.size()); ++c)
    for (long ab = 0; block_[static_cast<std::size_t>(c)] >= 0 && ab < static_cast<long>(m) * m; ++ab) {
      const long I0 = (c % n_) * m + ab % m, J0 = (c / n_) * m + ab / m;
      Cell* first = sub(I0, J0);
      if (*first != kUnknown) continue;
      // Flood the region through unknown sub-cells, noting the classes of the cells it touches.
      bool touches_inside = false, touches_outside = false;
      region.assign(1, I0 + N * J0);
      stack.assign(1, I0 + N * J0);
      *first = kNear;  // provisionally, as visited
      while (!stack.empty()) {
        const long g = stack.back();
        stack.pop_back();
        const long I = g % N, J = g / N;
        for (const auto& [dI, dJ] : {std::pair{-1L, 0L}, std::pair{1L, 0L}, std::pair{0L, -1L}, std::pair{0L, 1L}}) {
          const long In = I + dI, Jn = J + dJ;
          if (In < 0 || Jn < 0 || In >= N || Jn >= N) continue;
          Cell* next = sub(In, Jn);
          if (!next) {
            const Cell whole = cells_[static_cast<std::size_t>((In >> shift) + n_ * (Jn >> shift))];
            touches_inside = touches_inside || whole == kInside;
            touches_outside = touches_outside || whole == kOutside;
          } else if (*next == kUnknown) {
            *next = kNear;
            region.push_back(In + N * Jn);
            stack.push_back(In + N * Jn);
          }
        }
      }
      if (touches_inside && touches_outside) return give_up();
      Cell kind;
      if (touches_inside || touches_outside) {
        kind = touches_inside ? kInside : kOutside;
      } else {
        const cad::Vec2 centre(box_[0].lo + (I0 + 0.5) * cell_.x() / m, box_[1].lo + (J0 + 0.5) * cell_.y() / m);
        kind = exact(centre) ? kInside : kOutside;
      }
      for (const long g : region) *sub(g % N, g / N) = kind;
    }
  return true;
}

std::optional<bool> TrimRaster::lookup(const cad::Vec2& uv) const {
  const auto c = cell_of(uv);
  if (!c) return std::nullopt;
  const std::size_t index = static_cast<std::size_t>((*c)[0] + n_ * (*c)[1]);
  Cell cell = cells_[index];
  if (cell == kNear && m_ > 0) {
    const std::array<int, 2> s = sub_cell_of(uv, *c);
    cell = sub_cells_[static_cast<std::size_t>(block_[index]) * m_ * m_ + s[0] + m_ * s[1]];
  }
  if (cell == kInside) return true;
  if (cell == kOutside) return false;
  return std::nullopt;
}

std::array<int, 3> TrimRaster::census() const {
  std::array<int, 3> count{0, 0, 0};
  for (Cell c : cells_) ++count[c == kNear ? 0 : c == kInside ? 1 : 2];
  return count;
}

std::array<int, 3> TrimRaster::sub_census() const {
  std::array<int, 3> count{0, 0, 0};
  for (Cell c : sub_cells_) ++count[c == kNear ? 0 : c == kInside ? 1 : 2];
  return count;
}

}  // namespace semimesh::occ
