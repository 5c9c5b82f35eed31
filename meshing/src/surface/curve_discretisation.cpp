#include "semimesh/surface/curve_discretisation.hpp"

#include "semimesh/cad/labels.hpp"

#include "semimesh/surface/error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace semimesh::surface {
namespace {

// Fine samples resolve the size field: no sample interval longer than this fraction of the size.
constexpr double kSampleFraction = 0.25;
constexpr int kInitialSamples = 32;
constexpr int kMaxRefineRounds = 16;


void check_curve_id(const cad::Model& model, int curve) {
  if (curve < 0 || curve >= model.num_curves())
    throw SurfaceMeshError("curve id " + std::to_string(curve) + " is out of range: the model has " +
                           std::to_string(model.num_curves()) + " curves");
}

bool is_closed(const cad::Model& model, int curve) {
  const auto ends = model.curve_vertices(curve);
  return ends[0] == ends[1];
}

/// Parameters at the given arc-length fractions (0 = start, 1 = end, increasing), ends exact.
CurveMesh mesh_from_fractions(const cad::Model& model, int curve, const std::vector<double>& fractions) {
  const cad::Curve& c = model.curve(curve);
  const cad::Interval range = c.bounds();
  const double length = c.length();
  CurveMesh mesh;
  mesh.curve = curve;
  mesh.t.push_back(range.lo);
  for (std::size_t i = 1; i + 1 < fractions.size(); ++i)
    mesh.t.push_back(c.parameter_at_length(mesh.t.back(), (fractions[i] - fractions[i - 1]) * length));
  mesh.t.push_back(range.hi);
  for (double t : mesh.t) mesh.points.push_back(c.point(t));
  const auto ends = model.curve_vertices(curve);
  mesh.points.front() = model.vertex(ends[0]).point;
  mesh.points.back() = model.vertex(ends[1]).point;
  for (std::size_t i = 1; i < mesh.t.size(); ++i)
    if (!(mesh.t[i] > mesh.t[i - 1]))
      throw SurfaceMeshError(cad::curve_label(model, curve) + ": the discretisation is not increasing in the parameter "
                             "(segments too short for the curve's parametrisation)");
  return mesh;
}

/// A pole: one segment over the parameter range, both nodes at its vertex.
CurveMesh pole_mesh(const cad::Model& model, int curve) {
  const cad::Interval range = model.curve(curve).bounds();
  const Vec3 at = model.vertex(model.curve_vertices(curve)[0]).point;
  CurveMesh mesh;
  mesh.curve = curve;
  mesh.t = {range.lo, range.hi};
  mesh.points = {at, at};
  return mesh;
}

// The size integral F = integral of ds / h along a curve, cumulative at fine samples that resolve
// the size field, with the arc length s at the same samples.
struct SizeIntegral {
  std::vector<double> s;  ///< [samples] arc length from the start
  std::vector<double> F;  ///< [samples] integral of ds / h from the start
};

SizeIntegral size_integral(const cad::Curve& c, const SizeField& size) {
  const cad::Interval range = c.bounds();
  // Fine samples (parameter, size), bisected until every interval is short against the size.
  std::vector<double> t(kInitialSamples + 1), h(kInitialSamples + 1);
  for (int i = 0; i <= kInitialSamples; ++i) {
    t[i] = range.lo + range.length() * i / kInitialSamples;
    h[i] = size(c.point(t[i]));
  }
  std::vector<double> ds;  // [samples - 1] arc length of each interval
  for (int round = 0;; ++round) {
    ds.resize(t.size() - 1);
    std::vector<double> nt{t.front()}, nh{h.front()};
    bool refined = false;
    for (std::size_t i = 0; i + 1 < t.size(); ++i) {
      ds[i] = c.arc_length(t[i], t[i + 1]);
      if (round < kMaxRefineRounds && ds[i] > kSampleFraction * std::min(h[i], h[i + 1])) {
        const double mid = 0.5 * (t[i] + t[i + 1]);
        nt.push_back(mid);
        nh.push_back(size(c.point(mid)));
        refined = true;
      }
      nt.push_back(t[i + 1]);
      nh.push_back(h[i + 1]);
    }
    if (!refined) break;
    t.swap(nt);
    h.swap(nh);
  }

  // F = integral of ds / h (trapezoid), cumulative at the samples.
  SizeIntegral out;
  std::vector<double>& F = out.F;
  F.assign(t.size(), 0.0);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) F[i + 1] = F[i] + 0.5 * ds[i] * (1.0 / h[i] + 1.0 / h[i + 1]);
  out.s.assign(t.size(), 0.0);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) out.s[i + 1] = out.s[i] + ds[i];
  return out;
}

