// naca.* parameters: reading, and every invalid value rejected with the key in the message.
#include "naca_reference.hpp"

#include "semimesh/cad/error.hpp"

#include <gtest/gtest.h>

namespace {

using semimesh::cad::CadError;
using semimesh::cad::Params;
using semimesh::cad::Source;
using semimesh::mock_cad::load_naca;
using semimesh::mock_cad::naca_params_from;

TEST(NacaParams, ReadsEveryKey) {
  const Params p{{"naca.code", "2412"}, {"naca.chord", "2"},        {"naca.span", "4"},
                 {"naca.taper", "0.5"}, {"naca.sweep", "-15"},      {"naca.te", "sharp"},
                 {"naca.farfield", "false"}, {"naca.box", " -20, -15,0 ,30,15 , 12"}, {"naca.units", "m"}};
  const auto w = naca_params_from(p);
  EXPECT_EQ(w.code, "2412");
  EXPECT_EQ(w.chord, 2.0);
  EXPECT_EQ(w.span, 4.0);
  EXPECT_EQ(w.taper, 0.5);
  EXPECT_EQ(w.sweep_deg, -15.0);
  EXPECT_TRUE(w.sharp_te);
  EXPECT_FALSE(w.farfield);
  EXPECT_EQ(w.box, (std::array<double, 6>{-20, -15, 0, 30, 15, 12}));
  EXPECT_EQ(w.units, "m");
}

TEST(NacaParams, DefaultsAreTheBluntNaca0012InABox) {
  const auto w = naca_params_from(Params{});
  EXPECT_EQ(w.code, "0012");
  EXPECT_FALSE(w.sharp_te);
  EXPECT_TRUE(w.farfield);
  auto model = load_naca(Source{});
  EXPECT_EQ(model->backend(), "naca");
  EXPECT_EQ(model->units(), "chord");
  EXPECT_EQ(model->scale_applied(), 1.0);
  EXPECT_TRUE(model->thread_safe());
  EXPECT_NEAR(model->tolerance(), 1e-12, 1e-20);
  EXPECT_TRUE(model->is_closed());
}

struct BadCase {
  const char* key;
  const char* value;
  const char* also_in_message;  // what the message must explain
};

class NacaBadParam : public ::testing::TestWithParam<BadCase> {};

TEST_P(NacaBadParam, IsRejectedNamingTheKey) {
  const BadCase& c = GetParam();
  Params p{{c.key, c.value}};
  try {
    naca_params_from(p);
    FAIL() << c.key << " = '" << c.value << "' was accepted";
  } catch (const CadError& e) {
    EXPECT_EQ(e.kind(), CadError::Kind::BadParameter);
    const std::string msg = e.what();
    EXPECT_NE(msg.find(c.key), std::string::npos) << msg;
    if (std::string(c.also_in_message) != "unknown parameter") {
      EXPECT_NE(msg.find(c.value), std::string::npos) << msg;
    }
    EXPECT_NE(msg.find(c.also_in_message), std::string::npos) << msg;
  }
  // The builder rejects the same values given as a struct (through the same checks).
  if (std::string(c.key) == "naca.span") {
    semimesh::mock_cad::NacaWingParams w;
    w.span = -1;
    EXPECT_THROW(semimesh::mock_cad::make_naca_wing(w), CadError);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Naca, NacaBadParam,
    ::testing::Values(BadCase{"naca.code", "00a2", "4 digits MPTT"}, BadCase{"naca.code", "2 0", "4 digits"},
                      BadCase{"naca.code", "00012", "4 digits"}, BadCase{"naca.code", "0000", "thickness"},
                      BadCase{"naca.code", "2012", "camber position"}, BadCase{"naca.chord", "0", "chord > 0"},
                      BadCase{"naca.chord", "-1", "chord > 0"}, BadCase{"naca.chord", "abc", "number"},
                      BadCase{"naca.span", "-2", "> 0"}, BadCase{"naca.span", "0", "> 0"},
                      BadCase{"naca.taper", "0", "> 0"}, BadCase{"naca.taper", "-0.5", "> 0"},
                      BadCase{"naca.sweep", "80", "< 80"}, BadCase{"naca.sweep", "-85", "< 80"},
                      BadCase{"naca.te", "round", "blunt"}, BadCase{"naca.farfield", "maybe", "true or false"},
                      BadCase{"naca.box", "-10,-10,1,11,10,10", "zmin"}, BadCase{"naca.box", "0.5,-10,0,11,10,10", "enclos"},
                      BadCase{"naca.box", "-10,-10,0,0.9,10,10", "enclos"}, BadCase{"naca.box", "-10,-0.01,0,11,10,10", "enclos"},
                      BadCase{"naca.box", "-10,-10,0,11,10,2", "enclos"}, BadCase{"naca.box", "1,2,3", "6 comma-separated"},
                      BadCase{"naca.box", "-10,-10,0,11,10,10,4", "6 comma-separated"},
                      BadCase{"naca.box", "-10;-10;0;11;10;10", "6 comma-separated"}, BadCase{"naca.units", "", "unit"},
                      BadCase{"naca.shape", "sphere", "revolution"}, BadCase{"naca.tip", "rounded", "flat"}, BadCase{"naca.cord", "1", "unknown parameter"},
                      BadCase{"naca.wall", "sphere", "plane"}, BadCase{"naca.dihedral", "45", "|dihedral| < 45"},
                      BadCase{"naca.dihedral", "-60", "|dihedral| < 45"}, BadCase{"naca.wall_radius", "2", "unset unless naca.wall = cylinder"}));

// On a cylinder (naca.wall = cylinder, radius 1.5 by default): each conflict names its key, its
// value and what was expected.
TEST(NacaParams, FuselageWallRadiusAndBoxAreChecked) {
  struct Case {
    Params changes;
    std::string key, value, expected;
  };
  const std::vector<Case> cases = {
      {{{"naca.wall_radius", "0"}}, "naca.wall_radius", "0", "radius > 0"},
      {{{"naca.wall_radius", "-1"}}, "naca.wall_radius", "-1", "radius > 0"},
      {{{"naca.wall_radius", "0.2"}}, "naca.wall_radius", "0.2", "half thickness"},
      {{{"naca.box", "-10,-10,0,11,10,10"}}, "naca.box", "-10,-10,0,11,10,10", "zmin < -3.15"},
      {{{"naca.box", "-10,-1.6,-20,11,10,10"}}, "naca.box", "-10,-1.6,-20,11,10,10", "ymin < -1.65"},
      {{{"naca.box", "0.5,-12,-14,11,12,10"}}, "naca.box", "0.5,-12,-14,11,12,10", "enclosing the wing"},
      {{{"naca.tip", "round"}}, "naca.tip", "round", "flat on naca.wall = cylinder"},
      {{{"naca.taper", "2.5"}}, "naca.taper", "2.5", "below 1 + 0.5 naca.span / naca.wall_radius = 2"},
      {{{"naca.shape", "revolution"}, {"naca.te", "sharp"}, {"naca.farfield", "false"}}, "naca.wall", "cylinder",
       "plane for naca.shape = revolution"},
  };
  for (const Case& c : cases) {
    Params p{{"naca.wall", "cylinder"}};
    for (const auto& [key, value] : c.changes.all()) p.set(key, value);
    try {
      naca_params_from(p);
      FAIL() << c.key << " = " << c.value << " was accepted on a cylinder";
    } catch (const CadError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(e.kind(), CadError::Kind::BadParameter);
      EXPECT_EQ(msg.rfind(c.key + " = '" + c.value + "': expected ", 0), 0u) << msg;
      EXPECT_NE(msg.find(c.expected), std::string::npos) << msg;
    }
  }
  // The cone's half angle: only for naca.wall = cone, not 0 there, below 30 degrees, and its apex
  // outside the box.
  const std::vector<Case> cone_cases = {
      {{{"naca.wall", "cylinder"}, {"naca.wall_angle", "3"}}, "naca.wall_angle", "3", "unset unless naca.wall = cone"},
      {{{"naca.wall", "cone"}, {"naca.wall_angle", "0"}}, "naca.wall_angle", "0", "0 is naca.wall = cylinder"},
      {{{"naca.wall", "cone"}, {"naca.wall_angle", "30"}}, "naca.wall_angle", "30", "|angle| < 30"},
      {{{"naca.wall", "cone"}, {"naca.wall_angle", "-9"}}, "naca.wall_angle", "-9", "over the box's x range [-10, 11]"},
      {{{"naca.wall", "cone"}, {"naca.wall_angle", "20"}, {"naca.span", "0.5"}, {"naca.box", "-2,-5,-6,3,5,2"}}, "naca.span", "0.5",
       "whose crest lifts the root to z = 0.36"},
  };
  for (const Case& c : cone_cases) {
    Params p;
    for (const auto& [key, value] : c.changes.all()) p.set(key, value);
    try {
      naca_params_from(p);
      FAIL() << c.key << " = " << c.value << " was accepted";
    } catch (const CadError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(c.key + " = '" + c.value + "': expected ", 0), 0u) << msg;
      EXPECT_NE(msg.find(c.expected), std::string::npos) << msg;
    }
  }
  // The defaults, a thin fuselage and a given box are fine.
  EXPECT_NO_THROW(naca_params_from(Params{{"naca.wall", "cylinder"}}));
  EXPECT_NO_THROW(naca_params_from(Params{{"naca.wall", "cylinder"}, {"naca.wall_radius", "0.25"}}));
  EXPECT_NO_THROW(naca_params_from(Params{{"naca.wall", "cylinder"}, {"naca.box", "-5,-2,-4,6,2,4"}}));
  EXPECT_EQ(naca_params_from(Params{{"naca.wall", "cone"}}).wall_angle_deg, 5.0);
  EXPECT_NO_THROW(naca_params_from(Params{{"naca.wall", "cone"}, {"naca.wall_angle", "-4"}}));
}

// The body of revolution has no wall, a pole at the tail and no camber: each conflict is named.
TEST(NacaParams, RevolutionNeedsSymmetricSharpAndNoWall) {
  const Params ok{{"naca.shape", "revolution"}, {"naca.te", "sharp"}, {"naca.farfield", "false"}};
  EXPECT_NO_THROW(semimesh::mock_cad::load_naca(semimesh::cad::Source{"", ok}));
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"naca.te", "blunt"}, {"naca.farfield", "true"}, {"naca.code", "2412"}}) {
    Params p = ok;
    p.set(key, value);
    try {
      semimesh::mock_cad::load_naca(semimesh::cad::Source{"", p});
      FAIL() << key << " = " << value << " was accepted with naca.shape = revolution";
    } catch (const CadError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(key), std::string::npos) << msg;
      EXPECT_NE(msg.find("revolution"), std::string::npos) << msg;
    }
  }
}

