#include "semimesh/farfield/detail/interior_points.hpp"

#include "semimesh/farfield/detail/fixed_offset.hpp"

#include "semimesh/geometry/box_tree.hpp"
#include "semimesh/ho/closest_point.hpp"
#include "semimesh/surface/size_field.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <future>
#include <limits>
#include <stdexcept>
#include <system_error>

namespace semimesh::farfield {
namespace {

using Eigen::Vector3d;
using geometry::Box;
using geometry::BoxTree;

// A leaf cell's side over the spacing at its centre: one point per cell of side s gives Delaunay
// edges of about 1.2 s on a lattice; the octree's sides halve, so a leaf lies between half and all
// of this.
constexpr double kLeafSide = 1.0;
// How far a point may move from its cell's centre, per side, in each direction.
constexpr double kJitter = 0.2;
// No point nearer the boundary than this times the spacing: the boundary's vertices are there.
constexpr double kClearance = 0.6;

enum class RayHit { Miss, Cross, Graze };

// Whether the ray x + t d, t > 0, crosses triangle abc (Moller-Trumbore); Graze when it passes
// within round-off of the triangle's edges or plane, where the count could go either way.
RayHit ray_hits_triangle(const Vector3d& x, const Vector3d& d, const Vector3d& a, const Vector3d& b,
                         const Vector3d& c) {
  constexpr double kEdge = 1e-9;
  const Vector3d e1 = b - a, e2 = c - a;
  const Vector3d p = d.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) <= 1e-12 * e1.norm() * e2.norm()) {
    const Vector3d n = e1.cross(e2);
    return std::abs(n.dot(x - a)) <= kEdge * n.norm() * (e1.norm() + e2.norm()) ? RayHit::Graze : RayHit::Miss;
  }
  const Vector3d s = x - a;
  const double u = s.dot(p) / det;
  if (u < -kEdge || u > 1 + kEdge) return RayHit::Miss;
  const Vector3d q = s.cross(e1);
  const double v = d.dot(q) / det;
  if (v < -kEdge || u + v > 1 + kEdge) return RayHit::Miss;
  const double t = e2.dot(q) / det;
  if (t < 0) return RayHit::Miss;
  if (u < kEdge || v < kEdge || u + v > 1 - kEdge) return RayHit::Graze;
  return RayHit::Cross;
}

// Whether the ray x + t d (t >= 0) meets the box; inverse: 1 / d component-wise.
bool ray_meets_box(const Vector3d& x, const Vector3d& inverse, const Box& box) {
  double near = 0.0, far = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    double t0 = (box.lo[k] - x[k]) * inverse[k], t1 = (box.hi[k] - x[k]) * inverse[k];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
    if (near > far) return false;
  }
  return true;
}

// The boundary's triangles in a box tree, and the three questions the filling asks of them.
class Boundary {
 public:
  Boundary(const std::vector<Vector3d>& points, const std::vector<std::array<int, 3>>& triangles)
      : points_(points), triangles_(triangles), boxes_(geometry::triangle_boxes(points, triangles)), tree_(boxes_) {}

  bool has_triangle_in(const Box& box) const {
    return tree_.visit([&](const Box& b) { return b.overlaps(box); }, [](int) { return true; });
  }

  bool has_triangle_within(const Vector3d& x, double distance) const {
    const double r2 = distance * distance;
    return tree_.visit(
        [&](const Box& b) { return b.squared_distance(x) <= r2; },
        [&](int t) {
          return (x - ho::closest_point_on_triangle(x, corner(t, 0), corner(t, 1), corner(t, 2)).point).squaredNorm() <=
                 r2;
        });
  }

