#include "trim_raster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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
  m_ = m;
  shift_ = 0;  // m = 2^shift_: sub-cell coordinates split into cell and offset by shifts and masks
  while ((1 << shift_) < m) ++shift_;
  sub_margin_ = margin;
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
    const long k = sub_index(I, J);
    return k < 0 ? nullptr : &sub_cells_[static_cast<std::size_t>(k)];
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
            const Cell whole = cells_[static_cast<std::size_t>((In >> shift_) + n_ * (Jn >> shift_))];
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

long TrimRaster::sub_index(long I, long J) const {
  const long mask = m_ - 1;
  const int b = block_[static_cast<std::size_t>((I >> shift_) + n_ * (J >> shift_))];
  return b < 0 ? -1 : (static_cast<long>(b) << (2 * shift_)) + (I & mask) + ((J & mask) << shift_);
}

TrimRaster::Cell TrimRaster::sub_class(long I, long J) const {
  const long k = sub_index(I, J);
  return k >= 0 ? sub_cells_[static_cast<std::size_t>(k)] : cells_[static_cast<std::size_t>((I >> shift_) + n_ * (J >> shift_))];
}

namespace {

// (a, b)'s axis-aligned box grown by r (per axis), as the global sub-cells it touches, clipped to [0, N).
std::array<long, 4> touched(const cad::Vec2& a, const cad::Vec2& b, const cad::Vec2& r, long N) {
  const auto lo = [&](double x, double grow) { return std::clamp(static_cast<long>(std::floor(x - grow)), 0L, N - 1); };
  const auto hi = [&](double x, double grow) { return std::clamp(static_cast<long>(std::floor(x + grow)), 0L, N - 1); };
  return {lo(std::min(a.x(), b.x()), r.x()), hi(std::max(a.x(), b.x()), r.x()), lo(std::min(a.y(), b.y()), r.y()),
          hi(std::max(a.y(), b.y()), r.y())};
}

double distance_to_segment(const cad::Vec2& p, const cad::Vec2& a, const cad::Vec2& b) {
  const cad::Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

}  // namespace

double TrimRaster::uv_distance(const cad::Vec2& p, std::uint32_t segment) const {
  return distance_to_segment(p.cwiseProduct(sub_), segments_[segment][0].cwiseProduct(sub_),
                             segments_[segment][1].cwiseProduct(sub_));
}

bool TrimRaster::keep_polylines(const std::vector<std::vector<cad::Vec2>>& loops,
                                const std::vector<std::vector<cad::Vec2>>& midpoints, const Tolerances& tolerances) {
  if (m_ == 0 || loops.size() != midpoints.size()) return false;
  const cad::Vec2 sub = cell_ / m_;
  const auto scaled = [&](const cad::Vec2& uv) {
    return cad::Vec2((uv.x() - box_[0].lo) / sub.x(), (uv.y() - box_[1].lo) / sub.y());
  };
  std::vector<std::array<cad::Vec2, 2>> segments;
  std::vector<double> segment_deviation;  // twice the midpoint's distance from the chord
  std::vector<cad::Vec2> ends;
  double deviation = 0.0;  // the largest, in the parameters as the tolerances
  for (std::size_t l = 0; l < loops.size(); ++l) {
    if (loops[l].size() < 2 || midpoints[l].size() + 1 != loops[l].size()) return false;
    for (std::size_t k = 0; k + 1 < loops[l].size(); ++k) {
      segment_deviation.push_back(2.0 * distance_to_segment(midpoints[l][k], loops[l][k], loops[l][k + 1]));
      deviation = std::max(deviation, segment_deviation.back());
      segments.push_back({scaled(loops[l][k]), scaled(loops[l][k + 1])});
    }
    ends.push_back(scaled(loops[l].front()));
    ends.push_back(scaled(loops[l].back()));
  }
  const double band = tolerances.boundary + deviation;
  // An open end blocks the rays within the band or within its gap to the nearest other end
  // (edges meet within their vertices' tolerance, not exactly): a ray through a gap would miss a crossing.
  std::vector<double> reach(ends.size());
  double widest_gap = 0.0;
  for (std::size_t e = 0; e < ends.size(); ++e) {
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < ends.size(); ++f)
      if (f != e) gap = std::min(gap, (ends[f] - ends[e]).cwiseProduct(sub).norm());
    reach[e] = std::max(band, gap);
    widest_gap = std::max(widest_gap, gap);
  }
  // A classified sub-cell is more than refine()'s margin - 1/2 sub-cells from every polyline along
  // both parameters (its samples at most half a sub-cell apart): with the band narrower, the
  // polygons and the loops agree there, so a ray's count ends on a known class.
  const double finer = std::min(sub.x(), sub.y());
  const double widest = std::max(band, tolerances.vertex);
  if (!(widest < (sub_margin_ - 0.5) * finer) || !(widest_gap < finer)) return false;
  // Two passes over the items each sub-cell lists: count, then fill.
  const long N = static_cast<long>(n_) * m_;
  std::vector<std::uint32_t> first(sub_cells_.size() + 1, 0), items;
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    if (pass == 1) items.resize(first.back());
    const auto list = [&](const cad::Vec2& a, const cad::Vec2& b, std::size_t id, double grown) {
      const auto [I0, I1, J0, J1] = touched(a, b, cad::Vec2(grown / sub.x(), grown / sub.y()), N);
      for (long J = J0; J <= J1; ++J)
        for (long I = I0; I <= I1; ++I) {
          const long k = sub_index(I, J);
          if (k < 0) continue;  // a classified cell: no query there needs the polylines
          if (pass == 0)
            ++first[static_cast<std::size_t>(k) + 1];
          else
            items[next[static_cast<std::size_t>(k)]++] = static_cast<std::uint32_t>(id);
        }
    };
    for (std::size_t s = 0; s < segments.size(); ++s) list(segments[s][0], segments[s][1], s, band);
    for (std::size_t e = 0; e < ends.size(); ++e)
      list(ends[e], ends[e], segments.size() + e, std::max(reach[e], tolerances.vertex));
    if (pass == 0)
      for (std::size_t k = 0; k < sub_cells_.size(); ++k) first[k + 1] += first[k];
  }
  segments_ = std::move(segments);
  deviation_ = std::move(segment_deviation);
  open_ends_ = std::move(ends);
  end_reach_ = std::move(reach);
  first_ = std::move(first);
  items_ = std::move(items);
  sub_ = sub;
  band_ = band;
  vertex_ = tolerances.vertex;
  on_ = kOnFraction * tolerances.on;
  return true;
}