// The rounded tip stands above z = span (by the tip section's half thickness, 0.06 chord for 0012):
// a box that clears the flat tip but not the cap is refused with the cap's height; a body of
// revolution has no tip to round.
TEST(NacaParams, RoundTipNeedsRoomAboveTheSpanAndAWing) {
  const Params low_box{{"naca.tip", "round"}, {"naca.span", "2"}, {"naca.box", "-10,-10,0,11,10,2.03"}};
  try {
    naca_params_from(low_box);
    FAIL() << "a box below the rounded tip's crown was accepted";
  } catch (const CadError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("naca.box"), std::string::npos) << msg;
    EXPECT_NE(msg.find("z [0, 2.06"), std::string::npos) << msg;  // 2 + 0.5 * 0.12 (max y_t ~ t / 2)
  }
  Params flat = low_box;
  flat.set("naca.tip", "flat");
  EXPECT_NO_THROW(naca_params_from(flat));
  const Params body{{"naca.shape", "revolution"}, {"naca.te", "sharp"}, {"naca.farfield", "false"}, {"naca.tip", "round"}};
  try {
    naca_params_from(body);
    FAIL() << "naca.tip = round was accepted with naca.shape = revolution";
  } catch (const CadError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("naca.tip"), std::string::npos) << msg;
    EXPECT_NE(msg.find("revolution"), std::string::npos) << msg;
  }
}

