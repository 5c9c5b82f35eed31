// A CAD surface (face): a parametric map (u,v) -> S(u,v), trimmed by the loops the Model
// records for it.
//
// Orientation contract: normal() points OUT of the solid, INTO the fluid. A backend whose
// natural du x dv points the other way passes orientation = -1 to the constructor; normal()
// and curvatures() then account for it, so no caller ever flips a normal.
#pragma once

#include "semimesh/cad/types.hpp"

#include <array>
#include <functional>
#include <optional>
#include <string>

namespace semimesh::cad {

class Surface {
 public:
  Surface(int id, std::string name, int orientation = +1)
      : id_(id), name_(std::move(name)), orientation_(orientation >= 0 ? +1 : -1) {}
  virtual ~Surface() = default;
  Surface(const Surface&) = delete;
  Surface& operator=(const Surface&) = delete;

  int id() const { return id_; }
  const std::string& name() const { return name_; }
  /// +1 when du x dv points into the fluid, -1 when it points into the solid.
  int orientation() const { return orientation_; }

  virtual SurfaceKind kind() const = 0;
  /// Parameter box {u-interval, v-interval}; trimming loops lie inside it.
  virtual std::array<Interval, 2> bounds() const = 0;
  /// S and its first and second partial derivatives.
  virtual SurfaceDerivatives derivatives(const Vec2& uv) const = 0;
  virtual Vec3 point(const Vec2& uv) const { return derivatives(uv).p; }
  virtual bool is_planar() const { return kind() == SurfaceKind::Plane; }

  /// The period of parameter `direction` (0: u, 1: v) when the surface closes on itself in it:
  /// S(u + period, v) = S(u, v) with all derivatives (a cylinder, a body of revolution, a closed
  /// B-spline). Such a face is usually bounded by a seam curve its loop walks twice (Model::is_seam);
  /// its two images lie one period apart. Default: not periodic. Throws CadError on a direction
  /// other than 0 or 1.
  virtual std::optional<double> period(int direction) const;

  /// Area of the trimmed face from the backend's own exact integrator, when it has one; nullopt
  /// otherwise (callers then integrate with cad::face_area's generic quadrature).
  virtual std::optional<double> exact_area() const { return std::nullopt; }

  /// Whether (u,v) lies inside the trimmed face (on the boundary counts as inside).
  virtual bool contains(const Vec2& uv) const = 0;

  /// Closest point to x. `guess` seeds the local solver; without it the backend finds a start.
  /// The default is Newton on the parameter box from a sampled start; `inside` from contains().
  virtual SurfaceProjection project(const Vec3& x, std::optional<Vec2> guess = std::nullopt) const;

  /// project(x, guess) for callers that need only the foot: uv, point, distance and converged are
  /// exactly project(x, guess)'s, `inside` is not decided (false). The default calls project(); a
  /// backend whose guided project() is local_projection() plus contains() returns
  /// local_projection() alone, saving the trimming test (OCC's exact classifier near a face's loops).
  virtual SurfaceProjection project_near(const Vec3& x, const Vec2& guess) const;

  /// Unit normal pointing into the fluid (see the orientation contract above).
  Vec3 normal(const Vec2& uv) const;
  /// The same from derivatives already evaluated at a point (saves a second evaluation).
  Vec3 normal(const SurfaceDerivatives& d) const;
  /// Principal curvatures with the sign convention of PrincipalCurvatures.
  PrincipalCurvatures curvatures(const Vec2& uv) const;

 protected:
  /// What the default project(x, guess) does before classifying: Newton from guess, restarted off a
  /// pole (leave_pole); `inside` false.
  SurfaceProjection local_projection(const Vec3& x, const Vec2& guess) const;

 private:
  int id_;
  std::string name_;
  int orientation_;
};

/// A closest-point solve that stopped at a pole (a point where the surface does not move along one
/// parameter, `angle`) cannot turn towards the point: the gradient has no component along `angle` there.
/// When `found` is such a point, `solve` (the backend's local solver from a start) is restarted a
/// little off the pole at 8 values of `angle` and the nearest result is returned; else `found`.
SurfaceProjection leave_pole(const Surface& s, SurfaceProjection found,
                             const std::function<SurfaceProjection(const Vec2&)>& solve);

}  // namespace semimesh::cad