// The global sub-cell at `along` on the ray's axis and `across` on the other.
std::array<long, 2> TrimRaster::ray_cell(int axis, long along, long across) const {
  return axis == 0 ? std::array<long, 2>{along, across} : std::array<long, 2>{across, along};
}

int TrimRaster::shortest_ray(const cad::Vec2& p) const {
  const long N = static_cast<long>(n_) * m_;
  const std::array<long, 2> start{static_cast<long>(std::floor(p.x())), static_cast<long>(std::floor(p.y()))};
  for (long step = 0;; ++step) {
    bool inside_box = false;
    for (int r = 0; r < 4; ++r) {
      const int axis = r / 2;
      const long I = start[axis] + (r % 2 ? -step : step);
      if (I < 0 || I >= N) continue;
      inside_box = true;
      const auto [u, v] = ray_cell(axis, I, start[1 - axis]);
      const Cell kind = sub_class(u, v);
      if (kind == kInside || kind == kOutside) return r;
    }
    if (!inside_box) return -1;
  }
}

std::optional<bool> TrimRaster::along_ray(const cad::Vec2& p, int axis, int direction) const {
  const long N = static_cast<long>(n_) * m_;
  const int t = 1 - axis;
  const double c = p[t];  // the ray: points of coordinate t equal to c
  const long across = static_cast<long>(std::floor(c));
  bool odd = false;
  for (long I = static_cast<long>(std::floor(p[axis])); I >= 0 && I < N; I += direction) {
    const auto [u, v] = ray_cell(axis, I, across);
    const Cell kind = sub_class(u, v);
    if (kind == kInside || kind == kOutside) return (kind == kInside) != odd;
    // A near sub-cell: the crossings within its part of the ray, [I, I + 1) cut at p.
    const double lo = direction > 0 ? std::max(static_cast<double>(I), p[axis]) : static_cast<double>(I);
    const double hi = direction > 0 ? static_cast<double>(I + 1) : std::min(static_cast<double>(I + 1), p[axis]);
    const auto k = static_cast<std::size_t>(sub_index(u, v));
    for (std::uint32_t i = first_[k]; i < first_[k + 1]; ++i) {
      const std::uint32_t item = items_[i];
      if (item >= segments_.size()) {  // an open end this close to the ray: the loop may leak there
        const std::size_t e = item - segments_.size();
        const cad::Vec2& end = open_ends_[e];
        const double r = end_reach_[e];  // in the parameters; the ray's coordinates in sub-cells
        if (std::abs(end[t] - c) * sub_[t] <= r && end[axis] >= lo - r / sub_[axis] && end[axis] <= hi + r / sub_[axis])
          return std::nullopt;
        continue;
      }
      const cad::Vec2& a = segments_[item][0];
      const cad::Vec2& b = segments_[item][1];
      if ((a[t] > c) == (b[t] > c)) continue;  // half-open across the ray: a shared sample counts once
      const double x = a[axis] + (c - a[t]) * (b[axis] - a[axis]) / (b[t] - a[t]);
      if (x >= lo && x < hi) odd = !odd;
    }
  }
  return std::nullopt;  // left the box before a classified sub-cell
}