TEST(NacaParams, DihedralIsReadAndNotForRoundTipsOrBodies) {
  EXPECT_EQ(naca_params_from(Params{{"naca.dihedral", "-7.5"}}).dihedral_deg, -7.5);
  EXPECT_EQ(naca_params_from(Params{}).dihedral_deg, 0.0);
  for (const Params& p : {Params{{"naca.dihedral", "5"}, {"naca.tip", "round"}},
                          Params{{"naca.dihedral", "5"}, {"naca.shape", "revolution"}, {"naca.te", "sharp"}, {"naca.farfield", "false"}}}) {
    try {
      naca_params_from(p);
      FAIL() << "a dihedral was accepted with a rounded tip or a body of revolution";
    } catch (const CadError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("naca.dihedral = '5': expected 0 ", 0), 0u) << e.what();
    }
  }
}

TEST(NacaParams, CodeMessageIsActionable) {
  try {
    naca_params_from(Params{{"naca.code", "00a2"}});
    FAIL();
  } catch (const CadError& e) {
    EXPECT_STREQ(e.what(), "naca.code = '00a2': expected 4 digits MPTT (e.g. 0012)");
  }
}

TEST(NacaParams, BoxOnlyMattersWithAFarField) {
  EXPECT_NO_THROW(naca_params_from(Params{{"naca.farfield", "false"}, {"naca.box", "0,0,5,1,1,6"}}));
  auto model = load_naca(Source{"", Params{{"naca.farfield", "false"}}});
  EXPECT_EQ(model->num_surfaces(), 4);  // upper, lower, te_base, tip
  EXPECT_FALSE(model->is_closed());     // open at the root without the wall
}

TEST(NacaParams, AFilePathIsRefused) {
  try {
    load_naca(Source{"wing.step", Params{}});
    FAIL();
  } catch (const CadError& e) {
    EXPECT_EQ(e.kind(), CadError::Kind::BadParameter);
    EXPECT_NE(std::string(e.what()).find("wing.step"), std::string::npos);
  }
}

TEST(NacaParams, CamberWithoutPositionIsFineWhenThereIsNoCamber) {
  EXPECT_NO_THROW(naca_params_from(Params{{"naca.code", "0412"}}));
  EXPECT_NO_THROW(naca_params_from(Params{{"naca.code", "2412"}}));
  EXPECT_NO_THROW(naca_params_from(Params{{"naca.code", "0001"}}));
}

}  // namespace
