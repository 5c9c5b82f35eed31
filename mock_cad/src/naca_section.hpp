// The chord-normalised NACA 4-digit profile: closed-form points with exact first and second
// derivatives in the parameter u (chordwise station x = u^2), and a point-in-outline test.
//
// Formulas: Abbott & von Doenhoff, "Theory of Wing Sections" (1959), sec. 6.4, and
// NACA Report 460 (Jacobs, Ward, Pinkerton 1933). The surface points are offset from the camber
// line perpendicular to it: X = x -+ y_t sin(theta), Y = y_c +- y_t cos(theta), theta = atan(dy_c/dx).
#pragma once

#include "semimesh/cad/types.hpp"

#include <vector>

namespace semimesh::mock_cad::detail {

using cad::Vec2;

/// +1: the upper (suction, y > 0) side; -1: the lower side.
enum class Side : int { Upper = +1, Lower = -1 };

inline double sign_of(Side side) { return side == Side::Upper ? 1.0 : -1.0; }

/// A profile point (X, Y) in chord units and its derivatives with respect to u.
struct ProfilePoint {
  Vec2 p;
  Vec2 d1;
  Vec2 d2;
};

/// A scalar function of u and its first two u-derivatives.
struct ScalarPoint {
  double f = 0.0, d1 = 0.0, d2 = 0.0;
};

/// The four NACA digits MPTT as fractions of the chord.
struct NacaDigits {
  double max_camber = 0.0;      ///< m = M / 100
  double camber_position = 0.0;  ///< p = P / 10
  double thickness = 0.0;        ///< t = TT / 100
};

/// Where a point lies relative to the closed outline.
enum class OutlineSide { Outside = -1, OnBoundary = 0, Inside = +1 };

class NacaSection {
 public:
  NacaSection(const NacaDigits& digits, bool sharp_te);

  /// Point and u-derivatives of one side at u in [0, 1] (u = 0: leading edge, u = 1: trailing edge).
  ProfilePoint eval(Side side, double u) const;
  /// Only the point (cheaper: no derivatives).
  Vec2 point(Side side, double u) const;

  /// Half thickness y_t at chordwise station x in [0, 1].
  double half_thickness(double x) const;
  /// y_t(u^2) and its u-derivatives (a polynomial in u: sqrt(x) = u).
  ScalarPoint half_thickness_in_u(double u) const;
  /// dy_t/du at u = 0: the leading-edge slope of Y for a symmetric section.
  double leading_edge_slope() const { return 5.0 * digits_.thickness * kA0; }

  /// The u of the maximum camber x = p where the camber line's curvature jumps, so the skins'
  /// u-derivatives jump too (the standard 4-digit construction has a small tangent kink there);
  /// -1 for a symmetric section. The smallest u with u * u >= p: eval() there gives the aft limits.
  double crease_u() const { return crease_u_; }

  /// Classifies q (chord units) against the outline; within `tol` of it counts as OnBoundary.
  OutlineSide classify(const Vec2& q, double tol) const;

  /// Box around the outline: {xmin, ymin}, {xmax, ymax} (chord units).
  const Vec2& extent_lo() const { return extent_lo_; }
  const Vec2& extent_hi() const { return extent_hi_; }

  const NacaDigits& digits() const { return digits_; }
  bool sharp_te() const { return sharp_te_; }

 private:
  static constexpr double kA0 = 0.2969;

  // An arc of one side on which X(u) is strictly monotone: a graph over X.
  struct Piece {
    Side side;
    double u_lo, u_hi;
    double x_lo, x_hi;  // min and max of X over the arc
    bool increasing;    // X grows with u
  };

  struct Camber {
    double y, slope, curvature;  // y_c, dy_c/dx, d2y_c/dx2 at x
  };
  Camber camber(double x) const;
  double solve_for_x(const Piece& piece, double x) const;
  double foot_distance(const Piece& piece, double u, const Vec2& q) const;

  NacaDigits digits_;
  bool sharp_te_;
  double a4_;  // x^4 coefficient of the thickness polynomial
  double crease_u_ = -1.0;
  std::vector<Piece> pieces_;
  Vec2 extent_lo_, extent_hi_;
};

}  // namespace semimesh::mock_cad::detail
