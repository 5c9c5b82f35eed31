#include "semimesh/surface/shell_size_limit.hpp"

#include "semimesh/cad/labels.hpp"
#include "semimesh/surface/error.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>

namespace semimesh::surface {
namespace {

using cad::Vec2;

constexpr int kMarchSteps = 16;
// The limit's bisection stops at this precision relative to its bracket's top (the limit kept is
// the bracket's bottom, a size that passes: conservative), or after kBisections halvings. A size
// source needs no more: 20 halvings (7e-8 after the scan's 1.15) cost a third of the size field
// on NekMesh's wing, most of it in OCC's point-in-face tests along the marches.
constexpr double kLimitPrecision = 1e-3;
constexpr int kBisections = 20;
// The gap is not monotone in h over long arcs (an arc round the whole nose comes back out), so the
// first failure is found by growing h from a fraction of the radius by this factor, then bisected.
constexpr double kScanStart = 0.05;
constexpr double kScanGrowth = 1.15;
// The longest edges of a triangulation of target size h are about this times h (measured 0.031 to
// 0.040 at a target of 0.03 near a leading edge), so a size source is the limit divided by it.
constexpr double kEdgeOvershoot = 1.5;
// Measured (bench/robustness, order 5, NACA 0006 and 2412 noses of radius 0.004 and 0.016): where the
// body turns fast, surface sizes up to 0.75 x the thickness always gave valid prisms, sizes of one
// thickness or more sometimes did not; the chord-gap model alone misses that, so a curved place
// (one where the gap limits the size) also gets size <= max(kThinShell x thickness, radius).
constexpr double kThinShell = 0.75;
// The thickness the gap model asks for is where prisms start to fold (measured: 0.0206 folds,
// 0.022 is marginal, 0.025 is sound); the remedy offered keeps this margin.
constexpr double kThicknessMargin = 1.25;

// The ends and the midpoint of an arc on the surface, with the unit normals there.
struct Arc {
  Vec2 a, m, b;
  Vec3 na, nm, nb;
};

// Walks `length` from uv along the surface, starting in tangent direction `dir` and keeping the
// direction tangent (transported by projection); stops at the surface's boundary. The normals come
// from the evaluations the walk makes anyway.
Arc march(const cad::Surface& s, const Vec2& start, Vec3 dir, double length) {
  const auto box = s.bounds();
  // The path and its normals in this thread's buffers: the size field marches ~10^6 times.
  thread_local std::vector<Vec2> path;
  thread_local std::vector<Vec3> normals;
  path.assign(1, start);
  cad::SurfaceDerivatives d = s.derivatives(start);  // at the path's end: the step's Jacobian, the normal
  normals.assign(1, s.normal(d));
  for (int k = 0; k < kMarchSteps; ++k) {
    Eigen::Matrix<double, 3, 2> jacobian;
    jacobian << d.du, d.dv;
    const Vec2 step = (jacobian.transpose() * jacobian).ldlt().solve(jacobian.transpose() * dir * (length / kMarchSteps));
    const Vec2 next = path.back() + step;
    if (!std::isfinite(next.x()) || !std::isfinite(next.y()) || next.x() < box[0].lo || next.x() > box[0].hi ||
        next.y() < box[1].lo || next.y() > box[1].hi || !s.contains(next))
      break;
    path.push_back(next);
    d = s.derivatives(next);
    normals.push_back(s.normal(d));
    dir = (dir - dir.dot(normals.back()) * normals.back()).normalized();
  }
  const std::size_t mid = path.size() / 2;
  return {path.front(), path[mid], path.back(), normals.front(), normals[mid], normals.back()};
}

// Gap of the straight offset chord over the arc's midpoint at thickness 0 (g0, negative on a convex
// arc) and its growth per unit thickness (c): g(delta) = g0 + c delta.
std::pair<double, double> chord_gap(const cad::Surface& s, const Arc& arc) {
  const Vec3 a = s.point(arc.a), b = s.point(arc.b), m = s.point(arc.m);
  return {(0.5 * (a + b) - m).dot(arc.nm), 0.5 * (arc.na + arc.nb).dot(arc.nm)};
}

bool gap_ok(const cad::Surface& s, const Vec2& uv, const Vec3& dir, double h, double thickness, double fraction) {
  for (double sign : {1.0, -1.0}) {
    const auto [g0, c] = chord_gap(s, march(s, uv, sign * dir, h));
    if (g0 + c * thickness < fraction * thickness) return false;
  }
  return true;
}

// Thickness that keeps the gap for edges of length h at uv: g0 + c delta >= q delta.
double thickness_needed(const cad::Surface& s, const Vec2& uv, const Vec3& dir, double h, double fraction) {
  double needed = 0.0;
  for (double sign : {1.0, -1.0}) {
    const auto [g0, c] = chord_gap(s, march(s, uv, sign * dir, h));
    if (g0 >= 0.0) continue;
    if (c <= fraction) return std::numeric_limits<double>::infinity();
    needed = std::max(needed, -g0 / (c - fraction));
  }
  return needed;
}

std::string label(const Vec3& p) { return fmt::format("({:.4g}, {:.4g}, {:.4g})", p.x(), p.y(), p.z()); }

// The name of the CAD curve of `surface` nearest to p, when one is within `within`.
std::string nearby_curve(const cad::Model& model, int surface, const Vec3& p, double within) {
  std::string best;
  double best_distance = within;
  for (int c = 0; c < model.num_curves(); ++c) {
    const auto& uses = model.surfaces_of_curve(c);
    if (std::none_of(uses.begin(), uses.end(), [&](const cad::SurfaceUse& u) { return u.surface == surface; })) continue;
    const double d = (model.curve(c).project(p).point - p).norm();
    if (d <= best_distance) best_distance = d, best = cad::curve_label(model, c);
  }
  return best;
}

}  // namespace

namespace {

// The limits along one row of samples (u = its i-th value) of one surface.
std::vector<ShellSizeLimit> row_limits(const cad::Surface& s, int i, const ShellSizing& shell, double max_size,
                                       double probe_size) {
  const double delta = shell.thickness, q = shell.min_gap_fraction;
  const int n = shell.samples;
  const auto box = s.bounds();
  std::vector<ShellSizeLimit> limits;
  for (int j = 0; j <= n; ++j) {
    const Vec2 uv(box[0].lo + box[0].length() * i / n, box[1].lo + box[1].length() * j / n);
    if (!s.contains(uv)) continue;
    const cad::PrincipalCurvatures k = s.curvatures(uv);
    if (!(k.k_max > 0.0)) continue;  // concave or flat: the outer chord passes outside the arc
    const double radius = 1.0 / k.k_max;
    // On the osculating circle (R + delta) cos(h / 2R) >= R + q delta holds for every h: no limit.
    const double circle = (radius + q * delta) / (radius + delta);
    if (2.0 * radius * std::acos(circle) >= max_size) continue;
    double lo = 0.0, hi = std::min(max_size, kScanStart * radius);  // ok at lo
    while (hi < max_size && gap_ok(s, uv, k.dir_max, hi, delta, q)) lo = hi, hi = std::min(max_size, hi * kScanGrowth);
    if (hi >= max_size && gap_ok(s, uv, k.dir_max, hi, delta, q)) continue;
    for (int b = 0; b < kBisections && hi - lo > kLimitPrecision * hi; ++b) {
      const double mid = 0.5 * (lo + hi);
      (gap_ok(s, uv, k.dir_max, mid, delta, q) ? lo : hi) = mid;
    }
    limits.push_back({s.point(uv), s.id(), radius, lo, thickness_needed(s, uv, k.dir_max, probe_size, q)});
  }
  return limits;
}

}  // namespace

std::vector<ShellSizeLimit> shell_size_limits(const cad::Model& model, const ShellSizing& shell, double max_size,
                                              double probe_size, const ProgressCallback& progress) {
  if (!(shell.thickness > 0.0)) throw SurfaceMeshError("shell size limit: the thickness must be > 0");
  const int rows_per_surface = shell.samples + 1;
  std::vector<const cad::Surface*> curved;  // planar faces limit nothing
  for (int id : shell.body_surfaces)
    if (!model.surface(id).is_planar()) curved.push_back(&model.surface(id));
  // Rows in parallel (the CAD queries dominate), each writing its own slot: the limits come out in
  // (surface, row, column) order whatever the thread count.
  const long rows = static_cast<long>(curved.size()) * rows_per_surface;
  std::vector<std::vector<ShellSizeLimit>> per_row(static_cast<std::size_t>(rows));
  ProgressCounter counter(progress, static_cast<std::size_t>(rows), "shell limits");
  std::mutex mutex, report_mutex;
  long failed_at = rows;
  std::exception_ptr error;
#pragma omp parallel for schedule(dynamic, 1) if (model.thread_safe())
  for (long r = 0; r < rows; ++r) {
    try {
      per_row[static_cast<std::size_t>(r)] =
          row_limits(*curved[static_cast<std::size_t>(r / rows_per_surface)], static_cast<int>(r % rows_per_surface),
                     shell, max_size, probe_size);
      counter.add();
      // Whichever thread ends a row reports (one at a time): a row is long, and thread 0 alone may
      // end only a few of them.
      const std::lock_guard<std::mutex> lock(report_mutex);
      counter.report_if_due();
    } catch (...) {  // may not leave the parallel region: the lowest row's is rethrown, as in order
      const std::lock_guard<std::mutex> lock(mutex);
      if (r < failed_at) failed_at = r, error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
  counter.finish();
  std::vector<ShellSizeLimit> limits;
  for (const auto& row : per_row) limits.insert(limits.end(), row.begin(), row.end());
  return limits;
}

namespace {

/// The target size of the point source at one limit.
double source_size(const ShellSizeLimit& l, const ShellSizing& shell) {
  return std::min(l.size / kEdgeOvershoot, std::max(kThinShell * shell.thickness, l.radius));
}

}  // namespace

double smallest_shell_size(const cad::Model& model, const ShellSizing& shell, double max_size,
                           const ProgressCallback& progress) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const ShellSizeLimit& l :
       shell_size_limits(model, shell, max_size * kEdgeOvershoot, max_size * kEdgeOvershoot, progress))
    smallest = std::min(smallest, source_size(l, shell));
  return smallest;
}

std::vector<PointSource> shell_size_sources(const cad::Model& model, const ShellSizing& shell, const SizeParams& sizing,
                                            const ProgressCallback& progress) {
  const std::vector<ShellSizeLimit> limits =
      shell_size_limits(model, shell, sizing.max_size * kEdgeOvershoot, sizing.min_size * kEdgeOvershoot, progress);
  std::vector<PointSource> sources;
  std::vector<std::pair<double, const ShellSizeLimit*>> forbidden;  // (size, place) below min_size
  double thickest = 0.0;
  for (const ShellSizeLimit& l : limits) {
    const double size = source_size(l, shell);
    sources.push_back({l.point, size});
    if (size >= sizing.min_size) continue;
    forbidden.push_back({size, &l});
    const double thin_shell = l.radius >= sizing.min_size ? 0.0 : sizing.min_size / kThinShell;
    thickest = std::max({thickest, kThicknessMargin * l.thickness_for_probe, thin_shell});
  }
  if (forbidden.empty()) return sources;
  // Name the place nearest the centre of those within 1% of the smallest size: along a uniform
  // leading edge that is mid-span, not a corner where three curves meet.
  const double needed = std::min_element(forbidden.begin(), forbidden.end())->first;
  std::vector<const ShellSizeLimit*> worst_places;
  Vec3 centre = Vec3::Zero();
  for (const auto& [size, place] : forbidden)
    if (size <= 1.01 * needed) worst_places.push_back(place), centre += place->point;
  centre /= static_cast<double>(worst_places.size());
  const ShellSizeLimit* worst = *std::min_element(worst_places.begin(), worst_places.end(), [&](auto* a, auto* b) {
    return (a->point - centre).norm() < (b->point - centre).norm();
  });
  const std::string curve = nearby_curve(model, worst->surface, worst->point, sizing.min_size);
  const std::string thickness_remedy =
      std::isfinite(thickest) ? fmt::format(" or nearfield.thickness >= {:.3g}", thickest) : std::string();
  throw SurfaceMeshError(fmt::format(
      "the near-field shell cannot stand on {}{} at {}: curvature radius {:.3g}, shell thickness {:.3g} "
      "needs a surface size <= {:.3g} there (the shell's straight outer face over a curved body face folds on coarser edges), "
      "but sizing.min_size = {:.3g} forbids it ({} such place(s)); set sizing.min_size <= {:.3g}{}",
      cad::surface_label(model, worst->surface), curve.empty() ? "" : " near " + curve,
      label(worst->point), worst->radius, shell.thickness, needed, sizing.min_size,
      forbidden.size(), needed * 0.99, thickness_remedy));
}

}  // namespace semimesh::surface
