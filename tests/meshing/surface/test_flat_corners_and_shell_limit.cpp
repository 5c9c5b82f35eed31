// Surface meshes that curve into valid elements (issue #10): no triangle makes a smooth stretch of
// boundary its corner, and the shell thickness bounds the size where the body is curved.
#include "semimesh/surface/error.hpp"
#include "semimesh/surface/shell_size_limit.hpp"
#include "semimesh/surface/surface_mesh.hpp"
#include "wing_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include <map>
#include <regex>
#include <string>

namespace semimesh::surface {
namespace {

using testing::naca_model;
using testing::surface_named;

// Coarse, the tip's leading edge is the corner of a single triangle without the fix.
SizeParams coarse_sizes() {
  SizeParams p;
  p.max_size = 4.0;
  p.min_size = 0.04;
  p.curvature_segments = 4.0;
  p.le_size = 0.08;
  p.te_size = 0.05;
  return p;
}

TEST(FlatCorners, EveryBoundaryNodeOnASmoothStretchHasTwoTriangles) {
  for (const bool sharp : {false, true}) {
    SCOPED_TRACE(sharp ? "sharp TE" : "blunt TE");
    mock_cad::NacaWingParams params;
    params.sharp_te = sharp;
    params.taper = sharp ? 0.3 : 1.0;
    const auto model = mock_cad::make_naca_wing(params);
    const SizeField size(*model, coarse_sizes());
    const CurveMeshes curves = discretise_all_curves(*model, size);
    const int tip = surface_named(*model, "tip");
    const SurfaceMesh m = mesh_surface(*model, tip, curves, size);
    std::map<int, int> triangles_at;
    for (const auto& t : m.triangles)
      for (int v : t) ++triangles_at[v];
    // Smooth: inside a curve, or the leading-edge vertex where tip_upper and tip_lower meet
    // tangentially (the profile's nose). The trailing-edge corners are real corners.
    double nose_x = 1e300;
    for (const cad::Vec3& p : m.points) nose_x = std::min(nose_x, p.x());
    int checked = 0;
    for (int i = 0; i < m.num_nodes(); ++i) {
      const NodeOrigin& o = m.origin[i];
      if (!o.on_boundary()) continue;
      const bool nose = o.vertex >= 0 && m.points[i].x() == nose_x;
      if (o.vertex >= 0 && !nose) continue;
      EXPECT_GE(triangles_at[i], 2) << "boundary node " << i << " at (" << m.points[i].transpose() << ") curve " << o.curve << " vertex " << o.vertex;
      ++checked;
    }
    EXPECT_GT(checked, 4);
    // Still a conforming, (u, v)-positive triangulation.
    for (const auto& t : m.triangles) {
      const cad::Vec3 n = (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]);
      EXPECT_GT(n.dot(model->surface(tip).normal(m.uv[t[0]])), 0.0);
    }
  }
}

struct Remedies {
  double min_size = 0.0, thickness = 0.0;
};

// The values the refusal offers: "set sizing.min_size <= A or nearfield.thickness >= B".
Remedies remedies_of(const std::string& message) {
  std::smatch match;
  Remedies r;
  if (std::regex_search(message, match, std::regex(R"(sizing\.min_size <= ([0-9.e-]+))"))) r.min_size = std::stod(match[1]);
  if (std::regex_search(message, match, std::regex(R"(nearfield\.thickness >= ([0-9.e-]+))"))) r.thickness = std::stod(match[1]);
  return r;
}

std::vector<int> body_of(const cad::Model& model) {
  return {surface_named(model, "upper"), surface_named(model, "lower"), surface_named(model, "te_base"),
          surface_named(model, "tip")};
}

TEST(ShellSizeLimit, OnlyTheCurvedNoseLimitsAndAThickerShellAllowsMore) {
  const auto model = naca_model();
  const ShellSizing thin{0.02, body_of(*model), 0.5, 16}, thick{0.1, body_of(*model), 0.5, 16};
  const auto limits = shell_size_limits(*model, thin, 0.2, 0.03);
  ASSERT_FALSE(limits.empty());
  double smallest_thin = 1.0;
  for (const ShellSizeLimit& l : limits) {
    EXPECT_LT(l.point.x(), 0.3) << "the flat aft body needs no limit";
    smallest_thin = std::min(smallest_thin, l.size);
  }
  double smallest_thick = 1.0;
  for (const ShellSizeLimit& l : shell_size_limits(*model, thick, 0.2, 0.03)) smallest_thick = std::min(smallest_thick, l.size);
  EXPECT_GT(smallest_thick, smallest_thin);
  // The leading-edge radius of a NACA 0012 is 1.1019 t^2 = 0.0159 chord (Abbott & von Doenhoff).
  double nose_radius = 1.0;
  for (const ShellSizeLimit& l : limits) nose_radius = std::min(nose_radius, l.radius);
  EXPECT_NEAR(nose_radius, 1.1019 * 0.12 * 0.12, 2e-4);
}

TEST(ShellSizeLimit, ProgressRisesToOneAndDoesNotChangeTheLimits) {
  const auto model = naca_model();
  const ShellSizing thin{0.02, body_of(*model), 0.5, 16};
  std::vector<double> fractions;
  const auto reported = shell_size_limits(*model, thin, 0.2, 0.03, [&](double f, const std::string& step) {
    EXPECT_EQ(step, "shell limits");
    fractions.push_back(f);
  });
  const auto silent = shell_size_limits(*model, thin, 0.2, 0.03);
  ASSERT_EQ(reported.size(), silent.size());
  for (std::size_t i = 0; i < silent.size(); ++i) EXPECT_EQ(reported[i].size, silent[i].size);
  ASSERT_GE(fractions.size(), 10u) << "one report per few sample rows, over 4 surfaces";
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0);
}

TEST(ShellSizeLimit, RefusalNamesThePlaceAndEachRemedyItOffersWorks) {
  const auto model = naca_model();
  SizeParams sizing = coarse_sizes();
  sizing.min_size = 0.03;
  const ShellSizing shell{0.02, body_of(*model), 0.5, 16};
  std::string message;
  try {
    shell_size_sources(*model, shell, sizing);
    FAIL() << "min_size 0.03 over a 0.02 shell on a 0.016 nose must be refused";
  } catch (const SurfaceMeshError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("('leading_edge')"), std::string::npos) << message;
  EXPECT_NE(message.find("sizing.min_size = 0.03 forbids it"), std::string::npos) << message;
  const Remedies r = remedies_of(message);
  ASSERT_GT(r.min_size, 0.0) << message;
  ASSERT_GT(r.thickness, 0.0) << message;
  EXPECT_LT(r.min_size, sizing.min_size);
  EXPECT_GT(r.thickness, shell.thickness);

  SizeParams smaller = sizing;
  smaller.min_size = r.min_size;
  EXPECT_NO_THROW(shell_size_sources(*model, shell, smaller));
  ShellSizing thicker = shell;
  thicker.thickness = r.thickness;
  EXPECT_NO_THROW(shell_size_sources(*model, thicker, sizing));
  // Sources ask for no more than the refusal said was needed, and never below it at the nose.
  for (const PointSource& s : shell_size_sources(*model, shell, smaller)) EXPECT_GE(s.size, r.min_size);
}

}  // namespace
}  // namespace semimesh::surface
