// A model with free curves (faces not sewn) is refused with the curves named; the unit a file
// declares and the one geometry.units sets, each with its reason. On the shared NekMesh STEP wing,
// whose box faces are separate in the file (its README) and join only when sewn.
#include "semimesh/pipeline/closed_model.hpp"

#include "semimesh/backends/builtin.hpp"
#include "semimesh/cad/error.hpp"
#include "semimesh/pipeline/config.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace semimesh::pipeline {
namespace {

std::string nekmesh_wing() { return std::string(SEMIMESH_TESTDATA_DIR) + "/cad/nektar_3d_bl_wing_naca0012.stp"; }

std::unique_ptr<cad::Model> load(cad::Params params) {
  return backends::default_registry().load("occ", cad::Source{nekmesh_wing(), std::move(params)});
}

#define SKIP_WITHOUT_FILE()                                   \
  if (!std::filesystem::exists(nekmesh_wing()))               \
  GTEST_SKIP() << nekmesh_wing() << " not found (see shared/testdata/cad/README.md)"

TEST(ClosedModel, UnsewnFacesAreRefusedNamingTheirFreeCurves) {
  SKIP_WITHOUT_FILE();
  const auto sewn = load({});
  EXPECT_TRUE(free_curves(*sewn).empty());
  EXPECT_NO_THROW(require_closed(*sewn, std::nullopt));

  const auto unsewn = load({{"occ.sew", "false"}});
  const std::vector<int> free = free_curves(*unsewn);
  ASSERT_FALSE(free.empty());
  for (int c : free) EXPECT_EQ(unsewn->surfaces_of_curve(c).size(), 1u);
  try {
    require_closed(*unsewn, 0.5);
    ADD_FAILURE() << "an unsewn model passed";
  } catch (const ConfigError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(std::to_string(free.size()) + " free curve(s)"), std::string::npos) << m;
    EXPECT_NE(m.find("geometry.sew_tolerance = 0.5"), std::string::npos) << m;
    EXPECT_NE(m.find("curve " + std::to_string(free.front()) + " ('" + unsewn->curve(free.front()).name() + "') of surface"),
              std::string::npos)
        << m;
  }
}

TEST(ClosedModel, TheUnitIsTheFilesUnlessSetAndSaysWhy) {
  SKIP_WITHOUT_FILE();
  const auto declared = load({});
  EXPECT_EQ(declared->units(), "mm");  // the file's header: SI_UNIT(.MILLI.,.METRE.)
  EXPECT_NE(declared->units_origin().find("declared by the file (STEP length unit"), std::string::npos)
      << declared->units_origin();
  const auto overridden = load({{"occ.units", "in"}});
  EXPECT_EQ(overridden->units(), "in");
  EXPECT_NE(overridden->units_origin().find("the file declares mm"), std::string::npos) << overridden->units_origin();
  // The numbers stay as written: only what they are called changes.
  EXPECT_NEAR((overridden->bbox().hi - declared->bbox().hi).norm(), 0.0, 1e-9 * declared->bbox().diagonal());
  try {
    load({{"occ.units", "furlong"}});
    ADD_FAILURE() << "an unknown unit passed";
  } catch (const cad::CadError& e) {
    EXPECT_NE(std::string(e.what()).find("'occ.units' = 'furlong': unknown length unit (known: mm, cm, m"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace semimesh::pipeline
