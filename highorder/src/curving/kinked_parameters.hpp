// Curving on CAD whose parameters are kinked. CAD exporters (OpenVSP among them) write a wing skin
// as Bezier patches joined at knots of full multiplicity, and its edges the same way: the geometry
// is smooth, but the parametric speed |dS/du|, |dS/dv| or |dC/dt| jumps at each joint (by 2-8x on
// OpenVSP's ONERA M6). Nodes placed at the node set's fractions of an edge's parameter interval
// then bunch up on one side of a joint the edge crosses, and thin layer elements fold. So on a
// kinked surface or curve the nodes are placed at fractions of a chart that takes the kinks out
// (KinkChart: the parameters mapped piecewise linearly so that the speed is continuous at each
// kink), which on patches that only reparametrise a smooth surface gives back its smooth
// parameters, and so the parameter placement's accuracy.
#pragma once

#include "semimesh/cad/curve.hpp"
#include "semimesh/cad/surface.hpp"

#include <vector>

namespace semimesh::ho::detail {

/// Neighbouring speeds further apart than this ratio make a kink.
inline constexpr double kKinkRatio = 1.5;

/// A piecewise linear reparametrisation of one parameter that takes its kinks out: s(t) has slope
/// 1 up to the first kink and is multiplied at each kink by the ratio of the speeds after and
/// before it, so the speed in s is continuous there. Between kinks s is affine in t, so each smooth
/// piece keeps its own parameters up to scale: nodes placed at fractions of s are those of the
/// surface's smooth parametrisation when the kinks are pure reparametrisations (Bezier patches
/// with moved knots). Default: the identity.
class KinkChart {
 public:
  KinkChart() = default;
  /// kinks: ascending parameters; ratios: speed after / speed before, one per kink.
  KinkChart(std::vector<double> kinks, const std::vector<double>& ratios);
  double to_chart(double t) const;
  double from_chart(double s) const;
  bool identity() const { return kinks_.empty(); }

 private:
  std::vector<double> kinks_;   // t of each kink
  std::vector<double> at_;      // s of each kink
  std::vector<double> slopes_;  // ds/dt before the first kink (1), then after each
};

/// The chart along parameter `along` (0: u, 1: v) of a surface. Its kinks: on the middle iso-line
/// across the other parameter (knot lines of a tensor-product surface cross it), the speed along
/// the line at 257 evenly spaced parameters, two neighbours differing by more than kKinkRatio, the
/// kink then located between them by bisection. A smooth parametrisation changes by O(1/256) of
/// its log-speed scale between neighbours; the three spacings next to each end are left out, where
/// a pole's speed falls to 0 (its ratio there is at most 4/3). Planar B-spline faces are charted
/// too: a trailing-edge base written as patches bunches its nodes in-plane.
KinkChart kink_chart(const cad::Surface& surface, int along);
/// The same along a curve (the identity for lines and degenerate curves).
KinkChart kink_chart(const cad::Curve& curve);

}  // namespace semimesh::ho::detail
