// PyFR's importer limits, found before the user runs it: a pyramid on a parallelogram passes, one
// on a trapezoid (or a parallelogram moved by more than PyFR's 1e-10) does not; orders above 4.
#include "semimesh/pipeline/pyfr_limits.hpp"

#include <gtest/gtest.h>

namespace semimesh::pipeline {
namespace {

// One order-1 pyramid on the base (0,0,0) (1,0,0) (1+skew,1,0) (skew,1,0) with its apex above.
mesh::Mesh pyramid_on(double top_right_shift, double skew = 0.3) {
  mesh::Mesh m(1);
  std::vector<mesh::NodeId> v = {
      m.add_node({0, 0, 0}), m.add_node({1, 0, 0}), m.add_node({1 + skew + top_right_shift, 1, 0}),
      m.add_node({skew, 1, 0}), m.add_node({0.5, 0.5, 1})};
  m.add_element(ho::Shape::Pyramid, v);
  return m;
}

TEST(PyfrLimits, PyramidsOnParallelogramsPassAndOthersAreCounted) {
  EXPECT_EQ(pyramids_pyfr_refuses(pyramid_on(0.0)), 0u);
  EXPECT_EQ(pyramids_pyfr_refuses(pyramid_on(5e-11)), 0u) << "within PyFR's tolerance";
  EXPECT_EQ(pyramids_pyfr_refuses(pyramid_on(1e-9)), 1u);
  EXPECT_EQ(pyramids_pyfr_refuses(pyramid_on(0.2)), 1u) << "a trapezoid";
  EXPECT_TRUE(pyfr_refusals(pyramid_on(0.0)).empty());
  const std::vector<std::string> reasons = pyfr_refusals(pyramid_on(0.2));
  ASSERT_EQ(reasons.size(), 1u);
  EXPECT_NE(reasons[0].find("1 pyramid(s)"), std::string::npos) << reasons[0];
}

TEST(PyfrLimits, OrdersAboveFourAreNamed) {
  mesh::Mesh m(5);
  EXPECT_TRUE(pyfr_refusals(mesh::Mesh(4)).empty());
  const std::vector<std::string> reasons = pyfr_refusals(m);
  ASSERT_EQ(reasons.size(), 1u);
  EXPECT_NE(reasons[0].find("order 5"), std::string::npos) << reasons[0];
}

}  // namespace
}  // namespace semimesh::pipeline
