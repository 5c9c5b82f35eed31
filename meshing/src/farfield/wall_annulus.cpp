#include "semimesh/farfield/detail/wall_annulus.hpp"

#include "semimesh/farfield/far_field.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <string>

namespace semimesh::farfield {
namespace {

using Vec2 = Eigen::Vector2d;

struct VertexInfo {
  int index = -1;  // into Annulus::points; -1 for a vertex CGAL made itself (crossing constraints)
};
struct FaceInfo {
  int nesting = -1;  // constraints crossed from the infinite face: 1 inside the region
};
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel>;
using Fb = CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

struct Segment {
  Vec2 a, b;
  double length;
};

double distance_to_segment(const Vec2& x, const Segment& s) {
  const Vec2 d = s.b - s.a;
  const double t = std::clamp((x - s.a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (x - (s.a + t * d)).norm();
}

// Crossing-number test; points on the boundary may go either way (callers keep away from it).
bool inside_polygon(const Vec2& x, const std::vector<Vec2>& loop) {
  bool inside = false;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const Vec2& p = loop[i];
    const Vec2& q = loop[j];
    if ((p.y() > x.y()) != (q.y() > x.y()) && x.x() < (q.x() - p.x()) * (x.y() - p.y()) / (q.y() - p.y()) + p.x())
      inside = !inside;
  }
  return inside;
}

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

bool segments_intersect(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  const double d1 = cross(p1 - p0, q0 - p0), d2 = cross(p1 - p0, q1 - p0);
  const double d3 = cross(q1 - q0, p0 - q0), d4 = cross(q1 - q0, p1 - q0);
  return ((d1 > 0) != (d2 > 0) || d1 == 0 || d2 == 0) && ((d3 > 0) != (d4 > 0) || d3 == 0 || d4 == 0) &&
         std::max(std::min(p0.x(), p1.x()), std::min(q0.x(), q1.x())) <=
             std::min(std::max(p0.x(), p1.x()), std::max(q0.x(), q1.x())) &&
         std::max(std::min(p0.y(), p1.y()), std::min(q0.y(), q1.y())) <=
             std::min(std::max(p0.y(), p1.y()), std::max(q0.y(), q1.y()));
}

class Region {
 public:
  Region(const std::vector<Vec2>& outer, const std::vector<Vec2>& hole, double max_size, double growth)
      : outer_(outer), hole_(hole), max_size_(max_size), slope_(growth - 1.0) {
    for (const auto* loop : {&outer_, &hole_})
      for (std::size_t i = 0; i < loop->size(); ++i) {
        const Vec2& a = (*loop)[i];
        const Vec2& b = (*loop)[(i + 1) % loop->size()];
        segments_.push_back({a, b, (b - a).norm()});
      }
  }

  bool contains(const Vec2& x) const { return inside_polygon(x, outer_) && !inside_polygon(x, hole_); }

  // Target edge length and the distance to the nearest loop segment.
  std::pair<double, double> size_and_clearance(const Vec2& x) const {
    double size = max_size_, clearance = std::numeric_limits<double>::max();
    for (const Segment& s : segments_) {
      const double d = distance_to_segment(x, s);
      clearance = std::min(clearance, d);
      size = std::min(size, s.length + slope_ * d);
    }
    return {size, clearance};
  }

  // Far enough from the loops that no sliver forms against a boundary segment.
  bool accepts(const Vec2& x, double clearance_factor) const {
    if (!contains(x)) return false;
    const auto [size, clearance] = size_and_clearance(x);
    return clearance >= clearance_factor * size;
  }

  const std::vector<Vec2>& outer() const { return outer_; }
  const std::vector<Vec2>& hole() const { return hole_; }

 private:
  const std::vector<Vec2>& outer_;
  const std::vector<Vec2>& hole_;
  double max_size_;
  double slope_;
  std::vector<Segment> segments_;
};

void check_loops(const std::vector<Vec2>& outer, const std::vector<Vec2>& hole) {
  if (outer.size() < 3 || hole.size() < 3)
    throw FarFieldError("wall region: the box's bottom loop has " + std::to_string(outer.size()) +
                        " points and the footprint " + std::to_string(hole.size()) + "; each needs at least 3");
  for (const Vec2& p : hole)
    if (!inside_polygon(p, outer))
      throw FarFieldError("wall region: footprint point (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) +
                          ") lies outside the box's bottom loop");
  for (std::size_t i = 0; i < outer.size(); ++i)
    for (std::size_t j = 0; j < hole.size(); ++j)
      if (segments_intersect(outer[i], outer[(i + 1) % outer.size()], hole[j], hole[(j + 1) % hole.size()]))
        throw FarFieldError("wall region: footprint segment " + std::to_string(j) + " crosses the box's bottom loop");
}

// Candidate interior points: centres of the leaves of a quadtree refined until a leaf is no larger
// than about the local target size, kept when inside the region and clear of the loops.
std::vector<Vec2> quadtree_points(const Region& region) {
  Vec2 lo = region.outer().front(), hi = lo;
  for (const Vec2& p : region.outer()) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  struct Cell {
    Vec2 centre;
    double side;
  };
  std::vector<Cell> stack{{0.5 * (lo + hi), (hi - lo).maxCoeff()}};
  std::vector<Vec2> points;
  while (!stack.empty()) {
    const Cell cell = stack.back();
    stack.pop_back();
    const auto [size, clearance] = region.size_and_clearance(cell.centre);
    (void)clearance;
    if (cell.side > 1.2 * size) {
      const double q = 0.25 * cell.side;
      for (const Vec2& offset : {Vec2(-q, -q), Vec2(q, -q), Vec2(-q, q), Vec2(q, q)})
        stack.push_back({cell.centre + offset, 0.5 * cell.side});
    } else if (region.accepts(cell.centre, 0.6)) {
      points.push_back(cell.centre);
    }
  }
  return points;
}

// Constrained Delaunay triangulation of the loops (points [0, num_outer) and [num_outer,
// num_outer + num_hole)) plus interior points; returns the triangles of the region, counter-clockwise.
std::vector<std::array<int, 3>> triangulate(const std::vector<Vec2>& points, int num_outer, int num_hole) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    handles[i] = cdt.insert(Cdt::Point(points[i].x(), points[i].y()));
    if (handles[i]->info().index != -1)
      throw FarFieldError("wall region: point " + std::to_string(i) + " coincides with point " +
                          std::to_string(handles[i]->info().index) + " (duplicate loop points?)");
    handles[i]->info().index = static_cast<int>(i);
  }
  for (int loop_start : {0, num_outer}) {
    const int n = loop_start == 0 ? num_outer : num_hole;
    for (int i = 0; i < n; ++i) cdt.insert_constraint(handles[loop_start + i], handles[loop_start + (i + 1) % n]);
  }
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (v->info().index == -1)
      throw FarFieldError("wall region: the box's bottom loop or the footprint crosses itself near (" +
                          std::to_string(v->point().x()) + ", " + std::to_string(v->point().y()) + ")");