  // Odd crossings along a ray; a ray grazing an edge is replaced by the next of a few fixed
  // directions (none along a box axis or a lattice diagonal). After all of them graze, outside.
  bool inside(const Vector3d& x) const {
    static const Vector3d kDirections[] = {Vector3d(0.5431, 0.6183, 0.5683), Vector3d(-0.3712, 0.8321, -0.4121),
                                           Vector3d(0.7213, -0.2917, 0.6281), Vector3d(-0.2113, -0.5237, 0.8252)};
    for (const Vector3d& direction : kDirections) {
      const Vector3d d = direction.normalized();
      const Vector3d inverse = d.cwiseInverse();
      int crossings = 0;
      const bool grazed = tree_.visit([&](const Box& b) { return ray_meets_box(x, inverse, b); },
                                      [&](int t) {
                                        const RayHit hit =
                                            ray_hits_triangle(x, d, corner(t, 0), corner(t, 1), corner(t, 2));
                                        crossings += hit == RayHit::Cross;
                                        return hit == RayHit::Graze;
                                      });
      if (!grazed) return crossings % 2 == 1;
    }
    return false;
  }

 private:
  const Vector3d& corner(int t, int k) const { return points_[triangles_[t][k]]; }

  const std::vector<Vector3d>& points_;
  const std::vector<std::array<int, 3>>& triangles_;
  std::vector<Box> boxes_;
  BoxTree tree_;
};

enum class Side { Unknown, Inside, Outside };

struct Cell {
  std::array<std::uint32_t, 3> place;  // integer corner at its depth
  int depth = 0;
  Side side = Side::Unknown;  // known for a cell no boundary triangle comes near
};

class Filling {
 public:
  // The spacing field is built on another thread while this one builds the boundary's tree.
  Filling(const std::vector<Vector3d>& points, const std::vector<std::array<int, 3>>& triangles,
          const InteriorPointParams& params)
      : Filling(points, triangles, params, spacing_field_beside(points, triangles, params)) {}

