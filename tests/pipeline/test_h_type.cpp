// The H-type near field end to end (semimesh run as a library): the wing layer ends at the
// squared-off trailing edge, the wake block of hexes behind it stands a gap above the wall layer,
// and the far field fills the gap. Conformity, volume and proven validity from the run's own checks;
// the wake's layer ratios and its gap measured here on the mesh's vertices.
#include "semimesh/backends/builtin.hpp"
#include "semimesh/pipeline/pipeline.hpp"

#include <gtest/gtest.h>

#include "highorder/mesh/same_entities.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>
#include "temp_path.hpp"

namespace semimesh::pipeline {
namespace {

namespace fs = std::filesystem;

// The coarse case of the CLI tests (unit-span wing, 7 x 6 x 3 chord box, 0.05 chord shell), H-type.
const char* const kCoarseH = R"(
[geometry.naca]
span = 1.0
box = [-3.0, -3.0, 0.0, 4.0, 3.0, 3.0]
[nearfield]
topology = "H"
thickness = 0.05
[wall_layer]
thickness = 0.04
layers = 3
[wake]
length = 1.5
layers = 12
growth = 1.15
gap = 0.1
[sizing]
max_size = 1.0
min_size = 0.02
curvature_segments = 2
le_size = 0.06
te_size = 0.03
[farfield]
box_size = 1.0
wall_size = 0.6
[highorder]
order = 1
[boundary_layer]
layers = 1
[output]
formats = ["msh41"]
basename = "h"
)";

class Silent : public Progress {
 public:
  void stage_started(const std::string&) override {}
  void stage_finished(const StageTiming&) override {}
};

fs::path fresh_directory(const std::string& name) {
  const fs::path dir = semimesh::test::temp_path("h_type_" + name);
  fs::remove_all(dir);
  return dir;
}

RunResult run_h(const std::string& name, const std::vector<std::string>& overrides) {
  Config c = parse_config(kCoarseH, "h.toml", {}, overrides);
  c.output.directory = fresh_directory(name).string();
  Silent progress;
  return run(c, progress);
}

void expect_valid_conforming(const RunResult& r, const std::string& what) {
  EXPECT_EQ(r.conformity.problems.size(), 0u) << what;
  EXPECT_EQ(r.validity.invalid, 0) << what;
  EXPECT_LT(r.volume.mesh.boundary_relative_error(), 1e-9) << what;
  EXPECT_LT(r.volume.expected_relative_error(), std::max(1e-6, r.expected_volume_tolerance)) << what;
  for (const char* region : {"wing_layer", "junction", "wall_layer", "wake", "farfield"}) {
    ASSERT_TRUE(r.elements_by_region.count(region)) << what << ": " << region;
    EXPECT_GT(r.validity.min_scaled_jacobian_by_region.at(region), 0.0) << what << ": " << region;
  }
  EXPECT_GT(r.wake.hexes, 0) << what;
  EXPECT_GT(r.elements_by_type.at("pyramid"), 0u) << what;
  EXPECT_TRUE(r.checks_passed()) << what;
}

// Element vertices (not high-order nodes) of one region.
std::vector<Eigen::Vector3d> region_vertices(const mesh::Mesh& m, const std::string& region) {
  const auto it = std::find(m.region_names().begin(), m.region_names().end(), region);
  std::vector<char> seen(m.num_nodes(), 0);
  std::vector<Eigen::Vector3d> out;
  for (const mesh::Element& e : m.elements()) {
    if (e.region != it - m.region_names().begin()) continue;
    for (int v = 0; v < ho::num_vertices(e.shape); ++v)
      if (!seen[e.vertices[v]]) seen[e.vertices[v]] = 1, out.push_back(m.node(e.vertices[v]));
  }
  return out;
}

// Consecutive distances between the points of `cloud` on the segment a -> b, from a.
std::vector<double> gaps_on_segment(const std::vector<Eigen::Vector3d>& cloud, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = (b - a).normalized();
  const double length = (b - a).norm();
  std::vector<double> t;
  for (const Eigen::Vector3d& x : cloud) {
    const double along = (x - a).dot(u);
    if (along > -1e-9 && along < length + 1e-9 && (x - a - along * u).norm() < 1e-9) t.push_back(along);
  }
  std::sort(t.begin(), t.end());
  std::vector<double> gaps;
  for (std::size_t k = 0; k + 1 < t.size(); ++k) gaps.push_back(t[k + 1] - t[k]);
  return gaps;
}

TEST(HTypeEndToEnd, LinearMeshOnTheBluntWing) {
  const RunResult r = run_h("linear", {});
  expect_valid_conforming(r, "linear");
  // 12 streamwise cells over every cross-section quad above the gap.
  EXPECT_EQ(r.wake.hexes % 12, 0);
  EXPECT_EQ(r.wake.streamwise_cells, 12);
  EXPECT_EQ(r.wake.length, 1.5);
}

// The paper's split: the wake continues the wing's N layers with the ratio r at the trailing edge,
// falling linearly to ratio_end at the far end; the block stands at least `gap` above the wall layer.
TEST(HTypeEndToEnd, CurvedAndSplitWakeRatiosAndGapMeasured) {
  const RunResult r = run_h("split", {"highorder.order=2", "boundary_layer.layers=4", "boundary_layer.ratio=2",
                                      "wake.ratio_end=1.3"});
  expect_valid_conforming(r, "order 2");
  // The weld renamed and joined the split's entities (Mesh::replace_nodes): they are the ones a
  // fresh build of the same node lists makes, id for id.
  test::expect_same_entities(r.mesh, test::built_afresh(r.mesh));
  const std::vector<Eigen::Vector3d> wake = region_vertices(r.mesh, "wake");

  // The upper trailing-edge vertex nearest mid-span, its layer offset at the trailing edge.
  double row = 1e300;
  for (const Eigen::Vector3d& x : wake)
    if (std::abs(x.x() - 1.0) < 1e-9 && std::abs(x.z() - 0.5) < std::abs(row - 0.5)) row = x.z();
  Eigen::Vector3d a(0, -1, 0);
  for (const Eigen::Vector3d& x : wake)
    if (std::abs(x.x() - 1.0) < 1e-9 && x.z() == row && x.y() > a.y()) a = x;
  ASSERT_GT(a.y(), 0.0);
  Eigen::Vector3d top = a;  // the layer's outer vertex above a (its normal may lean a little spanwise)
  for (const Eigen::Vector3d& x : wake)
    if (std::abs(x.z() - a.z()) < 0.005 && x.x() < 1.0 + 0.04 && x.y() > top.y()) top = x;
  EXPECT_NEAR((top - a).norm(), 0.05, 1e-6);

  const std::vector<double> at_te = gaps_on_segment(wake, a, top);
  ASSERT_EQ(at_te.size(), 4u);
  for (std::size_t k = 1; k < at_te.size(); ++k) EXPECT_NEAR(at_te[k] / at_te[k - 1], 2.0, 1e-6) << k;
  const Eigen::Vector3d far(1.5, 0.0, 0.0);
  const std::vector<double> at_end = gaps_on_segment(wake, a + far, top + far);
  ASSERT_EQ(at_end.size(), 4u);
  for (std::size_t k = 1; k < at_end.size(); ++k) EXPECT_NEAR(at_end[k] / at_end[k - 1], 1.3, 1e-6) << k;

  double lowest = 1e300;
  for (const Eigen::Vector3d& x : wake) lowest = std::min(lowest, x.z());
  EXPECT_GE(lowest, 0.04 + 0.1 - 1e-9);
  EXPECT_LT(lowest, 0.04 + 0.1 + 0.05);  // the next trailing-edge row (te_size 0.03)
  EXPECT_NEAR(r.wake.gap, lowest - 0.04, 1e-12);
  EXPECT_EQ(r.wake.ratio_first, 2.0);
  EXPECT_EQ(r.wake.ratio_last, 1.3);
}

struct Variant {
  std::string name;
  std::vector<std::string> overrides;
};

class HTypeVariants : public ::testing::TestWithParam<Variant> {};

TEST_P(HTypeVariants, ConformingValidMeshWithTheRightVolume) {
  const Variant& v = GetParam();
  if (std::find(v.overrides.begin(), v.overrides.end(), "geometry.backend=occ") != v.overrides.end() &&
      !backends::default_registry().available("occ"))
    GTEST_SKIP() << "no OCC backend in this build";
  std::vector<std::string> all = v.overrides;
  all.push_back("boundary_layer.layers=3");
  expect_valid_conforming(run_h(v.name, all), v.name);
}

INSTANTIATE_TEST_SUITE_P(
    Wings, HTypeVariants,
    ::testing::Values(Variant{"cambered_4412", {"geometry.naca.code=\"4412\""}},
                      Variant{"swept_tapered", {"geometry.naca.taper=0.6", "geometry.naca.sweep=20"}},
                      Variant{"incidence_10_degrees", {"wake.direction=[0.9848, 0.1736, 0.0]"}},
                      Variant{"widening_5_degrees", {"wake.widening=5"}},
                      Variant{"incidence_10_widening_10", {"wake.direction=[0.9848, 0.1736, 0.0]", "wake.widening=10"}},
                      // the swept edge's root leaves the wake's origins behind: the ratio must still be r there
                      Variant{"sharp_swept_tapered", {"geometry.naca.te=sharp", "geometry.naca.taper=0.6", "geometry.naca.sweep=20"}},
                      Variant{"sharp_cambered_4412", {"geometry.naca.te=sharp", "geometry.naca.code=\"4412\""}},
                      // swept back: the strip top's legs to the two halos open by more than 180 degrees
                      Variant{"sharp_swept_back", {"geometry.naca.te=sharp", "geometry.naca.sweep=20"}},
                      // the rounded tip: the base capped by a half disc (flat corners), a pole at the tip's LE
                      Variant{"round_tip", {"geometry.naca.tip=\"round\""}},
                      Variant{"round_tip_sharp_swept_tapered",
                              {"geometry.naca.tip=\"round\"", "geometry.naca.te=sharp", "geometry.naca.taper=0.6",
                               "geometry.naca.sweep=20"}}),
    [](const ::testing::TestParamInfo<Variant>& info) { return info.param.name; });

void expect_same_mesh(const RunResult& analytic, const RunResult& occ) {
  expect_valid_conforming(occ, "occ");
  for (const char* region : {"wing_layer", "junction", "wake"})
    EXPECT_EQ(occ.elements_by_region.at(region), analytic.elements_by_region.at(region)) << region;
  EXPECT_EQ(occ.wake.hexes, analytic.wake.hexes);
  EXPECT_NEAR(occ.wake.gap, analytic.wake.gap, 1e-6);
  const std::vector<Eigen::Vector3d> a = region_vertices(analytic.mesh, "wake"), o = region_vertices(occ.mesh, "wake");
  ASSERT_EQ(a.size(), o.size());
  double worst = 0.0;  // every wake vertex of one has a counterpart in the other
  for (const Eigen::Vector3d& x : o) {
    double nearest = 1e300;
    for (const Eigen::Vector3d& y : a) nearest = std::min(nearest, (x - y).norm());
    worst = std::max(worst, nearest);
  }
  EXPECT_LT(worst, 1e-5);
}

TEST(HTypeEndToEnd, OccWingGivesTheAnalyticWingsMesh) {
  if (!backends::default_registry().available("occ")) GTEST_SKIP() << "no OCC backend in this build";
  expect_same_mesh(run_h("analytic", {"boundary_layer.layers=3"}),
                   run_h("occ", {"geometry.backend=occ", "boundary_layer.layers=3"}));
}

// Wake hexes standing on the sheet: faces with their four vertices in the plane through the
// straight trailing edge (x = 1, y = 0, along z) and the wake direction d (in the xy plane). Each
// sheet face with the side (sign of the hex's mean distance to the plane) of each hex using it;
// every wake hex counted in `hexes`.
std::map<std::vector<mesh::NodeId>, std::vector<double>> sheet_faces(const mesh::Mesh& m, const Eigen::Vector3d& d,
                                                                      int& hexes) {
  const auto region = std::find(m.region_names().begin(), m.region_names().end(), "wake") - m.region_names().begin();
  const Eigen::Vector3d normal = Eigen::Vector3d(-d.y(), d.x(), 0.0).normalized();
  auto across = [&](const Eigen::Vector3d& x) { return (x - Eigen::Vector3d(1, 0, 0)).dot(normal); };
  std::map<std::vector<mesh::NodeId>, std::vector<double>> sheet;
  hexes = 0;
  for (const mesh::Element& e : m.elements()) {
    if (e.region != region) continue;
    ++hexes;
    double side = 0.0;
    for (int k = 0; k < 8; ++k) side += across(m.node(e.vertices[k])) / 8.0;
    for (const std::vector<int>& f : ho::faces(ho::Shape::Hexahedron)) {
      std::vector<mesh::NodeId> v;
      for (int k : f)
        if (std::abs(across(m.node(e.vertices[k]))) < 1e-9) v.push_back(e.vertices[k]);
      if (v.size() != 4) continue;
      std::sort(v.begin(), v.end());
      sheet[v].push_back(side);
    }
  }
  return sheet;
}

// Sharp trailing edge (no base): the upper and lower wing layers end on the trailing edge with
// their own normals, their rear interfaces swept into wake hexes on either side of the sheet
// (the trailing edge swept), which both sides share face for face. Curved (order 2) and split
// (the junction's wedge between the root's two halos cut at the split's interfaces and welded), at
// incidence too; the wake ratios r at the trailing edge and ratio_end at the far end measured on
// the upper layer's edge at mid-span; the OCC-built sharp wing gives the same mesh.
TEST(HTypeEndToEnd, SharpTrailingEdgeWakeSheetSharedByBothSides) {
  for (const auto& [name, d] : std::vector<std::pair<std::string, Eigen::Vector3d>>{
           {"sharp", Eigen::Vector3d(1, 0, 0)}, {"sharp_incidence", Eigen::Vector3d(0.9848, 0.1736, 0.0)}}) {
    const RunResult r = run_h(name, {"geometry.naca.te=sharp", "highorder.order=2", "boundary_layer.layers=4",
                                     "boundary_layer.ratio=2", "wake.ratio_end=1.3",
                                     "wake.direction=[" + std::to_string(d.x()) + ", " + std::to_string(d.y()) + ", 0.0]"});
    expect_valid_conforming(r, name);
    test::expect_same_entities(r.mesh, test::built_afresh(r.mesh));  // the weld's, as in the blunt case
    int hexes = 0;
    const auto sheet = sheet_faces(r.mesh, d.normalized(), hexes);
    EXPECT_EQ(hexes, 4 * r.wake.hexes) << name;  // split into the wing's 4 layers
    EXPECT_EQ(r.wake.hexes % 12, 0) << name;
    EXPECT_EQ(2 * sheet.size(), static_cast<std::size_t>(r.wake.hexes)) << name;  // each stands on the sheet
    for (const auto& [face, sides] : sheet) {
      ASSERT_EQ(sides.size(), 2u) << name;
      EXPECT_LT(std::min(sides[0], sides[1]), 0.0) << name;
      EXPECT_GT(std::max(sides[0], sides[1]), 0.0) << name;
    }
    const std::vector<Eigen::Vector3d> wake = region_vertices(r.mesh, "wake");
    double lowest = 1e300;
    for (const Eigen::Vector3d& x : wake) lowest = std::min(lowest, x.z());
    EXPECT_GE(lowest, 0.04 + 0.1 - 1e-9) << name;
    EXPECT_NEAR(r.wake.gap, lowest - 0.04, 1e-12) << name;
    if (d.y() != 0.0) continue;
    // The trailing-edge node nearest mid-span, its upper offset (the farthest wake vertex above it
    // in the layer's first cell row), the split's interfaces between them and 1.5 downstream.
    double row = 1e300;
    for (const Eigen::Vector3d& x : wake)
      if (std::abs(x.x() - 1.0) < 1e-9 && std::abs(x.y()) < 1e-9 && std::abs(x.z() - 0.5) < std::abs(row - 0.5)) row = x.z();
    const Eigen::Vector3d a(1.0, 0.0, row);
    Eigen::Vector3d top = a;
    for (const Eigen::Vector3d& x : wake)
      if (std::abs(x.z() - row) < 1e-4 && x.x() < 1.0 + 0.04 && x.y() > top.y()) top = x;
    EXPECT_NEAR((top - a).norm(), 0.05, 1e-6) << name;
    const std::vector<double> at_te = gaps_on_segment(wake, a, top);
    ASSERT_EQ(at_te.size(), 4u) << name;
    for (std::size_t k = 1; k < at_te.size(); ++k) EXPECT_NEAR(at_te[k] / at_te[k - 1], 2.0, 1e-6) << k;
    const Eigen::Vector3d far(1.5, 0.0, 0.0);
    const std::vector<double> at_end = gaps_on_segment(wake, a + far, top + far);
    ASSERT_EQ(at_end.size(), 4u) << name;
    for (std::size_t k = 1; k < at_end.size(); ++k) EXPECT_NEAR(at_end[k] / at_end[k - 1], 1.3, 1e-6) << k;
  }
  if (!backends::default_registry().available("occ")) GTEST_SKIP() << "no OCC backend in this build";
  expect_same_mesh(run_h("sharp_analytic", {"geometry.naca.te=sharp", "boundary_layer.layers=3"}),
                   run_h("sharp_occ", {"geometry.naca.te=sharp", "geometry.backend=occ", "boundary_layer.layers=3"}));
}

// Widening at incidence: mid-span, the block's cross-flow thickness (across the sheet, the plane
// through the trailing edge and the wake direction) grows by 2 length tan(widening) from the
// trailing edge to the far end (measured on the mesh's wake vertices of one trailing-edge row).
TEST(HTypeEndToEnd, WideningAtIncidenceGrowsTheCrossFlowThickness) {
  const Eigen::Vector3d d = Eigen::Vector3d(0.9848, 0.1736, 0.0).normalized();
  const RunResult r = run_h("widening", {"wake.direction=[0.9848, 0.1736, 0.0]", "wake.widening=10"});
  expect_valid_conforming(r, "widening");
  const std::vector<Eigen::Vector3d> wake = region_vertices(r.mesh, "wake");
  double row = 1e300;
  for (const Eigen::Vector3d& x : wake)
    if (std::abs(x.x() - 1.0) < 1e-9 && std::abs(x.z() - 0.5) < std::abs(row - 0.5)) row = x.z();
  const Eigen::Vector3d te(1.0, 0.0, row), normal(-d.y(), d.x(), 0.0);
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};  // across the sheet: [0] at the trailing edge, [1] at the far end
  for (const Eigen::Vector3d& x : wake) {
    if (std::abs(x.z() - row) > 1e-4) continue;  // the row's offsets (their normals lean a little spanwise)
    const double along = (x - te).dot(d), across = (x - te).dot(normal);
    const int end = along < 0.03 ? 0 : along > 1.5 - 0.15 ? 1 : -1;
    if (end < 0) continue;
    lo[end] = std::min(lo[end], across), hi[end] = std::max(hi[end], across);
  }
  ASSERT_LT(lo[1], hi[1]) << row;
  EXPECT_NEAR((hi[1] - lo[1]) - (hi[0] - lo[0]), 2.0 * 1.5 * std::tan(10.0 * 3.14159265358979323846 / 180.0), 1e-6);
}

