// Small value types returned by CAD queries. All coordinates are in the model's unit, which the
// backend fixed once at load time (see Model::units()).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // Vec3::cross() is declared in Core but defined here

#include <array>
#include <string>

namespace semimesh::cad {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

/// Closed parameter interval [lo, hi].
struct Interval {
  double lo = 0.0;
  double hi = 0.0;
  double length() const { return hi - lo; }
  bool contains(double t, double tol = 0.0) const { return t >= lo - tol && t <= hi + tol; }
  double clamp(double t) const { return t < lo ? lo : (t > hi ? hi : t); }
};

/// Axis-aligned box; empty() until a point is added.
struct BBox {
  Vec3 lo = Vec3::Constant(+1e300);
  Vec3 hi = Vec3::Constant(-1e300);
  bool empty() const { return lo.x() > hi.x(); }
  void add(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void add(const BBox& b) {
    if (!b.empty()) { add(b.lo); add(b.hi); }
  }
  bool contains(const Vec3& p, double tol = 0.0) const {
    return (p.array() >= lo.array() - tol).all() && (p.array() <= hi.array() + tol).all();
  }
  double diagonal() const { return empty() ? 0.0 : (hi - lo).norm(); }
};

/// A curve point with its first and second derivative with respect to the curve parameter t.
struct CurveDerivatives {
  Vec3 p;   ///< C(t)
  Vec3 d1;  ///< dC/dt
  Vec3 d2;  ///< d2C/dt2
};

/// A surface point with first and second partial derivatives with respect to (u, v).
struct SurfaceDerivatives {
  Vec3 p;    ///< S(u,v)
  Vec3 du;   ///< dS/du
  Vec3 dv;   ///< dS/dv
  Vec3 duu;  ///< d2S/du2
  Vec3 duv;  ///< d2S/dudv
  Vec3 dvv;  ///< d2S/dv2
};

/// Principal curvatures (1/length) and directions of a surface at a point.
/// Sign convention: measured against the fluid-pointing normal so that a convex solid is
/// positive, e.g. a sphere of radius R has k1 = k2 = +1/R; a flat face has 0.
struct PrincipalCurvatures {
  double k_min = 0.0;
  double k_max = 0.0;
  Vec3 dir_min = Vec3::Zero();  ///< unit tangent of k_min
  Vec3 dir_max = Vec3::Zero();  ///< unit tangent of k_max
  double mean() const { return 0.5 * (k_min + k_max); }
  double gaussian() const { return k_min * k_max; }
};

/// Result of the closest-point query on a curve.
struct CurveProjection {
  double t = 0.0;          ///< parameter of the closest point found
  Vec3 point;              ///< C(t)
  double distance = 0.0;   ///< |x - C(t)|
  bool converged = false;  ///< the local solver met its tolerance
};

/// Result of the closest-point query on a surface.
struct SurfaceProjection {
  Vec2 uv;                 ///< parameters of the closest point found
  Vec3 point;              ///< S(u,v)
  double distance = 0.0;   ///< |x - S(u,v)|
  bool converged = false;  ///< the local solver met its tolerance
  bool inside = false;     ///< (u,v) lies inside the trimmed face (not only in its parameter box)
};

/// What kind of geometry carries a surface; reported by cad-info, used to pick fast paths.
enum class SurfaceKind { Plane, Cylinder, Cone, Sphere, Torus, BSpline, Bezier, Revolution, Extrusion, Offset, Analytic, Other };
enum class CurveKind { Line, Circle, Ellipse, BSpline, Bezier, Analytic, Other };

std::string to_string(SurfaceKind kind);
std::string to_string(CurveKind kind);

}  // namespace semimesh::cad