  // Nesting level by flood fill from the infinite face, one level per constraint crossed.
  std::deque<std::pair<Cdt::Face_handle, int>> seeds{{cdt.infinite_face(), 0}};
  while (!seeds.empty()) {
    const auto [seed, level] = seeds.front();
    seeds.pop_front();
    if (seed->info().nesting != -1) continue;
    std::vector<Cdt::Face_handle> queue{seed};
    seed->info().nesting = level;
    while (!queue.empty()) {
      const Cdt::Face_handle f = queue.back();
      queue.pop_back();
      for (int i = 0; i < 3; ++i) {
        const Cdt::Face_handle n = f->neighbor(i);
        if (n->info().nesting != -1) continue;
        if (cdt.is_constrained({f, i})) {
          seeds.push_back({n, level + 1});
        } else {
          n->info().nesting = level;
          queue.push_back(n);
        }
      }
    }
  }
  std::vector<std::array<int, 3>> triangles;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info().nesting == 1)
      triangles.push_back({f->vertex(0)->info().index, f->vertex(1)->info().index, f->vertex(2)->info().index});
  return triangles;
}

}  // namespace

Annulus triangulate_annulus(const std::vector<Vec2>& outer, const std::vector<Vec2>& hole, double max_size,
                            double growth) {
  check_loops(outer, hole);
  const Region region(outer, hole, max_size, growth);
  Annulus result;
  result.points = outer;
  result.points.insert(result.points.end(), hole.begin(), hole.end());
  const int num_boundary = static_cast<int>(result.points.size());
  const std::vector<Vec2> interior = quadtree_points(region);
  result.points.insert(result.points.end(), interior.begin(), interior.end());

  const int num_outer = static_cast<int>(outer.size()), num_hole = static_cast<int>(hole.size());
  result.triangles = triangulate(result.points, num_outer, num_hole);
  // Laplacian smoothing of the interior points, re-triangulating after each pass so the
  // triangulation stays Delaunay; a move that leaves the region or nears a loop is not made.
  constexpr int kSmoothingPasses = 3;
  for (int pass = 0; pass < kSmoothingPasses; ++pass) {
    std::vector<Vec2> sum(result.points.size(), Vec2::Zero());
    std::vector<int> count(result.points.size(), 0);
    for (const auto& t : result.triangles)
      for (int k = 0; k < 3; ++k) {
        // an interior point's edges are each seen from two triangles: every neighbour counts twice
        const int a = t[k], b = t[(k + 1) % 3];
        sum[a] += result.points[b];
        sum[b] += result.points[a];
        ++count[a];
        ++count[b];
      }
    for (std::size_t i = num_boundary; i < result.points.size(); ++i) {
      if (count[i] == 0) continue;
      const Vec2 moved = sum[i] / count[i];
      if (region.accepts(moved, 0.4)) result.points[i] = moved;
    }
    result.triangles = triangulate(result.points, num_outer, num_hole);
  }
  return result;
}

}  // namespace semimesh::farfield
