// The geometry of a wing-wall junction, from the CAD only (cadapi): which body-wall curves are
// concave corners, and the medial halo point of a root point.
#pragma once

#include "semimesh/cad/model.hpp"

#include <optional>
#include <vector>

namespace semimesh::nearfield {

using cad::Vec3;

/// A curve shared by a body surface and the wall, with its dihedral angle seen from the fluid
/// (90 degrees for a wing standing upright on the wall, 180 for a flat continuation, > 180 convex).
struct WallCurve {
  int curve = -1;
  int body_surface = -1;
  double min_angle_deg = 0.0;  ///< over samples along the curve
  double max_angle_deg = 0.0;
  Vec3 min_at = Vec3::Zero(), max_at = Vec3::Zero();  ///< where they are
};

/// Every curve shared by one of `body_surfaces` and `wall`, with its angle range from both surfaces'
/// fluid normals at `samples` points along it, both ends included (the side of the body face from the loop direction:
/// the face lies on the left of its loop seen from the fluid).
std::vector<WallCurve> wall_curves(const cad::Model& model, const std::vector<int>& body_surfaces, int wall,
                                   int samples = 9);

/// Those of wall_curves whose largest angle is below `concave_below_deg`: the concave corners that
/// carry a junction block.
std::vector<WallCurve> concave_wall_curves(const cad::Model& model, const std::vector<int>& body_surfaces, int wall,
                                           double concave_below_deg);

/// The medial halo point of the root point `root`: H = root + a e + wall_offset n_wall, with a > 0
/// such that H lies at distance `wing_offset` from the body surfaces, and at `wall_offset` from the
/// (planar) wall. `e` is a unit direction in the wall plane pointing away from the body.
/// Newton on a, distances by cadapi projections (the nearest of `body_surfaces`).
/// Throws NearFieldError naming the place when no such point is found near the root, and the
/// thicknesses that fit where the body leans away from the wall there (thicknesses_that_fit).
Vec3 medial_halo(const cad::Model& model, const std::vector<int>& body_surfaces, const Vec3& root, const Vec3& e,
                 const Vec3& n_wall, double wing_offset, double wall_offset);

/// Distance from x to the nearest of `surfaces` (closest points inside the trimmed faces), and
/// that point.
struct NearestPoint {
  double distance = 1e300;
  Vec3 point = Vec3::Zero();
  int surface = -1;
};
NearestPoint nearest_on_surfaces(const cad::Model& model, const std::vector<int>& surfaces, const Vec3& x);

/// Where medial_halo finds no point because the body leans away from the wall's normal at `root`
/// (the point `wall_offset` up that normal is farther than `wing_offset` from the body, on the side
/// `e` leads to, away from the body): the
/// thicknesses that would fit, each rounded to 4 digits on its safe side. The wall's (below
/// `wall_below`, the distance up the normal still within `wing_offset` of the body, by bisection)
/// with the shell's kept, or the shell's (at least `shell_at_least`, that point's distance) with
/// the wall's kept. std::nullopt when the body does not lean away there.
struct ThicknessesThatFit {
  double wall_below = 0.0;
  double shell_at_least = 0.0;
};
std::optional<ThicknessesThatFit> thicknesses_that_fit(const cad::Model& model, const std::vector<int>& body_surfaces,
                                                       const Vec3& root, const Vec3& e, const Vec3& n_wall,
                                                       double wing_offset, double wall_offset);

}  // namespace semimesh::nearfield
