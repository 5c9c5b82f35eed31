// The roles a blunt NACA wing built by the project (analytic or through OCC) must get from the
// detection: its faces carry the analytic names, which the detection never reads.
#pragma once

#include "semimesh/surface/cad_roles.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace semimesh::surface {

inline std::set<std::string> surface_names(const cad::Model& model, const std::vector<int>& surfaces) {
  std::set<std::string> out;
  for (int s : surfaces) out.insert(model.surface(s).name());
  return out;
}

/// Checks every role of `roles` on a blunt NACA wing of span `span` along z and chord `chord`.
inline void expect_blunt_naca_wing_roles(const cad::Model& model, const CadRoles& roles, double span, double chord) {
  using Names = std::set<std::string>;
  EXPECT_EQ(model.surface(roles.wall).name(), "wall");
  EXPECT_EQ(surface_names(model, roles.body), (Names{"upper", "lower", "te_base", "tip"}));
  EXPECT_EQ(surface_names(model, roles.farfield), (Names{"box_xmin", "box_xmax", "box_ymin", "box_ymax", "box_zmax"}));
  ASSERT_TRUE(roles.te_base.has_value());
  EXPECT_EQ(model.surface(*roles.te_base).name(), "te_base");
  EXPECT_EQ(surface_names(model, roles.tip), (Names{"tip"}));
  EXPECT_NEAR((roles.span_direction - cad::Vec3::UnitZ()).norm(), 0.0, 1e-9);
  EXPECT_NEAR(roles.span, span, 1e-6);
  EXPECT_NEAR(roles.chord, chord, 1e-3);
}

}  // namespace semimesh::surface
