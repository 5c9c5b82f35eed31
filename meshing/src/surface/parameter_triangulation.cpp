#include "parameter_triangulation.hpp"

#include "boundary_nodes.hpp"
#include "semimesh/surface/error.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <deque>
#include <numeric>
#include <optional>
#include <utility>

namespace semimesh::surface::detail {
namespace {

struct VertexInfo {
  int node = -1;
};
struct FaceInfo {
  int nesting = -1;  // number of loops crossed from the unbounded region
  bool in_domain() const { return nesting % 2 == 1; }
};

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel>;
using Fb = CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using Point = Cdt::Point;
using FaceHandle = Cdt::Face_handle;
using VertexHandle = Cdt::Vertex_handle;

// An inserted point must keep this fraction of the local size from the vertices around it, so
// refinement ends and leaves no tiny edges.
constexpr double kMinSpacing = 0.5;
constexpr std::size_t kMaxNodes = 20'000'000;

// Beyond this ratio between the mean lengths of S_u and S_v a Delaunay triangulation in raw (u, v)
// joins nodes far apart in space (on a revolved tip, u an angle on a radius of ~70 and v a length,
// it joined nodes a third of the way round), so the triangulation runs in (u, v) scaled by them.
constexpr double kMaxParameterStretch = 3.0;

// The triangulation's coordinates: v times `v_scale` (1 unless the face stretches its parameters).
// Only the Delaunay criterion sees them; nodes keep their (u, v).
double v_scale_of(const cad::Surface& face) {
  const auto box = face.bounds();
  constexpr int n = 8;
  double su = 0.0, sv = 0.0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const Vec2 uv(box[0].lo + box[0].length() * i / n, box[1].lo + box[1].length() * j / n);
      if (!face.contains(uv)) continue;
      const cad::SurfaceDerivatives d = face.derivatives(uv);
      su += d.du.norm();
      sv += d.dv.norm();
    }
  if (!(su > 0.0 && sv > 0.0)) return 1.0;
  const double ratio = sv / su;
  return ratio > kMaxParameterStretch || ratio < 1.0 / kMaxParameterStretch ? ratio : 1.0;
}

Vec2 to_uv(const Point& p, double v_scale) { return Vec2(p.x(), p.y() / v_scale); }
Point to_point(const Vec2& uv, double v_scale) { return Point(uv.x(), uv.y() * v_scale); }

// Nesting level by flood fill: faces reached from the infinite face without crossing a loop have
// level 0, each loop crossed adds one; the face is the odd levels (outer loop + holes).
void mark_domain(Cdt& cdt) {
  std::deque<std::pair<FaceHandle, int>> seeds{{cdt.infinite_face(), 0}};
  while (!seeds.empty()) {
    auto [start, level] = seeds.front();
    seeds.pop_front();
    if (start->info().nesting != -1) continue;
    std::deque<FaceHandle> queue{start};
    start->info().nesting = level;
    while (!queue.empty()) {
      FaceHandle f = queue.front();
      queue.pop_front();
      for (int i = 0; i < 3; ++i) {
        FaceHandle n = f->neighbor(i);
        if (n->info().nesting != -1) continue;
        if (cdt.is_constrained(Cdt::Edge(f, i))) {
          seeds.emplace_back(n, level + 1);
        } else {
          n->info().nesting = level;
          queue.push_back(n);
        }
      }
    }
  }
}

class Refiner {
 public:
  Refiner(const cad::Surface& face, const SizeField& size, double split_factor, double grid_step, double v_scale,
          SurfaceMesh& mesh, Cdt& cdt)
      : face_(face), size_(size), split_factor_(split_factor), grid_step_(grid_step), v_scale_(v_scale), mesh_(mesh),
        cdt_(cdt),
        periods_{face.period(0), face.period(1)},
        periodic_(periods_[0] || periods_[1]) {}

  void run() {
    for (FaceHandle f : cdt_.finite_face_handles())
      if (f->info().in_domain()) queue_.push_back(key(f));
    while (!queue_.empty()) {
      const auto entry = queue_.front();
      queue_.pop_front();
      FaceHandle f;
      if (!cdt_.is_face(entry[0], entry[1], entry[2], f)) continue;  // replaced since queued
      refine(f);
    }
  }

 private:
  using Key = std::array<VertexHandle, 3>;
  Vec2 uv_of(const Point& p) const { return to_uv(p, v_scale_); }
  static Key key(FaceHandle f) { return {f->vertex(0), f->vertex(1), f->vertex(2)}; }

  const Vec3& point(VertexHandle v) const { return mesh_.points[v->info().node]; }

  void refine(FaceHandle f) {
    const Vec3 &a = point(f->vertex(0)), &b = point(f->vertex(1)), &c = point(f->vertex(2));
    const double h = size_((a + b + c) / 3.0);
    if (const std::optional<Vec2> split = wrapping_edge_midpoint(f)) {
      if (try_insert(snap_to_grid(*split, grid_step_), f, 0.0)) return;
    }
    double longest = 0.0;
    for (int i = 0; i < 3; ++i) longest = std::max(longest, edge_length(f->vertex(i), f->vertex(Cdt::cw(i))));
    if (longest <= split_factor_ * h) return;
    for (const std::optional<Vec2>& candidate : {metric_circumcentre(f), longest_free_edge_midpoint(f), centroid(f)})
      if (candidate && try_insert(snap_to_grid(*candidate, grid_step_), f, h)) return;
  }

