// Steps of the C- and H-type builders with a contract of their own, on the analytic NACA wing:
//  - the wake's streamwise stations (geometric growth from the trailing edge to the length);
//  - the sharp trailing edge (the body-body curve leaving the wall farthest along the sweep);
//  - the base's flat corners (only where a round tip continues the base's sides tangentially);
//  - the skin handed to the far field cut at the split's interfaces: at the fractions along each
//    wing-layer edge, and still conforming (every cut node shared by the quads on both sides);
//  - the layer's thickness figures: the shortest and longest prism edge actually built.
#include "semimesh/cad/model.hpp"
#include "semimesh/mock_cad/naca.hpp"
#include "semimesh/nearfield/c_shell.hpp"
#include "semimesh/nearfield/detail/trailing_edge.hpp"
#include "semimesh/nearfield/h_shell.hpp"

#include "wing_case.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace semimesh::nearfield {
namespace {

using cad::Vec3;
using testing::curve_named;
using testing::naca;
using testing::wing_case;

TEST(WakeStations, GrowGeometricallyFromTheTrailingEdgeToTheLength) {
  WakeParams wake;
  wake.layers = 7;
  wake.growth = 1.25;
  wake.length = 2.5;
  const std::vector<double> s = detail::wake_stations(wake);
  ASSERT_EQ(s.size(), 8u);
  EXPECT_EQ(s.front(), 0.0);
  EXPECT_NEAR(s.back(), wake.length, 1e-14);
  for (std::size_t k = 2; k < s.size(); ++k)
    EXPECT_NEAR((s[k] - s[k - 1]) / (s[k - 1] - s[k - 2]), wake.growth, 1e-12) << "cell " << k;
  wake.growth = 1.0;
  const std::vector<double> even = detail::wake_stations(wake);
  for (std::size_t k = 0; k < even.size(); ++k) EXPECT_NEAR(even[k], k * wake.length / wake.layers, 1e-14);
}

// Run on to the far field's face: the configured stations first, then cells still growing but
// none longer than outlet_cell (once scaled), the last station exactly at the distance.
TEST(WakeStations, RunOnToADistanceGrowingUpToTheLongestCell) {
  WakeParams wake;
  wake.layers = 5;
  wake.growth = 1.3;
  wake.length = 1.0;
  wake.outlet_cell = 0.8;
  const std::vector<double> own = detail::wake_stations(wake);
  const std::vector<double> s = detail::wake_stations_to(wake, 7.0);
  ASSERT_GT(s.size(), own.size() + 3);
  for (std::size_t k = 0; k < own.size(); ++k) EXPECT_EQ(s[k], own[k]);
  EXPECT_EQ(s.back(), 7.0);
  for (std::size_t k = own.size(); k < s.size(); ++k) {
    EXPECT_GT(s[k] - s[k - 1], 0.0) << k;
    EXPECT_LE(s[k] - s[k - 1], wake.outlet_cell) << k;
    EXPECT_LE(s[k] - s[k - 1], wake.growth * (s[k - 1] - s[k - 2]) + 1e-12) << k;
  }
  EXPECT_GT(s[s.size() - 2] - s[s.size() - 3], 0.7 * wake.outlet_cell);  // the cap was reached
  const std::vector<double> shorter = detail::wake_stations_to(wake, 0.5);
  ASSERT_EQ(shorter.size(), own.size());
  for (std::size_t k = 0; k < own.size(); ++k) EXPECT_NEAR(shorter[k], 0.5 * own[k], 1e-15);
}

// The leading edge is a body-body curve leaving the wall too: the sweep direction decides.
TEST(SharpTrailingEdge, IsTheBodyCurveLeavingTheWallFarthestDownstream) {
  for (const auto& wing : {naca("0012", true), naca("2412", true, 0.6, 30.0)}) {
    const auto model = mock_cad::make_naca_wing(wing);
    BodyRoles roles;
    for (const std::string name : {"upper", "lower", "tip"}) roles.body_surfaces.push_back(*model->find_surface(name));
    roles.wall_surface = *model->find_surface("wall");
    ASSERT_GE(curve_named(*model, "trailing_edge"), 0);
    EXPECT_EQ(detail::sharp_trailing_edge(*model, roles, Vec3::UnitX()), curve_named(*model, "trailing_edge"));
    EXPECT_EQ(detail::sharp_trailing_edge(*model, roles, Vec3(1.0, 0.3, 0.0).normalized()),
              curve_named(*model, "trailing_edge"));
    EXPECT_EQ(detail::sharp_trailing_edge(*model, roles, -Vec3::UnitX()), curve_named(*model, "leading_edge"));
    BodyRoles no_wall = roles;
    no_wall.wall_surface = -1;
    EXPECT_EQ(detail::sharp_trailing_edge(*model, no_wall, Vec3::UnitX()), -1);
  }
}

// One-panel wings (blunt or sharp, flat or round tip, swept): the trailing edge ends at the tip.
// The cranked wing's continuation is tested on its OCC file (cli.init_cad_cranked_*_forced_h_refused).
TEST(TrailingEdgeContinuation, NoneOnAOnePanelWing) {
  for (bool sharp : {false, true})
    for (bool round : {false, true}) {
      mock_cad::NacaWingParams wing = naca("2412", sharp, 0.6, 30.0);
      wing.round_tip = round;
      const auto model = mock_cad::make_naca_wing(wing);
      BodyRoles roles;
      for (const std::string name : {"upper", "lower", "te_base", "tip"})
        if (auto s = model->find_surface(name)) roles.body_surfaces.push_back(*s);
      roles.wall_surface = *model->find_surface("wall");
      const std::vector<int> base = sharp ? std::vector<int>{} : std::vector<int>{*model->find_surface("te_base")};
      const int crack = sharp ? curve_named(*model, "trailing_edge") : -1;
      EXPECT_EQ(detail::trailing_edge_continuation(*model, roles, base, crack), -1)
          << "sharp " << sharp << " round " << round;
      // Without the tip among the body's faces the sides border nothing past the trailing edge:
      // still no continuation (the sides border each other at the leading edge).
      BodyRoles no_tip = roles;
      no_tip.body_surfaces.erase(std::remove(no_tip.body_surfaces.begin(), no_tip.body_surfaces.end(),
                                             *model->find_surface("tip")),
                                 no_tip.body_surfaces.end());
      EXPECT_EQ(detail::trailing_edge_continuation(*model, no_tip, base, crack), -1);
    }
}

// The flat tip's base is a rectangle (four right angles); the round tip's base is capped by a half
// disc that continues its two sides tangentially: flat at tip_te_upper and tip_te_lower only.
TEST(FlatBaseCorners, OnlyWhereARoundTipContinuesTheBasesSides) {
  mock_cad::NacaWingParams wing = naca("0012", false);
  const auto flat_tip = mock_cad::make_naca_wing(wing);
  EXPECT_TRUE(detail::flat_base_corners(*flat_tip, *flat_tip->find_surface("te_base")).empty());
  wing.round_tip = true;
  const auto round_tip = mock_cad::make_naca_wing(wing);
  std::set<std::string> names;
  for (int v : detail::flat_base_corners(*round_tip, *round_tip->find_surface("te_base")))
    names.insert(round_tip->vertex(v).name);
  EXPECT_EQ(names, (std::set<std::string>{"tip_te_upper", "tip_te_lower"}));
}

// The H-type near field with the wing layer split at fixed fractions (the split's interfaces).
NearField h_shell_split_at(const testing::WingCase& c, const std::vector<double>& fractions) {
  WakeParams wake;
  wake.te_base = c.model->find_surface("te_base") ? "te_base" : "auto";
  wake.length = 1.0;
  wake.layers = 6;
  ShellParams shell;
  shell.thickness = 0.05;
  return build_h_shell(*c.model, c.meshes, c.roles, shell, JunctionParams{}, /*wall_thickness=*/0.04, wake,
                       c.model->bbox(), [&](const Vec3&, const WakeBlock&) { return fractions; });
}

// Every wing-family layer edge (bottom, top) of the near field's stacks.
std::vector<std::pair<mesh::NodeId, mesh::NodeId>> wing_layer_edges(const NearField& f) {
  static constexpr int kHexAxisEdges[3][4][2] = {{{0, 1}, {3, 2}, {4, 5}, {7, 6}},
                                                 {{0, 3}, {1, 2}, {4, 7}, {5, 6}},
                                                 {{0, 4}, {1, 5}, {2, 6}, {3, 7}}};
  std::vector<std::pair<mesh::NodeId, mesh::NodeId>> edges;
  for (const LayerStack& s : f.stacks) {
    const mesh::Element& e = f.mesh.elements()[s.element];
    for (const LayerDirection& d : s.directions) {
      if (d.family != LayerFamily::Wing) continue;
      if (e.shape == ho::Shape::Prism)
        for (int i = 0; i < 3; ++i) edges.push_back({e.vertices[i], e.vertices[i + 3]});
      else
        for (const auto& pair : kHexAxisEdges[d.axis]) edges.push_back({e.vertices[pair[0]], e.vertices[pair[1]]});
    }
  }
  return edges;
}

TEST(HShellSkin, QuadsTheSplitCutsArePreCutAtItsInterfacesAndStayConforming) {
  const std::vector<double> fractions{0.0, 0.2, 0.5, 1.0};
  for (const bool sharp : {false, true}) {
    SCOPED_TRACE(sharp ? "sharp trailing edge" : "blunt trailing edge");
    const testing::WingCase c = wing_case(naca("0012", sharp), 0.4, /*structured_base=*/!sharp);
    const NearField f = h_shell_split_at(c, fractions);
    const mesh::Mesh& m = f.mesh;
    std::set<mesh::NodeId> skin_nodes;
    std::map<std::pair<mesh::NodeId, mesh::NodeId>, int> edge_uses;
    for (const SkinFace& s : f.skin)
      for (int k = 0; k < s.count; ++k) {
        const mesh::NodeId a = s.nodes[k], b = s.nodes[(k + 1) % s.count];
        skin_nodes.insert(a);
        ++edge_uses[{std::min(a, b), std::max(a, b)}];
      }
    // The cut nodes: skin nodes strictly inside a wing-layer edge, each at one of the fractions;
    // an edge that carries one carries them all.
    int cut_edges = 0;
    for (const auto& [bottom, top] : wing_layer_edges(f)) {
      const Vec3 a = m.node(bottom), ab = m.node(top) - a;
      std::vector<double> inside;
      for (mesh::NodeId v : skin_nodes) {
        const double t = (m.node(v) - a).dot(ab) / ab.squaredNorm();
        if (t > 1e-9 && t < 1.0 - 1e-9 && (m.node(v) - a - t * ab).norm() < 1e-9 * ab.norm()) inside.push_back(t);
      }
      if (inside.empty()) continue;
      ++cut_edges;
      std::sort(inside.begin(), inside.end());
      ASSERT_EQ(inside.size(), 2u) << "layer edge at " << a.transpose();
      EXPECT_NEAR(inside[0], 0.2, 1e-12);
      EXPECT_NEAR(inside[1], 0.5, 1e-12);
    }
    EXPECT_GT(cut_edges, 10);
    // Conforming: every skin edge is shared by two skin faces, but the rim on the wall layer's top
    // (the footprint's tops), used once.
    const std::set<mesh::NodeId> rim(f.footprint_top.begin(), f.footprint_top.end());
    for (const auto& [e, uses] : edge_uses) {
      const bool on_rim = rim.count(e.first) && rim.count(e.second);
      EXPECT_EQ(uses, on_rim ? 1 : 2) << "skin edge " << m.node(e.first).transpose() << " - "
                                      << m.node(e.second).transpose();
    }
  }
}

// The thickness figures are those of the layer built: the shortest and longest prism edge (C-type,
// H-type with the base bare, H-type with the layer cracked). A shell of 12 chords around a small wing
// (chord 0.05, as CShell.AShortRootLoopUnderAThickShellIsValid) is thinned where the layer would
// crowd the rest of the body, so the shortest edge is a reduced one, not the requested thickness.
TEST(JunctionShellThickness, FiguresAreTheShortestAndLongestPrismEdges) {
  enum class Kind { C, HBlunt, HSharp };
  for (const Kind kind : {Kind::C, Kind::HBlunt, Kind::HSharp}) {
    SCOPED_TRACE(kind == Kind::C ? "C-type" : kind == Kind::HBlunt ? "H-type, bare base" : "H-type, cracked layer");
    mock_cad::NacaWingParams small = naca("0012", kind == Kind::HSharp);
    small.chord = 0.05;
    const testing::WingCase c = wing_case(small, 0.4, /*structured_base=*/kind == Kind::HBlunt);
    ShellParams shell;
    shell.thickness = 0.6;
    WakeParams wake;
    wake.te_base = kind == Kind::HBlunt ? "te_base" : "auto";
    wake.length = 1.0;
    const NearField f = kind == Kind::C ? build_c_shell(*c.model, c.meshes, c.roles, shell, JunctionParams{}, 0.04)
                                        : build_h_shell(*c.model, c.meshes, c.roles, shell, JunctionParams{}, 0.04,
                                                        wake, c.model->bbox(), {});
    const auto& regions = f.mesh.region_names();
    const int layer = static_cast<int>(std::find(regions.begin(), regions.end(), "wing_layer") - regions.begin());
    double shortest = 1e300, longest = 0.0;
    for (const mesh::Element& e : f.mesh.elements()) {
      if (e.region != layer) continue;
      for (int i = 0; i < 3; ++i) {
        const double h = (f.mesh.node(e.vertices[i + 3]) - f.mesh.node(e.vertices[i])).norm();
        shortest = std::min(shortest, h), longest = std::max(longest, h);
      }
    }
    ASSERT_LT(shortest, 0.9 * shell.thickness);  // the case thins the layer
    EXPECT_NEAR(f.thickness_min, shortest, 1e-12);
    EXPECT_NEAR(f.thickness_max, longest, 1e-12);
  }
}

}  // namespace
}  // namespace semimesh::nearfield