// Bad H-type input: a BadInput RunError naming the key and value, and no file written.
TEST(HTypeEndToEnd, BadInputNamesTheKeyAndWritesNothing) {
  const std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> cases = {
      {{"wake.length=20"}, {"wake.length = 20", "leaves the far-field box"}},
      {{"wake.gap=5"}, {"wake.gap = 5", "tip"}},
      {{"wake.direction=[-1.0, 0.0, 0.0]"}, {"wake.direction = [-1, 0, 0]", "upstream"}},
      {{"wake.direction=[1.0, 0.0, -0.5]"}, {"wake.direction = [1, 0, -0.5]", "into the wall"}},
      {{"wake.direction=[0.02, 1.0, 0.0]"}, {"wake.direction = [0.02, 1, 0]", "inverted"}},
      // Steeply inclined and widened by 44 degrees, the first wake hexes turn inside out.
      {{"wake.widening=44", "wake.direction=[0.5, 1.0, 0.0]", "wake.length=0.8"}, {"wake.widening = 44", "the block folds"}},
      // A spanwise ratio line gives the sharp edge's root and strip top two ratios: the wedge takes one.
      {{"geometry.naca.te=sharp", "boundary_layer.layers=3", "boundary_layer.ratio_line=[0, 0, 0, 0, 0, 3]",
        "boundary_layer.ratio_end=1.0"},
       {"ratio differs", "ratio_line"}},
  };
  for (const auto& [overrides, expected] : cases) {
    Config c = parse_config(kCoarseH, "h.toml", {}, overrides);
    const fs::path dir = fresh_directory("bad");
    c.output.directory = dir.string();
    Silent progress;
    try {
      run(c, progress);
      ADD_FAILURE() << "no RunError for " << overrides.front();
    } catch (const RunError& e) {
      EXPECT_EQ(e.cause(), Error::Cause::BadInput) << e.what();
      for (const std::string& part : expected) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir)) << overrides.front();
  }
}

}  // namespace
}  // namespace semimesh::pipeline