  // The chord, or on a periodic face the path through the edge's (u, v) midpoint: an edge joining
  // the two sides of a seam cut can have a short chord while it wraps all the way round.
  double edge_length(VertexHandle p, VertexHandle q) const {
    if (!periodic_) return (point(q) - point(p)).norm();
    const Vec3 mid = face_.point(0.5 * (uv_of(p->point()) + uv_of(q->point())));
    return (mid - point(p)).norm() + (point(q) - mid).norm();
  }

  // The (u, v) midpoint of a free edge spanning more than a third of a period: on a periodic face
  // such an edge goes a long way round even where its chord is short (near a pole, or joining two
  // images of one seam point), so it is split whatever its length in space.
  // In a fan at a pole the limit is a twelfth of a period: a wide fan triangle whose other two
  // corners lie at unequal distances from the pole folds over.
  std::optional<Vec2> wrapping_edge_midpoint(FaceHandle f) const {
    for (int d = 0; d < 2; ++d) {
      if (!periods_[d]) continue;
      bool fan = false;
      for (int i = 0; i < 3; ++i) fan = fan || at_pole(uv_of(f->vertex(i)->point()), d);
      for (int i = 0; i < 3; ++i) {
        if (cdt_.is_constrained(Cdt::Edge(f, i))) continue;
        const Vec2 p = uv_of(f->vertex(Cdt::cw(i))->point()), q = uv_of(f->vertex(Cdt::ccw(i))->point());
        if (std::abs(q[d] - p[d]) > *periods_[d] / (fan ? 12.0 : 3.0) && !at_pole(p, d) && !at_pole(q, d))
          return 0.5 * (p + q);
      }
    }
    return std::nullopt;
  }

  // Whether S does not move along parameter direction d at uv (a pole: an edge from it may span
  // any angle).
  bool at_pole(const Vec2& uv, int d) const {
    const cad::SurfaceDerivatives s = face_.derivatives(uv);
    const Vec3& along = d == 0 ? s.du : s.dv;
    const Vec3& across = d == 0 ? s.dv : s.du;
    return along.norm() <= 1e-9 * across.norm();
  }

  // Circumcentre in the tangent-plane metric at the centroid: where the 3D circumcentre would be.
  std::optional<Vec2> metric_circumcentre(FaceHandle f) const {
    const Vec2 p0 = uv_of(f->vertex(0)->point()), p1 = uv_of(f->vertex(1)->point()), p2 = uv_of(f->vertex(2)->point());
    const Vec2 mid = (p0 + p1 + p2) / 3.0;
    const cad::SurfaceDerivatives d = face_.derivatives(mid);
    // A maps parameter steps to tangent-plane coordinates with |A du| = |S_u du + S_v dv|.
    const Vec3 e1 = d.du.normalized();
    const Vec3 e2 = (d.dv - d.dv.dot(e1) * e1).normalized();
    Eigen::Matrix2d A;
    A << e1.dot(d.du), e1.dot(d.dv), 0.0, e2.dot(d.dv);
    if (!(std::abs(A.determinant()) > 0.0)) return std::nullopt;
    const Vec2 q1 = A * (p1 - p0), q2 = A * (p2 - p0);
    const double det = 2.0 * (q1.x() * q2.y() - q1.y() * q2.x());
    if (!(std::abs(det) > 0.0)) return std::nullopt;
    const Vec2 centre((q2.y() * q1.squaredNorm() - q1.y() * q2.squaredNorm()) / det,
                      (q1.x() * q2.squaredNorm() - q2.x() * q1.squaredNorm()) / det);
    return p0 + A.inverse() * centre;
  }

  std::optional<Vec2> longest_free_edge_midpoint(FaceHandle f) const {
    int best = -1;
    double best_length = 0.0;
    for (int i = 0; i < 3; ++i) {
      if (cdt_.is_constrained(Cdt::Edge(f, i))) continue;
      const double l = (point(f->vertex(Cdt::cw(i))) - point(f->vertex(Cdt::ccw(i)))).norm();
      if (l > best_length) { best_length = l; best = i; }
    }
    if (best < 0) return std::nullopt;
    return 0.5 * (uv_of(f->vertex(Cdt::cw(best))->point()) + uv_of(f->vertex(Cdt::ccw(best))->point()));
  }

  std::optional<Vec2> centroid(FaceHandle f) const {
    return (uv_of(f->vertex(0)->point()) + uv_of(f->vertex(1)->point()) + uv_of(f->vertex(2)->point())) / 3.0;
  }