// n segments, node i at F = i F_end / n, as an arc-length fraction (linear within a fine interval).
CurveMesh mesh_by_size_integral(const cad::Model& model, int curve, const SizeIntegral& integral, int n) {
  const std::vector<double>& s = integral.s;
  const std::vector<double>& F = integral.F;
  std::vector<double> fractions{0.0};
  std::size_t k = 0;
  for (int i = 1; i < n; ++i) {
    const double target = F.back() * i / n;
    while (k + 2 < F.size() && F[k + 1] < target) ++k;
    const double w = F[k + 1] > F[k] ? (target - F[k]) / (F[k + 1] - F[k]) : 0.0;
    fractions.push_back((s[k] + w * (s[k + 1] - s[k])) / s.back());
  }
  fractions.push_back(1.0);
  return mesh_from_fractions(model, curve, fractions);
}

}  // namespace

CurveMesh discretise_curve(const cad::Model& model, int curve, const SizeField& size, int min_segments) {
  check_curve_id(model, curve);
  if (min_segments < 1) throw SurfaceMeshError("min_segments must be >= 1, got " + std::to_string(min_segments));
  if (model.curve(curve).is_degenerate()) return pole_mesh(model, curve);
  const SizeIntegral integral = size_integral(model.curve(curve), size);
  const int floor_segments = std::max(min_segments, is_closed(model, curve) ? 3 : 1);
  const int n = std::max(floor_segments, static_cast<int>(std::lround(integral.F.back())));
  return mesh_by_size_integral(model, curve, integral, n);
}

CurveMesh discretise_curve_to_count(const cad::Model& model, int curve, const SizeField& size, int segments) {
  check_curve_id(model, curve);
  if (model.curve(curve).is_degenerate()) return pole_mesh(model, curve);
  if (segments < (is_closed(model, curve) ? 3 : 1))
    throw SurfaceMeshError(cad::curve_label(model, curve) + ": segments must be >= " +
                           (is_closed(model, curve) ? "3 on a closed curve" : std::string("1")) + ", got " +
                           std::to_string(segments));
  return mesh_by_size_integral(model, curve, size_integral(model.curve(curve), size), segments);
}

CurveMesh discretise_curve(const cad::Model& model, int curve, const CurveCount& count) {
  check_curve_id(model, curve);
  if (model.curve(curve).is_degenerate()) return pole_mesh(model, curve);
  const int n = count.segments;
  if (n < 1) throw SurfaceMeshError(cad::curve_label(model, curve) + ": segments must be >= 1, got " + std::to_string(n));
  if (is_closed(model, curve) && n < 3)
    throw SurfaceMeshError(cad::curve_label(model, curve) + " is closed: it needs >= 3 segments, got " + std::to_string(n));
  const double q = count.bunching.parameter;
  std::vector<double> fractions(n + 1);
  for (int i = 0; i <= n; ++i) {
    const double xi = static_cast<double>(i) / n;
    switch (count.bunching.law) {
      case Bunching::Law::Uniform: fractions[i] = xi; break;
      case Bunching::Law::Geometric:
        if (!(q > 0.0)) throw SurfaceMeshError(cad::curve_label(model, curve) + ": geometric ratio must be > 0");
        // Segment k has length proportional to q^k: partial geometric sums.
        fractions[i] = std::abs(q - 1.0) < 1e-12 ? xi : (std::pow(q, i) - 1.0) / (std::pow(q, n) - 1.0);
        break;
      case Bunching::Law::Tanh:
        if (!(q > 0.0)) throw SurfaceMeshError(cad::curve_label(model, curve) + ": tanh strength must be > 0");
        fractions[i] = 0.5 * (1.0 + std::tanh(q * (2.0 * xi - 1.0)) / std::tanh(q));
        break;
      case Bunching::Law::Cosine: fractions[i] = 0.5 * (1.0 - std::cos(M_PI * xi)); break;
    }
  }
  fractions.front() = 0.0;
  fractions.back() = 1.0;
  return mesh_from_fractions(model, curve, fractions);
}

CurveMeshes::CurveMeshes(std::vector<CurveMesh> meshes) : meshes_(std::move(meshes)) {
  for (std::size_t i = 0; i < meshes_.size(); ++i)
    if (meshes_[i].curve != static_cast<int>(i))
      throw SurfaceMeshError("CurveMeshes: entry " + std::to_string(i) + " holds the mesh of curve " +
                             std::to_string(meshes_[i].curve) + "; entries must be indexed by curve id");
}

const CurveMesh& CurveMeshes::at(int curve) const {
  if (curve < 0 || curve >= size())
    throw SurfaceMeshError("no curve mesh for curve id " + std::to_string(curve) + " (" + std::to_string(size()) +
                           " curve meshes)");
  return meshes_[curve];
}

CurveMeshes discretise_all_curves(const cad::Model& model, const SizeField& size, const std::map<int, CurveCount>& counts,
                                  int min_segments) {
  for (const auto& entry : counts) check_curve_id(model, entry.first);
  std::vector<CurveMesh> meshes;
  for (int c = 0; c < model.num_curves(); ++c) {
    auto fixed = counts.find(c);
    meshes.push_back(fixed != counts.end() ? discretise_curve(model, c, fixed->second)
                                           : discretise_curve(model, c, size, min_segments));
  }
  return CurveMeshes(std::move(meshes));
}

}  // namespace semimesh::surface
