// The real near field: the NACA 0012 O-shell (build_o_shell), curved at P = 2, 3, 4 (GLL), split
// into layers, every element certified valid; and a first cell of 1e-5 chord.
#include "o_shell_fixture.hpp"

#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/ho/mesh_validity.hpp"
#include "repair_in_place.hpp"
#include "semimesh/ho/splitting/split_layers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace semimesh::ho {
namespace {

// Ratio r with delta (r - 1) / (r^N - 1) = height (bisection; the left side falls as r grows).
double ratio_for_first_cell(double delta, int layers, double height) {
  double lo = 1.0 + 1e-9, hi = 4.0;
  for (int k = 0; k < 200; ++k) {
    const double r = 0.5 * (lo + hi);
    (delta * (r - 1.0) / (std::pow(r, layers) - 1.0) > height ? lo : hi) = r;
  }
  return 0.5 * (lo + hi);
}

// Largest ratio of a prism's longest vertex-to-vertex edge to its shortest.
double largest_aspect_ratio(const mesh::Mesh& m) {
  double worst = 0.0;
  for (const mesh::Element& el : m.elements()) {
    double shortest = 1e300, longest = 0.0;
    for (const auto& e : edges(el.shape)) {
      const double l = (m.node(el.vertices[e[0]]) - m.node(el.vertices[e[1]])).norm();
      shortest = std::min(shortest, l);
      longest = std::max(longest, l);
    }
    worst = std::max(worst, longest / shortest);
  }
  return worst;
}

TEST(OShellHighOrder, CurvedAndSplitShellIsValidAtOrders2To4) {
  const mesh::Mesh& linear = testing::coarse_o_shell().field.mesh;
  ASSERT_GE(linear.elements().size(), 200u);
  ASSERT_LE(linear.elements().size(), 3000u);  // coarse, but the LE radius must be resolved
  for (int P = 2; P <= 4; ++P) {
    CurvingStats curving;
    mesh::Mesh curved = curve_mesh(linear, *testing::coarse_o_shell().model, {P, NodeSet::GLL, 50, 1e-10}, &curving);
    // The pipeline's order: certify the one-layer shell, repair what curving folded, then split.
    const RepairStats repair = repair_in_place(curved, *testing::coarse_o_shell().model, certify_mesh(curved).invalid_elements);
    EXPECT_TRUE(repair.failures.empty()) << "P = " << P << ": " << repair.failures.front().reason;
    const MeshValidity coarse = certify_mesh(curved);
    EXPECT_TRUE(coarse.all_valid()) << "P = " << P << ": " << coarse.invalid << " invalid one-layer prisms";
    SplitStats split;
    const mesh::Mesh layers = split_layers(curved, testing::all_elements(curved), {5, 2.0}, {}, &split);
    EXPECT_EQ(split.elements_out, 5 * split.elements_in);
    const MeshValidity v = certify_mesh(layers);
    EXPECT_TRUE(v.all_valid()) << "P = " << P << ": " << v.invalid << " invalid, first at element "
                               << (v.invalid ? v.invalid_elements[0] : 0);
    EXPECT_GT(v.min_scaled_jacobian, 0.0);
    std::printf("O-shell P = %d: %zu prisms, %d repaired (min blend %.3f), min scaled Jacobian %.3f (one layer "
                "%.3f), median %.3f\n",
                P, layers.elements().size(), repair.repaired_interior + repair.repaired_free_nodes, repair.min_blend,
                v.min_scaled_jacobian, coarse.min_scaled_jacobian, v.median_scaled_jacobian);
  }
}

TEST(OShellHighOrder, FirstCellOf1e5ChordIsValid) {
  const int P = 3, layers = 12;
  const double delta = 0.05, first_cell = 1e-5;
  const double r = ratio_for_first_cell(delta, layers, first_cell);
  ASSERT_LE(r, 2.5);
  mesh::Mesh curved = curve_mesh(testing::coarse_o_shell().field.mesh, *testing::coarse_o_shell().model, {P, NodeSet::GLL, 50, 1e-10});
  const RepairStats repair = repair_in_place(curved, *testing::coarse_o_shell().model, certify_mesh(curved).invalid_elements);
  EXPECT_TRUE(repair.failures.empty());
  SplitStats split;
  const mesh::Mesh fine = split_layers(curved, testing::all_elements(curved), {layers, r}, {}, &split);
  // Vertical edges are straight: the first cell is delta_x (r - 1) / (r^N - 1) with delta_x the local
  // thickness, at most the nominal delta.
  const double scale = (r - 1.0) / (std::pow(r, layers) - 1.0);
  EXPECT_NEAR(split.first_cell_height_max, testing::coarse_o_shell().field.thickness_max * scale, 1e-3 * first_cell);
  EXPECT_NEAR(split.first_cell_height_min, testing::coarse_o_shell().field.thickness_min * scale, 1e-3 * first_cell);
  EXPECT_NEAR(split.achieved_ratio, r, 1e-6);
  const MeshValidity v = certify_mesh(fine);
  EXPECT_TRUE(v.all_valid()) << v.invalid << " invalid, first at element " << (v.invalid ? v.invalid_elements[0] : 0);
  EXPECT_GT(v.min_scaled_jacobian, 0.0);
  std::printf("first cell: N = %d, r = %.4f, height %.3e .. %.3e chord, largest aspect ratio %.0f, min scaled "
              "Jacobian %.3f, %zu prisms\n",
              layers, r, split.first_cell_height_min, split.first_cell_height_max, largest_aspect_ratio(fine),
              v.min_scaled_jacobian, fine.elements().size());
}

}  // namespace
}  // namespace semimesh::ho
