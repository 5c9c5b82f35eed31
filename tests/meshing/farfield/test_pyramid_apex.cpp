// The apex of the pyramid over a skin quad.
#include "pyramid_apex.hpp"

#include "semimesh/farfield/far_field.hpp"

#include <gtest/gtest.h>

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

TEST(PyramidApex, NonConvexQuadHasNoValidPyramid) {
  // an arrowhead: the corner (0.2, 0.2) is reflex, det J < 0 there whatever the apex height
  EXPECT_THROW(pyramid_apex({Vector3d(0, 0, 0), Vector3d(2, 0, 0), Vector3d(0.2, 0.2, 0), Vector3d(0, 2, 0)}),
               FarFieldError);
}

}  // namespace
}  // namespace semimesh::farfield