std::optional<bool> TrimRaster::by_polylines(const cad::Vec2& p, bool only_on) const {
  const auto k = static_cast<std::size_t>(sub_index(static_cast<long>(std::floor(p.x())), static_cast<long>(std::floor(p.y()))));
  bool near = false;  // the curve may be on either side of p
  for (std::uint32_t i = first_[k]; i < first_[k + 1]; ++i) {
    if (items_[i] >= segments_.size()) {  // a vertex: within its tolerance the classifier may say on
      near = near || (p - open_ends_[items_[i] - segments_.size()]).cwiseProduct(sub_).norm() <= vertex_;
      continue;
    }
    const double d = uv_distance(p, items_[i]);
    // The curve passes within the segment's deviation of each of its points: p is on the loop.
    if (d + deviation_[items_[i]] <= on_) return true;
    near = near || d <= band_;
  }
  if (near || only_on) return std::nullopt;
  // The shortest of the four rays along u and v (a ray along a loop would cross the whole band's
  // length), found by walking them side by side; when it passes an open end, the others in turn
  // (rare: any ray that ends on a class gives the same answer).
  const int first = shortest_ray(p);
  if (first < 0) return std::nullopt;
  for (int k = 0; k < 4; ++k) {
    const int r = (first + k) % 4;
    if (const std::optional<bool> inside = along_ray(p, r / 2, r % 2 ? -1 : 1)) return inside;
  }
  return std::nullopt;
}

std::optional<bool> TrimRaster::lookup(const cad::Vec2& uv) const {
  const auto c = cell_of(uv);
  if (!c) return std::nullopt;
  const std::size_t index = static_cast<std::size_t>((*c)[0] + n_ * (*c)[1]);
  Cell cell = cells_[index];
  if (cell == kNear && m_ > 0) {
    const std::array<int, 2> s = sub_cell_of(uv, *c);
    cell = sub_cells_[static_cast<std::size_t>(block_[index]) * m_ * m_ + s[0] + m_ * s[1]];
    if (cell == kNear && band_ > 0.0) {
      // p in sub-cell units, inside the sub-cell found (clamped as sub_cell_of clamps).
      const double X = static_cast<double>((*c)[0]) * m_ + s[0], Y = static_cast<double>((*c)[1]) * m_ + s[1];
      const cad::Vec2 p(std::clamp((uv.x() - box_[0].lo) / (cell_.x() / m_), X, std::nextafter(X + 1.0, X)),
                        std::clamp((uv.y() - box_[1].lo) / (cell_.y() / m_), Y, std::nextafter(Y + 1.0, Y)));
      // On a side of the box, off the loops, OCC's classifier may answer either way (its rays
      // run along a straight edge's extension there: a point beyond a trailing edge's corner, on
      // the line of its base, is found inside): the polylines answer only that it is on a loop.
      const bool on_a_side = uv.x() <= box_[0].lo || uv.x() >= box_[0].hi || uv.y() <= box_[1].lo || uv.y() >= box_[1].hi;
      return by_polylines(p, on_a_side);
    }
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
