// Shared helpers of the surface meshing tests: the analytic NACA 0012 wing in its far-field box,
// and lookups by entity name.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/mock_cad/naca.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>

namespace semimesh::surface::testing {

inline std::unique_ptr<cad::Model> naca_model(std::array<double, 6> box = {-10, -10, 0, 11, 10, 10}) {
  mock_cad::NacaWingParams p;
  p.box = box;
  return mock_cad::make_naca_wing(p);
}

inline int curve_named(const cad::Model& m, const std::string& name) {
  for (int c = 0; c < m.num_curves(); ++c)
    if (m.curve(c).name() == name) return c;
  ADD_FAILURE() << "no curve " << name;
  return -1;
}

inline int surface_named(const cad::Model& m, const std::string& name) {
  auto s = m.find_surface(name);
  if (!s) ADD_FAILURE() << "no surface " << name;
  return s.value_or(-1);
}

/// NACA 4-digit half thickness (Abbott & von Doenhoff 1959, sec. 6.4; squared-off TE coefficient).
inline double naca_half_thickness(double t, double x) {
  return 5.0 * t * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1015 * x * x * x * x);
}

/// Area of the symmetric section of thickness t and unit chord: 2 * integral of y_t, in closed form
/// (the integrals of sqrt(x), x, x^2, x^3, x^4 over [0, 1] are 2/3, 1/2, 1/3, 1/4, 1/5).
inline double naca_section_area(double t) {
  return 10.0 * t * (0.2969 * 2.0 / 3.0 - 0.1260 / 2.0 - 0.3516 / 3.0 + 0.2843 / 4.0 - 0.1015 / 5.0);
}

}  // namespace semimesh::surface::testing