  bool try_insert(const Vec2& uv, FaceHandle hint, double h) {
    Cdt::Locate_type type;
    int index;
    const Point p = to_point(uv, v_scale_);
    FaceHandle at = cdt_.locate(p, type, index, hint);
    if (type == Cdt::VERTEX || type == Cdt::OUTSIDE_CONVEX_HULL || type == Cdt::OUTSIDE_AFFINE_HULL) return false;
    if (cdt_.is_infinite(at) || !at->info().in_domain()) return false;
    if (type == Cdt::EDGE && cdt_.is_constrained(Cdt::Edge(at, index))) return false;  // would split a curve segment
    const Vec3 x = face_.point(uv);
    if (too_close(at, x, kMinSpacing * h)) return false;
    if (mesh_.points.size() >= kMaxNodes) throw SurfaceMeshError("surface refinement exceeded the node limit");

    mesh_.uv.push_back(uv);
    mesh_.points.push_back(x);
    mesh_.origin.push_back(NodeOrigin{});
    const int nesting = at->info().nesting;  // `at` itself is replaced by the insertion
    VertexHandle v = cdt_.insert(p, at);
    v->info().node = mesh_.num_nodes() - 1;
    auto faces = cdt_.incident_faces(v), done = faces;
    do {
      faces->info().nesting = nesting;  // the new star lies in the same region
      queue_.push_back(key(faces));
    } while (++faces != done);
    return true;
  }

  // Whether a vertex of `at` or a neighbour of one is nearer to x than `spacing` in 3D. The
  // (u, v) Delaunay triangles can be far from 3D Delaunay where the surface stretches its
  // parameters, so the nearest vertex is not always one of the face containing x.
  bool too_close(FaceHandle at, const Vec3& x, double spacing) const {
    for (int i = 0; i < 3; ++i) {
      auto around = cdt_.incident_vertices(at->vertex(i)), done = around;
      do {
        if (!cdt_.is_infinite(around) && (point(around) - x).norm() < spacing) return true;
      } while (++around != done);
    }
    return false;
  }

  const cad::Surface& face_;
  const SizeField& size_;
  double split_factor_;
  double grid_step_;
  double v_scale_;
  SurfaceMesh& mesh_;
  Cdt& cdt_;
  std::array<std::optional<double>, 2> periods_;
  bool periodic_;
  std::deque<Key> queue_;
};

}  // namespace

void triangulate_parameter_space(const cad::Model& model, int surface, const std::vector<std::vector<int>>& loops,
                                 const SizeField& size, double split_factor, double grid_step, SurfaceMesh& mesh) {
  // Cocircular ties (common on evenly spaced boundaries) are broken by the insertion order and
  // the exact predicates: the boundary goes in snapped to the grid, in (u, v) order, constraints
  // sorted, so two models agreeing to ~1e-13 listing their loops any way give the same result.
  std::vector<Vec2> snapped;  // [nodes]
  for (const Vec2& uv : mesh.uv) snapped.push_back(snap_to_grid(uv, grid_step));
  auto lower = [&](int a, int b) {
    return std::make_pair(snapped[a].x(), snapped[a].y()) < std::make_pair(snapped[b].x(), snapped[b].y());
  };
  std::vector<int> by_position(mesh.num_nodes());
  std::iota(by_position.begin(), by_position.end(), 0);
  std::sort(by_position.begin(), by_position.end(), lower);
  const double v_scale = v_scale_of(model.surface(surface));
  Cdt cdt;
  std::vector<VertexHandle> handles(mesh.num_nodes());
  for (int node : by_position) {
    handles[node] = cdt.insert(to_point(snapped[node], v_scale));
    if (handles[node]->info().node != -1)
      throw SurfaceMeshError(cad::surface_label(model, surface) + ": boundary nodes " + std::to_string(handles[node]->info().node) +
                             " and " + std::to_string(node) + " coincide in parameter space (degenerate edge or pole?)");
    handles[node]->info().node = node;
  }
  std::vector<std::pair<int, int>> segments;  // [segments] (lower node, upper node) in (u, v) order
  for (const auto& loop : loops)
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      segments.push_back(lower(a, b) ? std::make_pair(a, b) : std::make_pair(b, a));
    }
  std::sort(segments.begin(), segments.end(), [&](const auto& s, const auto& t) {
    if (s.first != t.first) return lower(s.first, t.first);
    return lower(s.second, t.second);
  });
  for (const auto& [a, b] : segments) cdt.insert_constraint(handles[a], handles[b]);
  if (static_cast<int>(cdt.number_of_vertices()) != mesh.num_nodes())
    throw SurfaceMeshError(cad::surface_label(model, surface) +
                           ": boundary loops intersect in parameter space (curves crossing, or too coarse for the trim)");
  mark_domain(cdt);
  Refiner(model.surface(surface), size, split_factor, grid_step, v_scale, mesh, cdt).run();

  for (FaceHandle f : cdt.finite_face_handles())
    if (f->info().in_domain())
      mesh.triangles.push_back({f->vertex(0)->info().node, f->vertex(1)->info().node, f->vertex(2)->info().node});
  if (mesh.triangles.empty()) throw SurfaceMeshError(cad::surface_label(model, surface) + ": the boundary loops enclose no area");
}

}  // namespace semimesh::surface::detail
