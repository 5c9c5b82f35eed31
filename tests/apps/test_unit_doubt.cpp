// doubt_unit: a declared unit that puts a wing's root chord outside 5 cm .. 100 m is doubted, and
// the unit putting it nearest the middle of that range (in ratio) offered.
#include "unit_doubt.hpp"

#include <gtest/gtest.h>

namespace semimesh::app {
namespace {

TEST(UnitDoubt, PlausibleChordsAreTakenAsDeclared) {
  EXPECT_FALSE(doubt_unit(810.0, "mm"));  // the ONERA M6's root chord
  EXPECT_FALSE(doubt_unit(13.0, "in"));   // 0.33 m: a model wing
  EXPECT_FALSE(doubt_unit(4.5, "m"));
  EXPECT_FALSE(doubt_unit(1.0, "chord"));  // a generated wing: no length unit
  EXPECT_FALSE(doubt_unit(1.0, ""));
}

TEST(UnitDoubt, MetreNumbersUnderAnInchFlagAreDoubted) {
  const std::optional<UnitDoubt> doubt = doubt_unit(1.0, "in");  // 25 mm: no wing
  ASSERT_TRUE(doubt);
  EXPECT_EQ(doubt->likelier, "m");
  EXPECT_NE(doubt->why.find("0.0254 m"), std::string::npos) << doubt->why;
}

TEST(UnitDoubt, MillimetreNumbersUnderAMetreFlagAreDoubted) {
  const std::optional<UnitDoubt> doubt = doubt_unit(810.0, "m");  // 810 m
  ASSERT_TRUE(doubt);
  EXPECT_EQ(doubt->likelier, "mm");
}

}  // namespace
}  // namespace semimesh::app
