// The apex of the pyramid over a skin quad.
#include "semimesh/farfield/detail/pyramid_apex.hpp"

#include "semimesh/farfield/far_field.hpp"
#include "semimesh/ho/validity.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace semimesh::farfield {
namespace {

using Eigen::Vector3d;

TEST(PyramidApex, SquareGetsItsApexAThirdOfAnEdgeAboveTheCentre) {
  // counter-clockwise seen from +z: the apex goes up
  const Vector3d apex = pyramid_apex({Vector3d(0, 0, 0), Vector3d(2, 0, 0), Vector3d(2, 2, 0), Vector3d(0, 2, 0)});
  EXPECT_NEAR((apex - Vector3d(1, 1, 0.6)).norm(), 0.0, 1e-12);
  const Vector3d down = pyramid_apex({Vector3d(0, 0, 0), Vector3d(0, 2, 0), Vector3d(2, 2, 0), Vector3d(2, 0, 0)});
  EXPECT_NEAR((down - Vector3d(1, 1, -0.6)).norm(), 0.0, 1e-12);
}

TEST(PyramidApex, ThinQuadGetsAFlatPyramid) {
  // 0.01 x 1: the apex 0.003 above, so that it leans less than 45 degrees over its long edges too
  const Vector3d apex = pyramid_apex({Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 0.01, 0), Vector3d(0, 0.01, 0)});
  EXPECT_NEAR((apex - Vector3d(0.5, 0.005, 0.003)).norm(), 0.0, 1e-12);
}

TEST(PyramidApex, ShearedParallelogramBetweenNeighboursStaysUnderItsCaps) {
  // Edges 1 and ~2.01, altitudes 0.2 and ~0.0995 (the wake block's underside behind a steep wake
  // direction): alone, 0.3 times the shorter edge above (leaning ~80 degrees over its long edges);
  // with right-angled neighbours over its long edges (caps tan 40.5 degrees), under those caps.
  const std::array<Vector3d, 4> quad{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(3, 0.2, 0), Vector3d(2, 0.2, 0)};
  EXPECT_NEAR(pyramid_apex(quad).z(), 0.3, 1e-12);
  const double cap = std::tan(0.45 * 3.14159265358979323846 / 2.0), altitude = 0.2 / std::hypot(2.0, 0.2);
  const Vector3d apex = pyramid_apex(quad, {1e300, cap, 1e300, cap});
  EXPECT_LE(apex.z(), cap * 0.5 * altitude + 1e-12);
  EXPECT_GT(apex.z(), 0.0);
}

TEST(PyramidApex, TwistedTrapezoidWithAShortEdgeGetsATallerApex) {
  // An H-type rear interface's lowest quad (a swept NACA 4412 behind its base): a 0.016 edge on the
  // trailing edge, 0.12 long sides, its corners 0.0075 off their mean plane. Heights from the short
  // edge (up to 0.019) are all invalid; about 0.07 over the centre is valid.
  const std::array<Vector3d, 4> quad{Vector3d(1.02003336, 0.00121949105, 0.115611525),
                                     Vector3d(1.11099088, 0.0747518669, 0.1),
                                     Vector3d(1.05315867, 0.115122563, 0.126466576),
                                     Vector3d(1.0227955, 0.00121539569, 0.131685306)};
  const Vector3d apex = pyramid_apex(quad);
  Eigen::MatrixX3d nodes(5, 3);
  for (int i = 0; i < 4; ++i) nodes.row(i) = quad[i].transpose();
  nodes.row(4) = apex.transpose();
  EXPECT_TRUE(ho::certify_jacobian(ho::Shape::Pyramid, 1, ho::NodeSet::Equispaced, nodes).valid);
  const Vector3d centre = 0.25 * (quad[0] + quad[1] + quad[2] + quad[3]);
  EXPECT_GT((apex - centre).norm(), 0.019);  // above the short edge's heights
  EXPECT_LT((apex - centre).norm(), 0.1);    // the lowest valid one found, below the long edges' length
}

TEST(PyramidApex, SlopeCapOverAnEdgeLowersTheApex) {
  // A 2 x 2 square (apex 0.6 uncapped): a neighbour closing in over edge 0 allows slope 0.3 there,
  // i.e. at most 0.3 above the centre, 1 from that edge: the ladder's next height, 0.3, is taken.
  const std::array<Vector3d, 4> square{Vector3d(0, 0, 0), Vector3d(2, 0, 0), Vector3d(2, 2, 0), Vector3d(0, 2, 0)};
  const Vector3d apex = pyramid_apex(square, {0.3, 1e300, 1e300, 1e300});
  EXPECT_NEAR((apex - Vector3d(1, 1, 0.3)).norm(), 0.0, 1e-12);
  // A cap below every height the ladder tries: the uncapped apex (TetGen checks it against the
  // neighbours).
  EXPECT_NEAR((pyramid_apex(square, {1e300, 1e300, 1e-4, 1e300}) - Vector3d(1, 1, 0.6)).norm(), 0.0, 1e-12);
}

TEST(PyramidApex, NonConvexQuadHasNoValidPyramid) {
  // an arrowhead: the corner (0.2, 0.2) is reflex, det J < 0 there whatever the apex height
  EXPECT_THROW(pyramid_apex({Vector3d(0, 0, 0), Vector3d(2, 0, 0), Vector3d(0.2, 0.2, 0), Vector3d(0, 2, 0)}),
               FarFieldError);
}

}  // namespace
}  // namespace semimesh::farfield
