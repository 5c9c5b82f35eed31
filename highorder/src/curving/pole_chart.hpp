// Curving next to a pole. There a surface's parameters are polar: one of them is an angle about the
// pole. An element interpolated linearly in them is a polar patch that spans a fixed angle however
// small the element is, so its geometric error falls like h^2 at every order P (and the pole's
// triangles, whose two sides leave the pole along the same parameter line, are curved into folds).
// Next to a pole the nodes are instead placed where the straight-sided element's nodes project onto
// the surface: closest-point projection is a smooth chart where the pole has a tangent plane, so
// the error falls like h^(P+1) again (tests/highorder/ho_mesh/test_curve_periodic.cpp measures it;
// projecting the face's harmonic extension of its curved sides instead stalls at h^4 for P >= 4).
#pragma once

#include "semimesh/cad/model.hpp"

#include <Eigen/Core>

#include <vector>

namespace semimesh::ho::detail {

/// Points of the degenerate curves (poles) in the loops of `surface` where it has a tangent plane
/// (not a cone's apex).
std::vector<cad::Vec3> surface_poles(const cad::Model& model, int surface);

/// Whether the edge from a to b lies next to one of `poles`: a or b within `reach` times the edge's
/// length of a pole (CurvingParams::pole_reach).
bool near_pole(const std::vector<cad::Vec3>& poles, const cad::Vec3& a, const cad::Vec3& b, double reach);

/// Whether every side of a face with these vertices lies next to one of `poles` (near_pole): then
/// its interior nodes are placed by projection too. A face with a side placed by parameters takes
/// the parameters: its interior, projected from the straight-sided face, would not meet that side's
/// nodes (measured: the prisms along the reach's edge had 5-10 times the error of their neighbours).
bool face_near_pole(const std::vector<cad::Vec3>& poles, const std::vector<cad::Vec3>& vertices, double reach);

/// Row `row` of (uv, pts): the closest point of `surface` to x, started from uv's row (moved into
/// the parameter box).
void place_by_projection(const cad::Surface& surface, const cad::Vec3& x, Eigen::Ref<Eigen::MatrixXd> uv,
                         Eigen::Ref<Eigen::MatrixXd> pts, int row);

}  // namespace semimesh::ho::detail
