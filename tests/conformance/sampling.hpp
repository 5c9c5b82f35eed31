// Backend-agnostic helpers of the conformance suite: where to sample a trimmed face, the winding
// number of a point with respect to a model, composite Simpson arc length.
#pragma once

#include "semimesh/cad/model.hpp"

#include <vector>

namespace conformance {

using semimesh::cad::Vec2;
using semimesh::cad::Vec3;

/// Parameters on an n x n grid of the parameter box that lie inside the trimmed face together with
/// their four neighbours at `margin` (a fraction of the box) in u and v, so that the samples keep
/// away from trim curves. `offset` places the samples in their grid cells (0.5: cell centres);
/// an off-centre offset keeps them off the knots that splines often have at simple fractions.
std::vector<Vec2> inside_samples(const semimesh::cad::Surface& surface, int n, double margin = 0.02, double offset = 0.5);

/// The inside sample nearest to the centre of the parameter box (the face must have one).
Vec2 central_sample(const semimesh::cad::Surface& surface);

/// Generalised winding number (1/4pi) * sum over faces of the integral of (S - q).n / |S - q|^3 dA,
/// with n the fluid normal. For a geometrically closed model it is 0 or -1 in the fluid (fluid
/// outside a body / fluid enclosed by the model) and one more on the solid side. Adaptive in
/// the parameter plane: cells shrink until they are small against their distance to q.
double winding_number(const semimesh::cad::Model& model, const Vec3& q);

/// Length of a curve between a and b by composite Simpson on |C'(t)| with `intervals` (even) steps.
double simpson_length(const semimesh::cad::Curve& curve, double a, double b, int intervals);

}  // namespace conformance
