// Curving on CAD whose parameters are kinked. CAD exporters (OpenVSP among them) write a wing skin
// as Bezier patches joined at knots of full multiplicity, and its edges the same way: the geometry
// is smooth, but the parametric speed |dS/du|, |dS/dv| or |dC/dt| jumps at each joint (by 2-8x on
// OpenVSP's ONERA M6). Nodes placed at the node set's fractions of an edge's parameter interval
// then bunch up on one side of a joint the edge crosses, and thin layer elements fold. So on a
// kinked surface or curve the nodes go where the straight-sided element's nodes project onto it
// (as next to a pole: pole_chart.hpp): a chart that does not see the parameters, so the error
// still falls like h^(P+1).
#pragma once

#include "semimesh/cad/curve.hpp"
#include "semimesh/cad/surface.hpp"

namespace semimesh::ho::detail {

/// Neighbouring speeds further apart than this ratio make a kink.
inline constexpr double kKinkRatio = 1.5;

/// Whether `surface`'s parametric speed jumps: along 9 iso-lines in each direction, the speed
/// along the line at 257 evenly spaced parameters, two neighbours differing by more than
/// kKinkRatio. A smooth parametrisation changes by O(1/256) of its log-speed scale between
/// neighbours; the three spacings next to each end are left out, where a pole's speed falls to 0
/// (its ratio there is at most 4/3). A plane's parameters are affine, but a planar B-spline face's
/// may be kinked too (a trailing-edge base written as patches): its nodes then bunch up in-plane.
bool has_kinked_parameters(const cad::Surface& surface);

/// The same for a curve's |dC/dt| over its parameter interval. Lines are never kinked.
bool has_kinked_parameters(const cad::Curve& curve);

}  // namespace semimesh::ho::detail
