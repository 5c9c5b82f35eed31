// An independent reference for the tests: the textbook NACA 4-digit formulas in the chordwise
// station x (with sqrt(x) and atan), not in the backend's parameter u = sqrt(x).
// Abbott & von Doenhoff, "Theory of Wing Sections" (1959), sec. 6.4.
#pragma once

#include "semimesh/mock_cad/naca.hpp"

#include <memory>

namespace naca_test {

struct Point2 {
  double x = 0.0, y = 0.0;
};

/// Half thickness y_t(x) of thickness ratio t; a4 = -0.1036 when sharp, else -0.1015.
double half_thickness(double t, double x, bool sharp);
/// Camber line y_c(x) of maximum camber m at position p.
double camber(double m, double p, double x);
/// Upper (upper = true) or lower surface point at station x of the section "MPTT".
Point2 surface_point(double m, double p, double t, double x, bool upper, bool sharp);

/// A wing with the given changes to the defaults (farfield on).
std::unique_ptr<semimesh::cad::Model> wing(const semimesh::mock_cad::NacaWingParams& params = {});
/// Id of the surface / curve of that name; fails the test (throws) when absent.
int surface_id(const semimesh::cad::Model& model, const std::string& name);
int curve_id(const semimesh::cad::Model& model, const std::string& name);

}  // namespace naca_test
