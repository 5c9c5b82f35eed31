// Roles found without names on the analytic wing: the expected roles are the analytic model's own
// face names (which the detection never reads), its span and chord its parameters.
#include "naca_wing_roles.hpp"
#include "semimesh/surface/cad_roles.hpp"

#include "semimesh/mock_cad/naca.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <set>
#include <string>

namespace semimesh::surface {
namespace {

using Names = std::set<std::string>;

TEST(CadRoles, AnalyticBluntWing) {
  mock_cad::NacaWingParams p;
  p.span = 2.5;
  p.chord = 1.5;
  const auto model = mock_cad::make_naca_wing(p);
  expect_blunt_naca_wing_roles(*model, detect_cad_roles(*model), 2.5, 1.5);
}

TEST(CadRoles, AnalyticSharpSweptTaperedWingHasNoBase) {
  mock_cad::NacaWingParams p;
  p.sharp_te = true;
  p.sweep_deg = 30.0;
  p.taper = 0.4;
  p.code = "2412";
  const auto model = mock_cad::make_naca_wing(p);
  const CadRoles roles = detect_cad_roles(*model);
  EXPECT_EQ(surface_names(*model, roles.body), (Names{"upper", "lower", "tip"}));
  EXPECT_FALSE(roles.te_base.has_value());
  EXPECT_EQ(surface_names(*model, roles.tip), (Names{"tip"}));
  EXPECT_NE(describe_cad_roles(*model, roles).find("none (a closed trailing edge)"), std::string::npos);
}

TEST(CadRoles, NamedWallGivesTheSameRoles) {
  const auto model = mock_cad::make_naca_wing({});
  const CadRoles found = detect_cad_roles(*model);
  const CadRoles named = detect_cad_roles(*model, *model->find_surface("wall"));
  EXPECT_EQ(found.body, named.body);
  EXPECT_EQ(found.farfield, named.farfield);
  EXPECT_EQ(found.te_base, named.te_base);
}

void expect_error(const std::function<void()>& f, const std::string& part) {
  try {
    f();
    ADD_FAILURE() << "no error; expected one containing: " << part;
  } catch (const CadRoleError& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(CadRoles, BadInputIsNamed) {
  mock_cad::NacaWingParams p;
  p.farfield = false;
  const auto body_only = mock_cad::make_naca_wing(p);
  expect_error([&] { detect_cad_roles(*body_only); }, "no face holds a body's root loop");
  const auto model = mock_cad::make_naca_wing({});
  // A curved face may be a wall (a fuselage), but no body stands on the wing's own skin.
  expect_error([&] { detect_cad_roles(*model, *model->find_surface("upper")); }, "('upper') has no inner loop");
  expect_error([&] { detect_cad_roles(*model, *model->find_surface("box_xmin")); }, "('box_xmin') has no inner loop");
}

TEST(CadRoles, BodyOfRevolutionStandsOnNoWall) {
  const auto model = mock_cad::load_naca(cad::Source{
      "", {{"naca.shape", "revolution"}, {"naca.te", "sharp"}, {"naca.farfield", "false"}}});
  expect_error([&] { detect_cad_roles(*model); }, "no wall the body stands on");
}

}  // namespace
}  // namespace semimesh::surface
