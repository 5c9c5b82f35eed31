// The split pieces' inherited bounds (split_layers -> certify_mesh) pinned to the reference
// certification of every element on its own nodes: same verdicts, same bounds to rounding, on
// prisms and hexahedra (one and two directions) of orders 1-4; none inherited where the interfaces
// vary (a ratio field) or a piece's nodes moved after the split.
#include "semimesh/checks/volume.hpp"
#include "semimesh/ho/mesh_validity.hpp"
#include "semimesh/ho/quality.hpp"
#include "semimesh/ho/splitting/split_layers.hpp"
#include "semimesh/mesh/compact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <string>
#include <unordered_map>

namespace semimesh::ho {
namespace {

using Map = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

// Two elements of `shape` sharing the face at xi = 1 (hexahedra) or one prism, nodes F at the
// reference nodes (hexahedra: the second shifted by 2 along xi; F is smooth, so they conform).
mesh::Mesh curved_elements(Shape shape, int order, const Map& F) {
  mesh::Mesh m(order, NodeSet::GLL);
  const Eigen::MatrixX3d r = reference_nodes(shape, order, NodeSet::GLL);
  const int copies = shape == Shape::Hexahedron ? 2 : 1;
  std::vector<std::vector<mesh::NodeId>> ids(copies);
  std::map<std::array<long, 3>, mesh::NodeId> made;
  for (int c = 0; c < copies; ++c)
    for (Eigen::Index i = 0; i < r.rows(); ++i) {
      Eigen::Vector3d q = r.row(i).transpose();
      q(0) += 2.0 * c;
      const std::array<long, 3> key{std::lround(q(0) * 1e9), std::lround(q(1) * 1e9), std::lround(q(2) * 1e9)};
      auto it = made.find(key);
      if (it == made.end()) it = made.emplace(key, m.add_node(F(q))).first;
      ids[c].push_back(it->second);
    }
  for (const auto& element : ids) m.add_element(shape, element);
  return m;
}

Eigen::Vector3d bent(const Eigen::Vector3d& r) {
  const double x = r(0), y = r(1), z = r(2);
  return {x + 0.05 * y * z + 0.02 * std::sin(z), 0.15 * std::sin(0.5 * x) + y + 0.03 * x * z,
          0.1 * (z + 1.0) + 0.04 * std::cos(x) * (1.0 + 0.3 * y)};
}

void expect_same(const MeshValidity& fast, const MeshValidity& reference) {
  ASSERT_EQ(fast.bounds.size(), reference.bounds.size());
  EXPECT_EQ(fast.invalid, reference.invalid);
  EXPECT_EQ(fast.invalid_elements, reference.invalid_elements);
  for (std::size_t e = 0; e < fast.bounds.size(); ++e) {
    const JacobianBounds &a = fast.bounds[e], &b = reference.bounds[e];
    SCOPED_TRACE("element " + std::to_string(e));
    EXPECT_EQ(a.valid, b.valid);
    EXPECT_EQ(a.proven, b.proven);
    const double scale = std::abs(b.max_upper);
    EXPECT_NEAR(a.min_lower, b.min_lower, 1e-8 * scale);
    EXPECT_NEAR(a.max_upper, b.max_upper, 1e-8 * scale);
    EXPECT_NEAR(scaled_jacobian(a), scaled_jacobian(b), 1e-8);
  }
  EXPECT_NEAR(fast.min_scaled_jacobian, reference.min_scaled_jacobian, 1e-8);
  EXPECT_NEAR(fast.median_scaled_jacobian, reference.median_scaled_jacobian, 1e-8);
}

// The bent elements of `shape` split into 5 layers (ratio 2) along zeta and, hexahedra, 3 (ratio
// 1.5) along eta; their pieces' inherited bounds into `inherited`.
mesh::Mesh split_bent(Shape shape, int order, std::vector<InheritedBounds>& inherited) {
  const mesh::Mesh coarse = curved_elements(shape, order, bent);
  std::vector<LayerSplit> split;
  for (std::size_t e = 0; e < coarse.elements().size(); ++e)
    split.push_back({e, {2, shape == Shape::Hexahedron ? 1 : -1}, {0, 1}});
  return split_layers(coarse, split, {{{5, 2.0}, {}}, {{3, 1.5}, {}}}, nullptr, nullptr, {}, &inherited);
}

// check(shape, order, fine, inherited) on split_bent's pieces of prisms and hexahedra of orders 1-4.
void for_each_split_bent(
    const std::function<void(Shape, int, const mesh::Mesh&, const std::vector<InheritedBounds>&)>& check) {
  for (Shape shape : {Shape::Prism, Shape::Hexahedron})
    for (int order = 1; order <= 4; ++order) {
      SCOPED_TRACE(to_string(shape) + " P" + std::to_string(order));
      std::vector<InheritedBounds> inherited;
      const mesh::Mesh fine = split_bent(shape, order, inherited);
      check(shape, order, fine, inherited);
    }
}

TEST(InheritedBounds, SplitPiecesMatchTheReferenceCertification) {
  for_each_split_bent([](Shape, int, const mesh::Mesh& fine, const std::vector<InheritedBounds>& inherited) {
    ASSERT_EQ(inherited.size(), fine.elements().size());
    for (double floor : {0.0, 1e-5}) {
      const MeshValidity fast = certify_mesh(fine, 8, floor, {}, &inherited);
      const MeshValidity reference = certify_mesh(fine, 8, floor);
      EXPECT_EQ(fast.inherited, fine.elements().size());
      EXPECT_EQ(reference.inherited, 0u);
      EXPECT_TRUE(reference.all_valid());
      expect_same(fast, reference);
    }
  });
}

// The integrals certify_mesh found for fine's elements (NaN where none), as the checks give
// them to the volume check.
std::vector<double> integrals_of(const MeshValidity& certified) {
  std::vector<double> out;
  for (const JacobianBounds& b : certified.bounds) out.push_back(b.integral);
  return out;
}

// The pieces' volumes from their inherited bounds (the mean of the coarse det J's Bernstein
// coefficients on the piece, times the reference volume) pinned to each piece's own quadrature:
// the certification passes them on (all pieces) and the volume check takes them, and a piece
// without its integral, integrated on its own nodes, changes the sum by rounding only.
TEST(InheritedBounds, SplitPiecesVolumesMatchTheirOwnQuadrature) {
  for_each_split_bent([](Shape shape, int order, const mesh::Mesh& fine,
                         const std::vector<InheritedBounds>& inherited) {
    const std::vector<double> known = integrals_of(certify_mesh(fine, 8, 0.0, {}, &inherited));
    const checks::MeshVolume fast = checks::mesh_volume(fine, checks::VolumeRule::Exact, &known);
    const checks::MeshVolume reference = checks::mesh_volume(fine);
    EXPECT_EQ(fast.known, fine.elements().size());
    EXPECT_EQ(reference.known, 0u);
    EXPECT_NEAR(fast.element_volume, reference.element_volume, 1e-13 * reference.element_volume);
    EXPECT_NEAR(reference.element_volume, checks::mesh_volume(curved_elements(shape, order, bent)).element_volume,
                1e-13 * reference.element_volume);
    for (std::size_t k = 0; k < known.size(); ++k) {
      std::vector<double> without_k = known;
      without_k[k] = std::numeric_limits<double>::quiet_NaN();
      const checks::MeshVolume own = checks::mesh_volume(fine, checks::VolumeRule::Exact, &without_k);
      ASSERT_EQ(own.known, fine.elements().size() - 1);
      // The sum with piece k's own quadrature: its inherited integral differs by rounding.
      EXPECT_NEAR(own.element_volume, fast.element_volume, 1e-13 * std::abs(known[k])) << k;
      EXPECT_GT(known[k], 0.0);
    }
  });
}

// A piece whose node moved after the split is certified on its own (its fingerprint is no longer
// the one its bounds came with), with no integral: the volume check integrates it on its nodes.
TEST(InheritedBounds, AMovedPieceIsIntegratedOnItsOwn) {
  const mesh::Mesh coarse = curved_elements(Shape::Prism, 3, bent);
  std::vector<InheritedBounds> inherited;
  mesh::Mesh fine = split_layers(coarse, {{0, {2, -1}, {0, 0}}}, {{{5, 2.0}, {}}}, nullptr, nullptr, {}, &inherited);
  const std::vector<mesh::NodeId> last = fine.element_nodes(fine.elements().size() - 1);
  fine.place_node(last.back(), fine.node(last.back()) + Eigen::Vector3d(0.0, 0.0, 1e-3));  // an interior node
  const std::vector<double> known = integrals_of(certify_mesh(fine, 8, 0.0, {}, &inherited));
  EXPECT_TRUE(std::isnan(known.back()));
  const checks::MeshVolume fast = checks::mesh_volume(fine, checks::VolumeRule::Exact, &known);
  EXPECT_EQ(fast.known, fine.elements().size() - 1);
  EXPECT_NEAR(fast.element_volume, checks::mesh_volume(fine).element_volume, 1e-13 * fast.element_volume);
}

// Only the pieces have bounds: a copied element before or after them is certified on its own, and
// each piece finds its own entry.
TEST(InheritedBounds, KeptForThePiecesOnlyWhereverTheyAreInTheMesh) {
  const mesh::Mesh coarse = curved_elements(Shape::Hexahedron, 3, bent);
  for (std::size_t split_one : {0u, 1u}) {
    SCOPED_TRACE("split element " + std::to_string(split_one));
    std::vector<InheritedBounds> inherited;
    const mesh::Mesh fine = split_layers(coarse, {{split_one, {0, -1}, {0, 0}}}, {{{5, 2.0}, {}}}, nullptr, nullptr,
                                         {}, &inherited);
    ASSERT_EQ(fine.elements().size(), 6u);
    ASSERT_EQ(inherited.size(), 5u);
    const std::size_t first = split_one == 0 ? 0 : 1;  // the copied element keeps its place in mesh order
    for (std::size_t k = 0; k < inherited.size(); ++k) EXPECT_EQ(inherited[k].element, first + k);
    const MeshValidity fast = certify_mesh(fine, 8, 0.0, {}, &inherited);
    EXPECT_EQ(fast.inherited, 5u);
    expect_same(fast, certify_mesh(fine, 8, 0.0));
  }
}

TEST(InheritedBounds, AFloorAboveTheInheritedRatioSendsThePieceToTheReference) {
  const mesh::Mesh coarse = curved_elements(Shape::Prism, 3, bent);
  std::vector<InheritedBounds> inherited;
  const mesh::Mesh fine = split_layers(coarse, {{0, {2, -1}, {0, 0}}}, {{{5, 2.0}, {}}}, nullptr, nullptr, {}, &inherited);
  const MeshValidity reference = certify_mesh(fine, 8, 0.0);
  // A floor between the pieces' scaled Jacobians: the pieces below it are certified again (and
  // refined against the floor), the others keep their inherited bounds.
  std::vector<double> scaled;
  for (const JacobianBounds& b : reference.bounds) scaled.push_back(scaled_jacobian(b));
  const double floor = 0.5 * (*std::min_element(scaled.begin(), scaled.end()) + *std::max_element(scaled.begin(), scaled.end()));
  const MeshValidity fast = certify_mesh(fine, 8, floor, {}, &inherited);
  const MeshValidity slow = certify_mesh(fine, 8, floor);
  EXPECT_GT(fast.inherited, 0u);
  EXPECT_LT(fast.inherited, fine.elements().size());
  expect_same(fast, slow);
}

TEST(InheritedBounds, NoneWhereTheInterfacesVaryOrANodeMoved) {
  const mesh::Mesh coarse = curved_elements(Shape::Hexahedron, 2, bent);
  std::vector<LayerSplit> split{{0, {2, -1}, {0, 0}}, {1, {2, -1}, {0, 0}}};
  // A ratio that differs between the bottom vertices: the pieces are not the coarse map composed
  // with an affine map, so none inherits.
  const RatioField varying = [](const Eigen::Vector3d& x) { return 1.5 + 0.2 * x(0); };
  std::vector<InheritedBounds> inherited;
  mesh::Mesh fine = split_layers(coarse, split, {{{4, 1.5}, varying}}, nullptr, nullptr, {}, &inherited);
  EXPECT_EQ(certify_mesh(fine, 8, 0.0, {}, &inherited).inherited, 0u);
  // A field giving the family's own ratio everywhere: all inherit.
  const RatioField constant = [](const Eigen::Vector3d&) { return 1.5; };
  fine = split_layers(coarse, split, {{{4, 1.5}, constant}}, nullptr, nullptr, {}, &inherited);
  EXPECT_EQ(certify_mesh(fine, 8, 0.0, {}, &inherited).inherited, fine.elements().size());
  // Moving one inner node of piece 0 (as a later stage might): that piece is certified again.
  const mesh::NodeId inner = fine.element_nodes(0).back();  // the piece's own volume node
  std::vector<mesh::NodeId> identity(fine.num_nodes());
  std::iota(identity.begin(), identity.end(), mesh::NodeId{0});
  const mesh::Mesh moved =
      mesh::with_nodes_replaced(fine, identity, {{inner, fine.node(inner) + Eigen::Vector3d(0.0, 0.0, 1e-3)}});
  const MeshValidity fast = certify_mesh(moved, 8, 0.0, {}, &inherited);
  EXPECT_EQ(fast.inherited, moved.elements().size() - 1);
  expect_same(fast, certify_mesh(moved, 8, 0.0));
  // Bounds for an element the mesh does not have, or out of order, are refused.
  std::vector<InheritedBounds> beyond = inherited;
  beyond.back().element = fine.elements().size();
  EXPECT_THROW(certify_mesh(fine, 8, 0.0, {}, &beyond), std::invalid_argument);
  std::vector<InheritedBounds> reversed(inherited.rbegin(), inherited.rend());
  EXPECT_THROW(certify_mesh(fine, 8, 0.0, {}, &reversed), std::invalid_argument);
}

}  // namespace
}  // namespace semimesh::ho
