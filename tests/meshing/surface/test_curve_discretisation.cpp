#include "semimesh/surface/curve_discretisation.hpp"
#include "semimesh/surface/error.hpp"
#include "wing_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace semimesh::surface {
namespace {

using testing::curve_named;
using testing::naca_model;

SizeParams curve_sizes() {
  SizeParams p;
  p.max_size = 0.5;
  p.min_size = 0.005;
  p.curvature_segments = 2.0;
  p.gradation = 1.2;
  return p;
}

std::vector<double> segment_lengths(const CurveMesh& m) {
  std::vector<double> out;
  for (int k = 0; k < m.segments(); ++k) out.push_back((m.points[k + 1] - m.points[k]).norm());
  return out;
}

TEST(CurveMesh, EveryCurveEndsExactlyAtItsVertices) {
  auto model = naca_model();
  SizeField size(*model, curve_sizes());
  const CurveMeshes meshes = discretise_all_curves(*model, size);
  ASSERT_EQ(meshes.size(), model->num_curves());
  for (int c = 0; c < model->num_curves(); ++c) {
    const CurveMesh& m = meshes.at(c);
    const auto range = model->curve(c).bounds();
    const auto ends = model->curve_vertices(c);
    EXPECT_EQ(m.t.front(), range.lo) << model->curve(c).name();
    EXPECT_EQ(m.t.back(), range.hi) << model->curve(c).name();
    EXPECT_EQ(m.points.front(), model->vertex(ends[0]).point) << model->curve(c).name();
    EXPECT_EQ(m.points.back(), model->vertex(ends[1]).point) << model->curve(c).name();
    for (int k = 0; k < m.segments(); ++k) EXPECT_LT(m.t[k], m.t[k + 1]);
    for (int k = 1; k < m.segments(); ++k)
      EXPECT_LT((m.points[k] - model->curve(c).point(m.t[k])).norm(), 1e-12);
  }
}

TEST(CurveMesh, SegmentsFollowTheSizeField) {
  auto model = naca_model();
  SizeField size(*model, curve_sizes());
  for (const char* name : {"root_upper", "root_lower", "leading_edge", "box_ymin_zmin", "te_upper"}) {
    const int c = curve_named(*model, name);
    const CurveMesh m = discretise_curve(*model, c, size);
    const auto lengths = segment_lengths(m);
    for (int k = 0; k < m.segments(); ++k) {
      // The target at the chord midpoint, which lies off a curved curve: project it back on.
      const double t_mid = model->curve(c).project(0.5 * (m.points[k] + m.points[k + 1])).t;
      const double target = size(model->curve(c).point(t_mid));
      EXPECT_GT(lengths[k], target / 1.5) << name << " segment " << k;
      EXPECT_LT(lengths[k], target * 1.5) << name << " segment " << k;
    }
  }
}

TEST(CurveMesh, UniformSizeGivesLengthOverSize) {
  auto model = naca_model();
  SizeParams p;
  p.max_size = 0.5;
  p.curvature_segments = 0.0;
  SizeField size(*model, p);
  const CurveMesh m = discretise_curve(*model, curve_named(*model, "box_ymin_zmin"), size);  // x from -10 to 11
  EXPECT_EQ(m.segments(), 42);
  for (double l : segment_lengths(m)) EXPECT_NEAR(l, 0.5, 1e-9);
  EXPECT_EQ(discretise_curve(*model, curve_named(*model, "root_te"), size, 3).segments(), 3);  // min_segments
}

TEST(CurveMesh, LeadingEdgeClustering) {
  auto model = naca_model();
  SizeParams p;
  p.max_size = 0.2;
  p.min_size = 0.001;
  p.curvature_segments = 0.0;
  p.gradation = 1.15;
  p.le_size = 0.004;
  p.te_size = 0.0;  // only the leading edge clusters
  SizeField size(*model, p);
  const CurveMesh m = discretise_curve(*model, curve_named(*model, "root_upper"), size);
  const auto lengths = segment_lengths(m);
  EXPECT_LT(lengths.front(), 0.004 * 1.5);
  EXPECT_GT(lengths.back(), 0.1);
  EXPECT_LT(lengths.back(), 0.2 * 1.5);
  // Growth between neighbours stays near the gradation.
  for (std::size_t k = 1; k < lengths.size(); ++k) EXPECT_LT(lengths[k] / lengths[k - 1], 1.3) << k;
  // Without the source the LE segment is much longer.
  p.le_size = 0.0;
  SizeField coarse(*model, p);
  EXPECT_GT(segment_lengths(discretise_curve(*model, curve_named(*model, "root_upper"), coarse)).front(), 0.1);
}

TEST(CurveMesh, PrescribedCountsAndBunchingLaws) {
  auto model = naca_model();
  const int c = curve_named(*model, "box_xmin_ymin");  // z from 0 to 10, a straight line
  const double L = 10.0;

  const auto uniform = segment_lengths(discretise_curve(*model, c, CurveCount{10, {}}));
  ASSERT_EQ(uniform.size(), 10u);
  for (double l : uniform) EXPECT_NEAR(l, 1.0, 1e-12);

  const auto geometric = segment_lengths(discretise_curve(*model, c, CurveCount{5, {Bunching::Law::Geometric, 2.0}}));
  ASSERT_EQ(geometric.size(), 5u);
  EXPECT_NEAR(geometric[0], L / 31.0, 1e-12);  // 1 + 2 + 4 + 8 + 16 = 31
  for (int k = 1; k < 5; ++k) EXPECT_NEAR(geometric[k] / geometric[k - 1], 2.0, 1e-9);

  for (Bunching::Law law : {Bunching::Law::Tanh, Bunching::Law::Cosine}) {
    const auto two_sided = segment_lengths(discretise_curve(*model, c, CurveCount{8, {law, 2.0}}));
    ASSERT_EQ(two_sided.size(), 8u);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(two_sided[k], two_sided[7 - k], 1e-9);  // symmetric
    EXPECT_LT(two_sided[0], 0.5 * two_sided[3]);                                     // clustered at the ends
  }
  // Cosine: 0.5 (1 - cos(pi/8)) of the length for the first segment.
  const auto cosine = segment_lengths(discretise_curve(*model, c, CurveCount{8, {Bunching::Law::Cosine, 0.0}}));
  EXPECT_NEAR(cosine[0], L * 0.5 * (1.0 - std::cos(M_PI / 8.0)), 1e-9);
}

TEST(CurveMesh, RejectsInvalidCounts) {
  auto model = naca_model();
  EXPECT_THROW(discretise_curve(*model, 0, CurveCount{0, {}}), SurfaceMeshError);
  EXPECT_THROW(discretise_curve(*model, 0, CurveCount{4, {Bunching::Law::Geometric, -1.0}}), SurfaceMeshError);
  EXPECT_THROW(discretise_curve(*model, model->num_curves(), CurveCount{4, {}}), SurfaceMeshError);
  EXPECT_THROW(CurveMeshes{}.at(0), SurfaceMeshError);
}

}  // namespace
}  // namespace semimesh::surface
