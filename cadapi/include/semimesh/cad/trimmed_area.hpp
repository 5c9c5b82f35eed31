// Area of a trimmed CAD face: the integral of |dS/du x dS/dv| over the part of the parameter box
// that Surface::contains() accepts.
#pragma once

#include "semimesh/cad/surface.hpp"

namespace semimesh::cad {

struct TrimmedArea {
  double area = 0.0;
  double error_estimate = 0.0;  ///< estimated |true area - area| (see trimmed_area)
  bool exact = false;           ///< from the backend's own integrator (Surface::exact_area)
};

/// Adaptive quadtree over the parameter box. A cell is classified by the trim test at its corners
/// and centre. Cells inside the face are integrated with 3x3 Gauss-Legendre, split until a cell
/// and its four children agree to `relative_tolerance`. Cells cut by a trim curve are split level
/// by level and integrated counting only their inside Gauss points, until their total area is
/// below `relative_tolerance` of the face, or a budget of 20000 trim tests per face is spent (the
/// trim test is the costly query on B-spline-trimmed OCC faces, ~0.2 ms or more).
/// Accuracy: exact to the quadrature tolerance on untrimmed faces; on trimmed ones error_estimate
/// is the change of the result over the last refinement (1e-5..1e-3 relative on the test faces). A trim
/// feature (hole, notch, sliver) that no corner or centre of the 12 x 12 base grid sees is missed.
TrimmedArea trimmed_area(const Surface& surface, double relative_tolerance = 1e-6);

/// The face's area: the backend's exact integrator where it has one (Surface::exact_area, error
/// estimate 0), else trimmed_area() with `relative_tolerance`.
TrimmedArea face_area(const Surface& surface, double relative_tolerance = 1e-6);

}  // namespace semimesh::cad