  // Cells in depth-first order down to where there are enough of them to share among threads.
  std::vector<Cell> top_cells() const {
    std::vector<Cell> cells{Cell{{0, 0, 0}, 0, Side::Unknown}};
    while (cells.size() < 512 && cells.front().depth < 6) {
      std::vector<Side> sides(cells.size());
#pragma omp parallel for schedule(dynamic, 1)
      for (std::size_t i = 0; i < cells.size(); ++i)
        sides[i] = classify(cells[i], size_(corner_of(cells[i]) + Vector3d::Constant(0.5 * side_at(cells[i].depth))));
      std::vector<Cell> next;
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if (sides[i] == Side::Outside) continue;
        for (int child = 0; child < 8; ++child) next.push_back(child_of(cells[i], child, sides[i]));
      }
      if (next.empty()) break;
      cells = std::move(next);
    }
    return cells;
  }

  void fill(const Cell& cell, std::vector<Vector3d>& out) const {
    const double side = side_at(cell.depth);
    const Vector3d centre = corner_of(cell) + Vector3d::Constant(0.5 * side);
    const double h = size_(centre);
    const Side known = classify(cell, h);
    if (known == Side::Outside) return;
    if (side <= kLeafSide * h) {
      const Vector3d x = centre + kJitter * side * fixed_offset(key_of(cell));
      if (known == Side::Unknown && (boundary_.has_triangle_within(x, kClearance * h) || !boundary_.inside(x))) return;
      out.push_back(x);
      return;
    }
    for (int child = 0; child < 8; ++child) fill(child_of(cell, child, known), out);
  }

 private:
  Filling(const std::vector<Vector3d>& points, const std::vector<std::array<int, 3>>& triangles,
          const InteriorPointParams& params, std::future<surface::SizeField> spacing)
      : boundary_(points, triangles), size_(spacing.get()), slope_(params.growth - 1.0) {
    Box box{points.front(), points.front()};
    for (const Vector3d& p : points) box.lo = box.lo.cwiseMin(p), box.hi = box.hi.cwiseMax(p);
    root_side_ = (box.hi - box.lo).maxCoeff() * (1.0 + 1e-6);
    root_lo_ = box.lo - Vector3d::Constant(1e-7 * root_side_);
  }

  static std::future<surface::SizeField> spacing_field_beside(const std::vector<Vector3d>& points,
                                                              const std::vector<std::array<int, 3>>& triangles,
                                                              const InteriorPointParams& params) {
    const auto build = [&points, &triangles, params] { return spacing_field(points, triangles, params); };
    try {
      return std::async(std::launch::async, build);
    } catch (const std::system_error&) {  // no thread to be had: built when asked, on this one
      return std::async(std::launch::deferred, build);
    }
  }

  static surface::SizeField spacing_field(const std::vector<Vector3d>& points,
                                          const std::vector<std::array<int, 3>>& triangles,
                                          const InteriorPointParams& params) {
    std::vector<double> length(points.size(), 0.0);
    std::vector<int> count(points.size(), 0);
    for (const auto& t : triangles)
      for (int k = 0; k < 3; ++k) {
        const double l = (points[t[k]] - points[t[(k + 1) % 3]]).norm();
        for (int end : {t[k], t[(k + 1) % 3]}) length[end] += l, count[end] += 1;
      }
    surface::SizeParams sizes;
    sizes.max_size = params.max_spacing;
    sizes.min_size = params.max_spacing;
    sizes.gradation = params.growth;
    sizes.curvature_segments = 0.0;
    sizes.le_curves.clear();
    sizes.te_curves.clear();
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (count[i] == 0) continue;
      const double h = length[i] / count[i];
      sizes.min_size = std::min(sizes.min_size, h);
      sizes.point_sources.push_back({points[i], h});
    }
    return surface::SizeField(sizes);
  }

  double side_at(int depth) const { return std::ldexp(root_side_, -depth); }
  Vector3d corner_of(const Cell& cell) const {
    return root_lo_ + side_at(cell.depth) * Vector3d(cell.place[0], cell.place[1], cell.place[2]);
  }
  static std::uint64_t key_of(const Cell& cell) {
    return (static_cast<std::uint64_t>(cell.depth) << 58) ^ (static_cast<std::uint64_t>(cell.place[0]) << 38) ^
           (static_cast<std::uint64_t>(cell.place[1]) << 19) ^ cell.place[2];
  }
  static Cell child_of(const Cell& cell, int child, Side side) {
    Cell c{cell.place, cell.depth + 1, side};
    for (int k = 0; k < 3; ++k) c.place[k] = 2 * c.place[k] + ((child >> k) & 1);
    return c;
  }

  // A cell's side of the boundary when no triangle comes within the clearance of any point it may
  // hold, h the spacing at its centre (a cell inside it has its centre within side of this one's:
  // its spacing is at most h + slope_ side); else Unknown.
  Side classify(const Cell& cell, double h) const {
    const double side = side_at(cell.depth);
    const Vector3d lo = corner_of(cell);
    const double reach = kClearance * (h + slope_ * side);
    if (boundary_.has_triangle_in(Box{lo - Vector3d::Constant(reach), lo + Vector3d::Constant(side + reach)}))
      return Side::Unknown;
    if (cell.side != Side::Unknown) return cell.side;
    return boundary_.inside(lo + Vector3d::Constant(0.5 * side)) ? Side::Inside : Side::Outside;
  }

  Boundary boundary_;
  surface::SizeField size_;
  double slope_;
  double root_side_ = 0.0;
  Vector3d root_lo_;
};

}  // namespace

std::vector<Vector3d> interior_points(const std::vector<Vector3d>& boundary,
                                      const std::vector<std::array<int, 3>>& triangles,
                                      const InteriorPointParams& params) {
  if (!(params.growth >= 1.0) || !(params.max_spacing > 0.0) || !std::isfinite(params.max_spacing))
    throw std::invalid_argument("interior_points: growth must be >= 1 and max_spacing > 0");
  if (triangles.empty()) return {};
  const Filling filling(boundary, triangles, params);
  const std::vector<Cell> cells = filling.top_cells();
  std::vector<std::vector<Vector3d>> found(cells.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t i = 0; i < cells.size(); ++i) filling.fill(cells[i], found[i]);
  std::vector<Vector3d> points;
  for (const auto& f : found) points.insert(points.end(), f.begin(), f.end());
  return points;
}

bool inside_boundary(const std::vector<Vector3d>& boundary, const std::vector<std::array<int, 3>>& triangles,
                     const Vector3d& x) {
  return Boundary(boundary, triangles).inside(x);
}

}  // namespace semimesh::farfield
