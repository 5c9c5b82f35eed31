// Tiny closed-form CAD entities for testing cadapi's generic algorithms (projection, arc length,
// normals, curvatures, topology) against answers known by hand.
#pragma once

#include "semimesh/cad/curve.hpp"
#include "semimesh/cad/surface.hpp"

#include <cmath>
#include <functional>
#include <utility>

namespace shapes {

using semimesh::cad::CurveDerivatives;
using semimesh::cad::CurveKind;
using semimesh::cad::Interval;
using semimesh::cad::SurfaceDerivatives;
using semimesh::cad::SurfaceKind;
using semimesh::cad::Vec2;
using semimesh::cad::Vec3;

constexpr double kPi = 3.14159265358979323846;

/// C(t) = a + t (b - a), t in [0, 1].
class Line : public semimesh::cad::Curve {
 public:
  Line(int id, Vec3 a, Vec3 b) : Curve(id, "line"), a_(std::move(a)), b_(std::move(b)) {}
  CurveKind kind() const override { return CurveKind::Line; }
  Interval bounds() const override { return {0.0, 1.0}; }
  CurveDerivatives derivatives(double t) const override { return {a_ + t * (b_ - a_), b_ - a_, Vec3::Zero()}; }

 private:
  Vec3 a_, b_;
};

/// Circle of radius r around the z axis in the plane z = 0: C(t) = r (cos t, sin t, 0), t in [lo, hi].
class Circle : public semimesh::cad::Curve {
 public:
  Circle(int id, double r, Interval range) : Curve(id, "circle"), r_(r), range_(range) {}
  CurveKind kind() const override { return CurveKind::Circle; }
  Interval bounds() const override { return range_; }
  CurveDerivatives derivatives(double t) const override {
    double c = std::cos(t), s = std::sin(t);
    return {Vec3(r_ * c, r_ * s, 0), Vec3(-r_ * s, r_ * c, 0), Vec3(-r_ * c, -r_ * s, 0)};
  }

 private:
  double r_;
  Interval range_;
};

/// Sphere of radius r at the origin: S(u, v) = r (cos v cos u, cos v sin u, sin v) on
/// u in [0, pi/2], v in [-pi/4, pi/4]; du x dv points away from the centre.
class SpherePatch : public semimesh::cad::Surface {
 public:
  SpherePatch(int id, double r, int orientation) : Surface(id, "sphere", orientation), r_(r) {}
  SurfaceKind kind() const override { return SurfaceKind::Sphere; }
  std::array<Interval, 2> bounds() const override { return {Interval{0, kPi / 2}, Interval{-kPi / 4, kPi / 4}}; }
  bool contains(const Vec2& uv) const override {
    auto b = bounds();
    return b[0].contains(uv.x()) && b[1].contains(uv.y());
  }
  SurfaceDerivatives derivatives(const Vec2& uv) const override {
    double cu = std::cos(uv.x()), su = std::sin(uv.x()), cv = std::cos(uv.y()), sv = std::sin(uv.y());
    SurfaceDerivatives d;
    d.p = r_ * Vec3(cv * cu, cv * su, sv);
    d.du = r_ * Vec3(-cv * su, cv * cu, 0);
    d.dv = r_ * Vec3(-sv * cu, -sv * su, cv);
    d.duu = r_ * Vec3(-cv * cu, -cv * su, 0);
    d.duv = r_ * Vec3(sv * su, -sv * cu, 0);
    d.dvv = r_ * Vec3(-cv * cu, -cv * su, -sv);
    return d;
  }

 private:
  double r_;
};

/// Cylinder of radius r around the z axis: S(u, v) = (r cos u, r sin u, v), u in [0, pi], v in [0, 2];
/// du x dv points away from the axis.
class Cylinder : public semimesh::cad::Surface {
 public:
  Cylinder(int id, double r) : Surface(id, "cylinder"), r_(r) {}
  SurfaceKind kind() const override { return SurfaceKind::Cylinder; }
  std::array<Interval, 2> bounds() const override { return {Interval{0, kPi}, Interval{0, 2}}; }
  bool contains(const Vec2&) const override { return true; }
  SurfaceDerivatives derivatives(const Vec2& uv) const override {
    double c = std::cos(uv.x()), s = std::sin(uv.x());
    SurfaceDerivatives d;
    d.p = Vec3(r_ * c, r_ * s, uv.y());
    d.du = Vec3(-r_ * s, r_ * c, 0);
    d.dv = Vec3(0, 0, 1);
    d.duu = Vec3(-r_ * c, -r_ * s, 0);
    d.duv = Vec3::Zero();
    d.dvv = Vec3::Zero();
    return d;
  }

 private:
  double r_;
};

/// Plane S(u, v) = o + u e1 + v e2 on the box [ulo, uhi] x [vlo, vhi], trimmed by `inside`.
class Plane : public semimesh::cad::Surface {
 public:
  Plane(int id, Vec3 o, Vec3 e1, Vec3 e2, std::array<Interval, 2> box, std::function<bool(const Vec2&)> inside,
        int orientation = +1)
      : Surface(id, "plane", orientation), o_(std::move(o)), e1_(std::move(e1)), e2_(std::move(e2)), box_(box),
        inside_(std::move(inside)) {}
  SurfaceKind kind() const override { return SurfaceKind::Plane; }
  std::array<Interval, 2> bounds() const override { return box_; }
  bool contains(const Vec2& uv) const override { return inside_(uv); }
  SurfaceDerivatives derivatives(const Vec2& uv) const override {
    return {o_ + uv.x() * e1_ + uv.y() * e2_, e1_, e2_, Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  }

 private:
  Vec3 o_, e1_, e2_;
  std::array<Interval, 2> box_;
  std::function<bool(const Vec2&)> inside_;
};

}  // namespace shapes
