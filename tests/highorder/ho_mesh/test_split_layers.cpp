// Isoparametric splitting: sub-element nodes on the coarse map, layer heights in the ratio r,
// validity inherited, conformity between split neighbours, curved faces kept, two-direction hexes.
#include "semimesh/ho/splitting/split_layers.hpp"

#include "semimesh/ho/basis.hpp"
#include "semimesh/ho/validity.hpp"

#include "prisms_on_square.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>

namespace semimesh::ho {
namespace {

using Map = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

// Interface positions in [-1, 1] for N layers growing by r, written from the definition
// (thicknesses h r^k summing to 2).
std::vector<double> expected_interfaces(int layers, double r) {
  const double h = r == 1.0 ? 2.0 / layers : 2.0 * (r - 1.0) / (std::pow(r, layers) - 1.0);
  std::vector<double> z{-1.0};
  for (int k = 0; k < layers; ++k) z.push_back(z.back() + h * std::pow(r, k));
  return z;
}

// One element whose nodes are F at its reference nodes.
mesh::Mesh single_element(Shape shape, int order, NodeSet set, const Map& F) {
  mesh::Mesh m(order, set);
  const Eigen::MatrixX3d r = reference_nodes(shape, order, set);
  std::vector<mesh::NodeId> ids;
  for (Eigen::Index i = 0; i < r.rows(); ++i) ids.push_back(m.add_node(F(r.row(i).transpose())));
  m.add_element(shape, ids);
  return m;
}

// A prism map in the space P_3(xi, eta) x P_3(zeta): curved body face, curved side face eta = 0.
Eigen::Vector3d prism_map(const Eigen::Vector3d& r) {
  const double x = r(0), y = r(1), z = r(2);
  return {x + 0.05 * y * z, 0.2 * x * (1.0 - x) + y + 0.03 * x * z, 0.1 * (z + 1.0) + 0.05 * x * x};
}

TEST(SplitLayers, PrismNodesLieOnTheCoarseMap) {
  for (NodeSet set : {NodeSet::Equispaced, NodeSet::GLL}) {
    const int P = 3, N = 5;
    const mesh::Mesh coarse = single_element(Shape::Prism, P, set, prism_map);
    SplitStats stats;
    const mesh::Mesh fine = split_layers(coarse, {0}, {N, 2.0}, {}, &stats);
    ASSERT_EQ(fine.elements().size(), std::size_t(N));
    EXPECT_EQ(stats.elements_in, 1);
    EXPECT_EQ(stats.elements_out, N);
    const std::vector<double> z = expected_interfaces(N, 2.0);
    const Eigen::MatrixX3d r = reference_nodes(Shape::Prism, P, set);
    double worst = 0.0;
    for (int k = 0; k < N; ++k) {
      const Eigen::MatrixX3d X = fine.element_coordinates(k);
      for (Eigen::Index i = 0; i < r.rows(); ++i) {
        Eigen::Vector3d q = r.row(i).transpose();
        q(2) = z[k] + 0.5 * (q(2) + 1.0) * (z[k + 1] - z[k]);
        worst = std::max(worst, (X.row(i).transpose() - prism_map(q)).norm());
      }
    }
    EXPECT_LT(worst, 1e-12);  // the map is in the element's space: exact up to round-off
  }
}

// Every piece of a prism or hex split in one or two directions, orders 1-4, both node sets, is the
// coarse map at the piece's reference nodes, computed here by the dense evaluation (map_points):
// the split sums only the basis values that are not 0 (sparse_rows.hpp).
TEST(SplitLayers, PiecesAreTheCoarseMapAtTheirReferenceNodesInEveryPlan) {
  const Map bent = [](const Eigen::Vector3d& q) {
    return Eigen::Vector3d(q(0) + 0.1 * std::sin(q(1) + q(2)), q(1) + 0.05 * q(0) * q(2), 0.3 * q(2) + 0.1 * std::cos(q(0)));
  };
  struct Plan {
    Shape shape;
    std::array<int, 2> direction;
  };
  const std::vector<Plan> plans{{Shape::Prism, {2, -1}},      {Shape::Hexahedron, {0, -1}}, {Shape::Hexahedron, {1, -1}},
                                {Shape::Hexahedron, {2, -1}}, {Shape::Hexahedron, {2, 1}},  {Shape::Hexahedron, {0, 2}}};
  const std::array<int, 2> layers{4, 3};
  const std::array<double, 2> ratio{1.7, 1.3};
  for (const Plan& plan : plans)
    for (NodeSet set : {NodeSet::Equispaced, NodeSet::GLL})
      for (int P = 1; P <= 4; ++P) {
        SCOPED_TRACE(to_string(plan.shape) + " directions " + std::to_string(plan.direction[0]) + "," +
                     std::to_string(plan.direction[1]) + " P" + std::to_string(P) + (set == NodeSet::GLL ? " GLL" : ""));
        const mesh::Mesh coarse = single_element(plan.shape, P, set, bent);
        const mesh::Mesh fine = split_layers(coarse, {{0, plan.direction, {0, 1}}},
                                             {{{layers[0], ratio[0]}, {}}, {{layers[1], ratio[1]}, {}}}, nullptr, nullptr);
        const bool two = plan.direction[1] >= 0;
        ASSERT_EQ(fine.elements().size(), std::size_t(layers[0] * (two ? layers[1] : 1)));
        const LagrangeBasis basis(plan.shape, P, set);
        const Eigen::MatrixX3d Xc = coarse.element_coordinates(0), r = basis.nodes();
        const std::array<std::vector<double>, 2> z{expected_interfaces(layers[0], ratio[0]),
                                                   expected_interfaces(layers[1], ratio[1])};
        const auto along = [](const std::vector<double>& zs, int k, double t) { return zs[k] + 0.5 * (t + 1.0) * (zs[k + 1] - zs[k]); };
        for (std::size_t e = 0; e < fine.elements().size(); ++e) {
          double best = 1e9;  // the piece (k_a, k_b) whose reference nodes it has
          for (int a = 0; a < layers[0]; ++a)
            for (int b = 0; b < (two ? layers[1] : 1); ++b) {
              Eigen::MatrixX3d q = r;
              for (Eigen::Index i = 0; i < q.rows(); ++i) {
                q(i, plan.direction[0]) = plan.shape == Shape::Prism ? along(z[0], a, r(i, 2)) : along(z[0], a, r(i, plan.direction[0]));
                if (two) q(i, plan.direction[1]) = along(z[1], b, r(i, plan.direction[1]));
              }
              best = std::min(best, (fine.element_coordinates(e) - map_points(basis, Xc, q)).cwiseAbs().maxCoeff());
            }
          EXPECT_LT(best, 1e-13) << "piece " << e;
        }
      }
}

TEST(SplitLayers, FirstCellHeightsFollowTheRatio) {
  // Vertical edges are straight: |d chi / d zeta| is 0.1 at vertex 0, so layer k there is 0.1 h r^k high.
  const mesh::Mesh coarse = single_element(Shape::Prism, 2, NodeSet::GLL, prism_map);
  SplitStats stats;
  const mesh::Mesh fine = split_layers(coarse, {0}, {5, 2.0}, {}, &stats);
  const double h0 = 2.0 / 31.0;  // 2 (r - 1) / (r^5 - 1)
  EXPECT_NEAR(stats.first_cell_height_min, 0.1 * h0, 1e-12);
  // The longest vertical edge is at vertex 2 (xi, eta) = (0, 1): d chi / d zeta = (0.05, 0, 0.1).
  EXPECT_NEAR(stats.first_cell_height_max, std::hypot(0.05, 0.1) * h0, 1e-12);
  EXPECT_NEAR(stats.achieved_ratio, 2.0, 1e-12);
  // The same from the nodes: vertex 3 of sub-element 0 over vertex 0.
  const Eigen::MatrixX3d X0 = fine.element_coordinates(0), X1 = fine.element_coordinates(1);
  const double first = (X0.row(3) - X0.row(0)).norm(), second = (X1.row(3) - X1.row(0)).norm();
  EXPECT_NEAR(second / first, 2.0, 1e-12);
}

TEST(SplitLayers, SubElementsOfAValidPrismAreValid) {
  const int P = 3;
  const mesh::Mesh coarse = single_element(Shape::Prism, P, NodeSet::GLL, prism_map);
  ASSERT_TRUE(certify_jacobian(Shape::Prism, P, NodeSet::GLL, coarse.element_coordinates(0)).valid);
  const mesh::Mesh fine = split_layers(coarse, {0}, {5, 2.0});
  for (std::size_t e = 0; e < fine.elements().size(); ++e)
    EXPECT_TRUE(certify_jacobian(Shape::Prism, P, NodeSet::GLL, fine.element_coordinates(e)).valid) << "sub-element " << e;
}

TEST(SplitLayers, CurvedSideFaceIsKept) {
  // On the side face eta = 0 the map gives y = 0.2 x (1 - x) + 0.03 x zeta with x = xi: check the
  // interior nodes of that face in every sub-element against it (zeta from z, independent of chi).
  const int P = 4;
  const mesh::Mesh coarse = single_element(Shape::Prism, P, NodeSet::GLL, prism_map);
  const mesh::Mesh fine = split_layers(coarse, {0}, {4, 1.5});
  int checked = 0;
  for (std::size_t e = 0; e < fine.elements().size(); ++e) {
    const mesh::Element& el = fine.elements()[e];
    const long f = fine.find_face({el.vertices[0], el.vertices[1], el.vertices[4], el.vertices[3]});
    ASSERT_GE(f, 0);
    for (mesh::NodeId id : fine.face_nodes(f)) {
      const Eigen::Vector3d x = fine.node(id);
      const double xi = x(0);                          // eta = 0 on this face
      const double zeta = (x(2) - 0.05 * xi * xi) / 0.1 - 1.0;
      EXPECT_NEAR(x(1), 0.2 * xi * (1.0 - xi) + 0.03 * xi * zeta, 1e-12);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 4 * (P + 1) * (P + 1));
}

// Two prisms sharing the side face (1, 2, 5, 4) of the first: a flat layer of thickness 0.1 under
// a smooth global bending, nodes placed element by element.
mesh::Mesh two_prisms(int order, NodeSet set) {
  return prisms_on_square(order, set, {{0, 1, 2}, {1, 3, 2}}, [](const Eigen::Vector3d& flat, double zeta) {
    const Eigen::Vector3d p = flat + Eigen::Vector3d(0, 0, 0.05 * (zeta + 1.0));
    return Eigen::Vector3d(p(0), p(1), p(2) + 0.1 * std::sin(p(0)) * std::cos(p(1)));
  });
}

TEST(SplitLayers, SplitNeighboursConform) {
  const int P = 3, N = 5;
  const mesh::Mesh coarse = two_prisms(P, NodeSet::GLL);
  const mesh::Mesh fine = split_layers(coarse, {0, 1}, {N, 2.0});
  ASSERT_EQ(fine.elements().size(), std::size_t(2 * N));
  // Each sub-element of the second prism sees the shared face nodes created by the first one: they
  // must still be on its own coarse map.
  const std::vector<double> z = expected_interfaces(N, 2.0);
  const LagrangeBasis basis(Shape::Prism, P, NodeSet::GLL);
  const Eigen::MatrixX3d r = basis.nodes();
  double worst = 0.0;
  for (int c = 0; c < 2; ++c) {
    const Eigen::MatrixX3d Xc = coarse.element_coordinates(c);
    for (int k = 0; k < N; ++k) {
      Eigen::MatrixX3d q = r;
      for (Eigen::Index i = 0; i < q.rows(); ++i) q(i, 2) = z[k] + 0.5 * (r(i, 2) + 1.0) * (z[k + 1] - z[k]);
      worst = std::max(worst, (fine.element_coordinates(c * N + k) - map_points(basis, Xc, q)).cwiseAbs().maxCoeff());
    }
  }
  EXPECT_LT(worst, 1e-12);
  // The shared side face is split once: the sub-faces are shared entities (5 faces used twice).
  std::multiset<long> used;
  for (std::size_t e = 0; e < fine.elements().size(); ++e)
    for (int f = 0; f < 5; ++f) used.insert(fine.elements()[e].faces[f]);
  int shared = 0;
  for (long f : std::set<long>(used.begin(), used.end())) shared += used.count(f) == 2 ? 1 : 0;
  EXPECT_EQ(shared, N + 2 * (N - 1));  // N pieces of the side face + layer interfaces in each prism
}

TEST(SplitLayers, SubElementsKeepTheRegionOfTheirElement) {
  mesh::Mesh coarse(2, NodeSet::GLL);
  {
    // The two prisms of two_prisms(), the second one put in another region.
    const mesh::Mesh source = two_prisms(2, NodeSet::GLL);
    for (mesh::NodeId id = 0; id < source.num_nodes(); ++id) coarse.add_node(source.node(id));
    const int layer = coarse.region_index("wing_layer"), wake = coarse.region_index("wake");
    coarse.add_element(Shape::Prism, source.element_nodes(0), layer);
    coarse.add_element(Shape::Prism, source.element_nodes(1), wake);
  }
  const int N = 3;
  const mesh::Mesh fine = split_layers(coarse, {0, 1}, {N, 1.5});
  ASSERT_EQ(fine.region_names(), coarse.region_names());
  ASSERT_EQ(fine.elements().size(), std::size_t(2 * N));
  for (int k = 0; k < 2 * N; ++k)
    EXPECT_EQ(fine.elements()[k].region, coarse.elements()[k / N].region) << "sub-element " << k;
}

TEST(SplitLayers, RefusesASplitElementWhoseSideFaceNeighbourIsNotSplitTheSameWay) {
  const mesh::Mesh coarse = two_prisms(2, NodeSet::GLL);
  try {
    split_layers(coarse, {1}, {3, 1.5});
    FAIL() << "splitting one of two prisms sharing a side face must be refused";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("element 1"), std::string::npos) << what;
    EXPECT_NE(what.find("element 0"), std::string::npos) << what;
  }
  std::vector<std::size_t> first_piece;
  const mesh::Mesh fine = split_layers(coarse, std::vector<LayerSplit>{{0, {2, -1}, {0, 0}}, {1, {2, -1}, {0, 0}}},
                                       {SplitFamily{{3, 1.5}, {}}}, nullptr, &first_piece);
  EXPECT_EQ(first_piece, (std::vector<std::size_t>{0, 3}));
  EXPECT_EQ(fine.elements().size(), 6u);
}

TEST(SplitLayers, RatioFieldKeepsConformityAndUsesTheVertexRatio) {
  const mesh::Mesh coarse = two_prisms(2, NodeSet::Equispaced);
  const RatioField ratio = [](const Eigen::Vector3d& x) { return 1.0 + x(0) + 0.5 * x(1); };
  const int N = 4;
  const mesh::Mesh fine = split_layers(coarse, {0, 1}, {N, 2.0}, ratio);
  // Heights along each vertical edge follow the ratio at its body vertex (edges are straight in z).
  for (std::size_t e = 0; e < fine.elements().size(); ++e) {
    const std::size_t coarse_element = e / N;
    const int k = static_cast<int>(e % N);
    const Eigen::MatrixX3d Xc = coarse.element_coordinates(coarse_element);
    const Eigen::MatrixX3d X = fine.element_coordinates(e);
    for (int v = 0; v < 3; ++v) {
      const std::vector<double> z = expected_interfaces(N, ratio(Xc.row(v).transpose()));
      const double height = Xc(v + 3, 2) - Xc(v, 2);
      EXPECT_NEAR(X(v, 2), Xc(v, 2) + 0.5 * (z[k] + 1.0) * height, 1e-12);
      EXPECT_NEAR(X(v + 3, 2), Xc(v, 2) + 0.5 * (z[k + 1] + 1.0) * height, 1e-12);
    }
  }
}

// A hexahedron map in Q_2 with a closed-form inverse: F(a, b, c) = (a, b + 0.1 a^2, c + 0.1 a b).
Eigen::Vector3d hex_map(const Eigen::Vector3d& r) { return {r(0), r(1) + 0.1 * r(0) * r(0), r(2) + 0.1 * r(0) * r(1)}; }
Eigen::Vector3d hex_inverse(const Eigen::Vector3d& x) {
  const double a = x(0), b = x(1) - 0.1 * a * a;
  return {a, b, x(2) - 0.1 * a * b};
}

TEST(SplitLayers, HexSplitInTwoDirections) {
  const int P = 2;
  const mesh::Mesh coarse = single_element(Shape::Hexahedron, P, NodeSet::Equispaced, hex_map);
  const mesh::Mesh once = split_layers(coarse, {0}, {3, 1.5});
  std::vector<std::size_t> all{0, 1, 2};
  SplitStats stats;
  const mesh::Mesh twice = split_hex_direction(once, all, 0, {2, 1.0}, &stats);
  ASSERT_EQ(twice.elements().size(), 6u);
  EXPECT_EQ(stats.elements_out, 6);
  // Every node of the result is F at a point of the refined lattice: xi in {-1, -1/2, ..., 1},
  // eta in {-1, 0, 1}, zeta at the interfaces of (3, 1.5) and their midpoints.
  const std::vector<double> z = expected_interfaces(3, 1.5);
  std::set<std::pair<long, long>> expected_zeta;
  std::set<std::array<long, 3>> seen;
  for (std::size_t e = 0; e < twice.elements().size(); ++e) {
    EXPECT_TRUE(certify_jacobian(Shape::Hexahedron, P, NodeSet::Equispaced, twice.element_coordinates(e)).valid);
    for (mesh::NodeId id : twice.element_nodes(e)) {
      const Eigen::Vector3d q = hex_inverse(twice.node(id));
      EXPECT_NEAR(q(0) * 2.0, std::round(q(0) * 2.0), 1e-12);
      EXPECT_NEAR(q(1), std::round(q(1)), 1e-12);
      double best = 1e9;
      for (int k = 0; k < 3; ++k)
        for (double t : {z[k], 0.5 * (z[k] + z[k + 1]), z[k + 1]}) best = std::min(best, std::abs(q(2) - t));
      EXPECT_LT(best, 1e-12);
      seen.insert({std::lround(q(0) * 4), std::lround(q(1) * 2), std::lround(q(2) * 1e6)});
    }
  }
  // (2*2+1) x (2+1) x (3*2+1) distinct lattice points, each one node: nothing duplicated or lost.
  std::set<mesh::NodeId> referenced;
  for (std::size_t e = 0; e < twice.elements().size(); ++e)
    for (mesh::NodeId id : twice.element_nodes(e)) referenced.insert(id);
  EXPECT_EQ(seen.size(), 105u);
  EXPECT_EQ(referenced.size(), 105u);
}

// A junction-like hex split along zeta (first direction, constant ratio) and eta (second, a ratio
// field): the eta interfaces follow the field's ratios at the two vertices of the foot at the top
// of zeta (xi = -1 and 1, eta = -1, zeta = 1), linearly in xi, whatever the zeta of the node.
TEST(SplitLayers, RatioFieldOnTheSecondDirectionFollowsTheFootAtTheTopOfTheFirst) {
  const int P = 2;
  const mesh::Mesh coarse = single_element(Shape::Hexahedron, P, NodeSet::Equispaced, hex_map);
  const RatioField ratio = [](const Eigen::Vector3d& x) { return 2.0 + 0.5 * x(0) + 0.25 * x(2); };
  const int Na = 3, Nb = 4;
  const mesh::Mesh fine = split_layers(coarse, std::vector<LayerSplit>{{0, {2, 1}, {0, 1}}},
                                       {SplitFamily{{Na, 1.5}, {}}, SplitFamily{{Nb, 2.0}, ratio}}, nullptr, nullptr);
  ASSERT_EQ(fine.elements().size(), static_cast<std::size_t>(Na * Nb));
  const std::vector<double> left = expected_interfaces(Nb, ratio(hex_map({-1, -1, 1})));
  const std::vector<double> right = expected_interfaces(Nb, ratio(hex_map({1, -1, 1})));
  ASSERT_NE(left, right);
  for (std::size_t e = 0; e < fine.elements().size(); ++e) {
    EXPECT_TRUE(certify_jacobian(Shape::Hexahedron, P, NodeSet::Equispaced, fine.element_coordinates(e)).valid);
    for (mesh::NodeId id : fine.element_nodes(e)) {
      const Eigen::Vector3d q = hex_inverse(fine.node(id));
      const double t = 0.5 * (q(0) + 1.0);
      double best = 1e9;  // eta at an interface of the interpolated distribution or a mid-layer
      for (int k = 0; k < Nb; ++k) {
        const double y0 = (1 - t) * left[k] + t * right[k], y1 = (1 - t) * left[k + 1] + t * right[k + 1];
        for (double y : {y0, 0.5 * (y0 + y1), y1}) best = std::min(best, std::abs(q(1) - y));
      }
      EXPECT_LT(best, 1e-12) << "node " << id << " at reference " << q.transpose();
    }
  }
}

// A mesh given up (moved in) lends its nodes to the split instead of a copy: the same output, and
// the input left without nodes. A ratio field makes the split read vertex coordinates too.
TEST(SplitLayers, AMeshGivenUpSplitsAsACopiedOneAndLendsItsNodes) {
  const int P = 3;
  mesh::Mesh coarse = single_element(Shape::Hexahedron, P, NodeSet::GLL, hex_map);
  const RatioField ratio = [](const Eigen::Vector3d& x) { return 2.0 + 0.5 * x(0) + 0.25 * x(2); };
  const std::vector<LayerSplit> split{{0, {2, 1}, {0, 1}}};
  const std::vector<SplitFamily> families{SplitFamily{{3, 1.5}, {}}, SplitFamily{{4, 2.0}, ratio}};
  const mesh::Mesh copied = split_layers(coarse, split, families, nullptr, nullptr);
  const std::size_t coarse_nodes = coarse.num_nodes();
  const mesh::Mesh given = split_layers(std::move(coarse), split, families, nullptr, nullptr);
  EXPECT_EQ(coarse.num_nodes(), 0u);  // NOLINT(bugprone-use-after-move): the test of the move
  ASSERT_GT(given.num_nodes(), coarse_nodes);
  EXPECT_TRUE(given.nodes() == copied.nodes());
  ASSERT_EQ(given.elements().size(), copied.elements().size());
  for (std::size_t e = 0; e < given.elements().size(); ++e)
    EXPECT_EQ(given.element_nodes(e), copied.element_nodes(e)) << "element " << e;
}

// A hex split along zeta (3 layers, r = 1.5) and eta (2 layers, r = 1) with a boundary face on
// four of its sides, and an unsplit hex beside it with one. A face at one end of a split direction
// keeps the pieces at that end, a face across a direction takes one face per layer, a face across
// both one per piece: each a face of a piece, on the coarse face, cut at the layers' interfaces.
TEST(SplitLayers, BoundaryFacesAreCutWithTheirElement) {
  const int P = 2;
  mesh::Mesh coarse = single_element(Shape::Hexahedron, P, NodeSet::Equispaced, hex_map);
  {
    const Eigen::MatrixX3d r = reference_nodes(Shape::Hexahedron, P, NodeSet::Equispaced);
    std::vector<mesh::NodeId> ids;  // the same map shifted away: touches nothing of the first
    for (Eigen::Index i = 0; i < r.rows(); ++i)
      ids.push_back(coarse.add_node(hex_map(r.row(i).transpose()) + Eigen::Vector3d(5, 0, 0)));
    coarse.add_element(Shape::Hexahedron, ids);
  }
  // Gmsh vertex order: 0 (-1,-1,-1) 1 (1,-1,-1) 2 (1,1,-1) 3 (-1,1,-1), 4-7 the same at zeta = 1.
  const auto add_face = [&](const std::string& group, std::size_t element, const std::array<int, 4>& local) {
    std::vector<mesh::NodeId> v;
    for (int i : local) v.push_back(coarse.elements()[element].vertices[i]);
    const long f = coarse.find_face(v);
    ASSERT_GE(f, 0) << group;
    coarse.add_boundary_face(group, Shape::Quadrilateral, coarse.face_nodes(f));
  };
  add_face("bottom", 0, {0, 1, 2, 3});  // zeta = -1: the body side of the first direction
  add_face("top", 0, {4, 5, 6, 7});     // zeta = 1
  add_face("front", 0, {0, 1, 5, 4});   // eta = -1: the body side of the second direction
  add_face("left", 0, {0, 3, 7, 4});    // xi = -1: across both directions
  add_face("other", 1, {0, 1, 2, 3});   // on the unsplit hex
  const int Na = 3, Nb = 2;
  const mesh::Mesh fine = split_layers(coarse, std::vector<LayerSplit>{{0, {2, 1}, {0, 1}}},
                                       {SplitFamily{{Na, 1.5}, {}}, SplitFamily{{Nb, 1.0}, {}}}, nullptr, nullptr);
  ASSERT_EQ(fine.elements().size(), static_cast<std::size_t>(Na * Nb + 1));

  std::set<std::uint32_t> element_faces;
  for (const mesh::Element& el : fine.elements()) element_faces.insert(el.faces.begin(), el.faces.end());
  struct Expected {
    int count;
    int fixed_axis;
    double fixed_value;
    std::set<long> zeta, eta;  // the faces' vertices' reference zeta and eta (times 1e6, rounded)
  };
  const auto rounded = [](const std::vector<double>& z) {
    std::set<long> s;
    for (double v : z) s.insert(std::lround(v * 1e6));
    return s;
  };
  const std::set<long> zeta = rounded(expected_interfaces(Na, 1.5)), eta = rounded(expected_interfaces(Nb, 1.0));
  const std::set<long> low = rounded({-1.0}), high = rounded({1.0}), both = rounded({-1.0, 1.0});
  const std::map<std::string, Expected> expected = {{"bottom", {Nb, 2, -1.0, low, eta}},
                                                    {"top", {Nb, 2, 1.0, high, eta}},
                                                    {"front", {Na, 1, -1.0, zeta, low}},
                                                    {"left", {Na * Nb, 0, -1.0, zeta, eta}},
                                                    {"other", {1, 2, -1.0, low, both}}};
  std::map<std::string, int> count;
  std::map<std::string, std::set<long>> seen_zeta, seen_eta;
  for (std::size_t b = 0; b < fine.boundary_faces().size(); ++b) {
    const mesh::BoundaryFace& bf = fine.boundary_faces()[b];
    const std::string& group = fine.group_names()[bf.group];
    ASSERT_EQ(expected.count(group), 1u) << group;
    const Expected& want = expected.at(group);
    ++count[group];
    EXPECT_EQ(element_faces.count(bf.face), 1u) << "boundary face " << b << " (" << group << ") is no piece's face";
    const Eigen::Vector3d shift = group == "other" ? Eigen::Vector3d(5, 0, 0) : Eigen::Vector3d::Zero();
    for (mesh::NodeId id : fine.boundary_face_nodes(b))
      EXPECT_NEAR(hex_inverse(fine.node(id) - shift)(want.fixed_axis), want.fixed_value, 1e-12) << group;
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector3d q = hex_inverse(fine.node(bf.vertices[i]) - shift);
      seen_zeta[group].insert(std::lround(q(2) * 1e6));
      seen_eta[group].insert(std::lround(q(1) * 1e6));
    }
  }
  for (const auto& [group, want] : expected) {
    EXPECT_EQ(count[group], want.count) << group;
    EXPECT_EQ(seen_zeta[group], want.zeta) << group;
    EXPECT_EQ(seen_eta[group], want.eta) << group;
  }
}

TEST(SplitLayers, RejectsBadInput) {
  const mesh::Mesh coarse = single_element(Shape::Prism, 2, NodeSet::GLL, prism_map);
  EXPECT_THROW(split_layers(coarse, {1}, {5, 2.0}), std::invalid_argument);
  EXPECT_THROW(split_layers(coarse, {0}, {0, 2.0}), std::invalid_argument);
  EXPECT_THROW(split_layers(coarse, {0}, {5, 0.5}), std::invalid_argument);
  EXPECT_THROW(split_hex_direction(coarse, {0}, 0, {5, 2.0}), std::invalid_argument);
}

}  // namespace
}  // namespace semimesh::ho
