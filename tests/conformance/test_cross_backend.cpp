// The OCC-built NACA wing is the analytic one: every OCC face lies on the analytic face of the
// same name within 1e-7 chord.
#include "sampling.hpp"

#include "semimesh/mock_cad/naca.hpp"
#include "semimesh/occ/occ_backend.hpp"

#include <gtest/gtest.h>

namespace conformance {
namespace {

TEST(CrossBackend, OccWingFacesLieOnTheAnalyticFaces) {
  const semimesh::cad::Params params{{"naca.code", "0012"}, {"naca.span", "2"}};
  auto analytic = semimesh::mock_cad::load_naca(semimesh::cad::Source{"", params});
  auto occ = semimesh::occ::load_occ(semimesh::cad::Source{"", params});
  ASSERT_EQ(occ->num_surfaces(), analytic->num_surfaces());
  const double chord = 1.0;
  for (int s = 0; s < occ->num_surfaces(); ++s) {
    const auto& face = occ->surface(s);
    EXPECT_EQ(face.name(), analytic->surface(s).name()) << "surface " << s << ": same id order expected";
    auto twin = analytic->find_surface(face.name());
    ASSERT_TRUE(twin.has_value()) << "no analytic surface named '" << face.name() << "'";
    const auto samples = inside_samples(face, 6, 0.01);
    ASSERT_FALSE(samples.empty()) << face.name();
    double worst = 0.0;
    for (const Vec2& uv : samples) worst = std::max(worst, analytic->surface(*twin).project(face.point(uv)).distance);
    EXPECT_LE(worst, 1e-7 * chord) << "surface '" << face.name() << "'";
  }
}

}  // namespace
}  // namespace conformance
