// A CAD curve: a parametric map t -> C(t) on [t0, t1].
//
// Backends implement bounds(), derivatives() and may override project() and arc_length() with
// faster or exact versions; the defaults here are generic and correct (Newton from sampled
// guesses; adaptive Gauss-Legendre). All queries are const and must be thread-safe unless the
// owning Model says otherwise (Model::thread_safe()).
#pragma once

#include "semimesh/cad/types.hpp"

#include <optional>
#include <string>
#include <vector>

namespace semimesh::cad {

class Curve {
 public:
  Curve(int id, std::string name) : id_(id), name_(std::move(name)) {}
  virtual ~Curve() = default;
  Curve(const Curve&) = delete;
  Curve& operator=(const Curve&) = delete;

  int id() const { return id_; }
  const std::string& name() const { return name_; }

  virtual CurveKind kind() const = 0;
  virtual Interval bounds() const = 0;
  /// C(t), dC/dt and d2C/dt2.
  virtual CurveDerivatives derivatives(double t) const = 0;
  virtual Vec3 point(double t) const { return derivatives(t).p; }

  /// A degenerate curve is one point in space walked over a parameter interval: the pole of a
  /// surface (the apex of a cone, the nose of a body of revolution), where a whole side of the
  /// face's parameter box maps to that point. Its derivatives are zero, its length is zero, its
  /// two end vertices are the same, and only one face uses it (once). Default: false.
  virtual bool is_degenerate() const { return false; }

  /// Closest point to x on the curve (clamped to bounds()). `guess` seeds the local solver;
  /// without it the default samples the curve to find a start.
  virtual CurveProjection project(const Vec3& x, std::optional<double> guess = std::nullopt) const;

  /// Parameters strictly inside bounds() where the tangent may jump (a B-spline's knots of
  /// multiplicity = degree, the corners of a loft linear between its sections), increasing.
  /// arc_length() integrates between them: a Gauss rule across a kink converges to about 1e-7 only,
  /// and a curve meshed in a thousand steps then runs out of length before its end. Default: none.
  virtual const std::vector<double>& tangent_breaks() const;

  /// Arc length between parameters a and b (signed: negative when b < a).
  virtual double arc_length(double a, double b) const;
  /// Parameter t such that arc_length(t_start, t) == s (s may be negative). Clamped to bounds.
  virtual double parameter_at_length(double t_start, double s) const;

  /// Curvature |C' x C''| / |C'|^3 (1/length).
  double curvature(double t) const;
  /// Unit tangent in the direction of increasing t.
  Vec3 tangent(double t) const;

  /// Total length over bounds().
  double length() const { auto b = bounds(); return arc_length(b.lo, b.hi); }

 private:
  int id_;
  std::string name_;
};

}  // namespace semimesh::cad
