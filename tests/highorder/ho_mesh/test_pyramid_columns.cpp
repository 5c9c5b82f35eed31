// ho::split_pyramid_columns: a pyramid on a trapezoid (which PyFR refuses) goes, with the hex column
// under it split into prisms and the pyramid at the column's other end into tetrahedra; the result
// conforms, keeps the volume and is valid; what cannot be split along one column is refused by name.
#include "semimesh/checks/conformity.hpp"
#include "semimesh/checks/volume.hpp"
#include "semimesh/ho/basis.hpp"
#include "semimesh/ho/mesh_validity.hpp"
#include "semimesh/ho/splitting/pyramid_columns.hpp"
#include "semimesh/mesh/compact.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>

namespace semimesh::ho {
namespace {

using Vertices = std::vector<Eigen::Vector3d>;
using Deformation = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

// Builds elements of order P from their vertices (straight-sided), each node moved by `deform`;
// nodes at one place (to 1e-9) are one node, so neighbours share their entities; every face used by one
// element becomes a boundary face of group "skin", or `group_of` its vertices' centroid if that names one.
class MeshBuilder {
 public:
  MeshBuilder(int order, NodeSet set, Deformation deform = {}) : order_(order), set_(set), deform_(std::move(deform)) {}

  void add(Shape shape, const Vertices& v) { elements_.push_back({shape, v}); }

  mesh::Mesh build(const std::function<std::string(const Eigen::Vector3d&)>& group_of = {}) const {
    mesh::Mesh m(order_, set_);
    std::map<std::array<long long, 3>, mesh::NodeId> ids_at;
    for (const auto& [shape, v] : elements_) {
      const Eigen::MatrixX3d ref = reference_nodes(shape, order_, set_);
      const Eigen::MatrixX3d x = LagrangeBasis(shape, 1, NodeSet::Equispaced).values(ref) * corners(v);
      std::vector<mesh::NodeId> ids;
      for (Eigen::Index i = 0; i < x.rows(); ++i) {
        const Eigen::Vector3d p = x.row(i).transpose();
        const std::array<long long, 3> key{std::llround(p.x() * 1e9), std::llround(p.y() * 1e9), std::llround(p.z() * 1e9)};
        const auto [it, fresh] = ids_at.try_emplace(key, 0);
        if (fresh) it->second = m.add_node(moved(p));
        ids.push_back(it->second);
      }
      m.add_element(shape, ids);
    }
    // Boundary faces on the faces one element uses, with the element's outward vertex order.
    std::map<std::uint32_t, int> uses;
    for (const mesh::Element& e : m.elements())
      for (std::size_t k = 0; k < faces(e.shape).size(); ++k) ++uses[e.faces[k]];
    for (std::size_t e = 0; e < m.elements().size(); ++e) {
      const mesh::Element& el = m.elements()[e];
      const std::vector<mesh::NodeId> nodes = m.element_nodes(e);
      for (std::size_t k = 0; k < faces(el.shape).size(); ++k) {
        if (uses[el.faces[k]] != 1) continue;
        const std::vector<int>& f = faces(el.shape)[k];
        const Shape fs = f.size() == 3 ? Shape::Triangle : Shape::Quadrilateral;
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (int v : f) centroid += elements_[e].second[v] / static_cast<double>(f.size());
        std::string group = group_of ? group_of(centroid) : "";
        // The face's canonical nodes: found by placing a face element of order P on its vertices.
        const Eigen::MatrixX3d fref = reference_nodes(fs, order_, set_);
        Eigen::MatrixX3d fv(f.size(), 3);
        for (std::size_t i = 0; i < f.size(); ++i) fv.row(i) = elements_[e].second[f[i]].transpose();
        const Eigen::MatrixX3d at = LagrangeBasis(fs, 1, NodeSet::Equispaced).values(fref) * fv;
        std::vector<mesh::NodeId> ids;
        for (Eigen::Index i = 0; i < at.rows(); ++i) ids.push_back(nearest(m, nodes, at.row(i).transpose()));
        m.add_boundary_face(group.empty() ? "skin" : group, fs, ids);
      }
    }
    return mesh::without_unreferenced_nodes(m);
  }

 private:
  static Eigen::MatrixX3d corners(const Vertices& v) {
    Eigen::MatrixX3d c(v.size(), 3);
    for (std::size_t i = 0; i < v.size(); ++i) c.row(i) = v[i].transpose();
    return c;
  }
  Eigen::Vector3d moved(const Eigen::Vector3d& x) const { return deform_ ? deform_(x) : x; }
  // The element node at the place a straight face node moves to.
  mesh::NodeId nearest(const mesh::Mesh& m, const std::vector<mesh::NodeId>& nodes, const Eigen::Vector3d& x) const {
    const Eigen::Vector3d target = moved(x);
    mesh::NodeId best = nodes[0];
    for (mesh::NodeId n : nodes)
      if ((m.node(n) - target).norm() < (m.node(best) - target).norm()) best = n;
    return best;
  }

  int order_;
  NodeSet set_;
  Deformation deform_;
  std::vector<std::pair<Shape, Vertices>> elements_;
};

// A column of hexes along z whose cross-section is the trapezoid A B C D, levels z = 0..n.
const Eigen::Vector2d kA(0, 0), kB(1, 0), kC(1.4, 1), kD(0, 1);

Eigen::Vector3d at(const Eigen::Vector2d& p, double z) { return {p.x(), p.y(), z}; }

void add_column(MeshBuilder& b, int hexes) {
  for (int k = 0; k < hexes; ++k)
    b.add(Shape::Hexahedron, {at(kA, k), at(kB, k), at(kC, k), at(kD, k), at(kA, k + 1), at(kB, k + 1),
                              at(kC, k + 1), at(kD, k + 1)});
}

// Pyramids on the column's bottom (apex below) and top (apex above).
void add_end_pyramids(MeshBuilder& b, int hexes) {
  b.add(Shape::Pyramid, {at(kA, 0), at(kD, 0), at(kC, 0), at(kB, 0), Eigen::Vector3d(0.6, 0.5, -0.7)});
  b.add(Shape::Pyramid, {at(kA, hexes), at(kB, hexes), at(kC, hexes), at(kD, hexes), Eigen::Vector3d(0.6, 0.5, hexes + 0.7)});
}

// A unit cube beside the column's lowest hex (sharing its face A D) with a pyramid on its square
// bottom: a parallelogram base, which stays.
void add_neighbour(MeshBuilder& b) {
  const Eigen::Vector2d e(-1, 0), f(-1, 1);
  b.add(Shape::Hexahedron, {at(e, 0), at(kA, 0), at(kD, 0), at(f, 0), at(e, 1), at(kA, 1), at(kD, 1), at(f, 1)});
  b.add(Shape::Pyramid, {at(e, 0), at(f, 0), at(kD, 0), at(kA, 0), Eigen::Vector3d(-0.5, 0.5, -0.5)});
}

std::map<Shape, int> shapes(const mesh::Mesh& m) {
  std::map<Shape, int> count;
  for (const mesh::Element& e : m.elements()) ++count[e.shape];
  return count;
}

std::size_t refused_pyramids(const mesh::Mesh& m) {
  std::size_t n = 0;
  for (std::size_t e = 0; e < m.elements().size(); ++e)
    n += m.elements()[e].shape == Shape::Pyramid && !has_parallelogram_base(m, e, 1e-11);
  return n;
}

TEST(PyramidColumns, ParallelogramTestIsPyfrsOnTheFirstOrderCorners) {
  MeshBuilder b(1, NodeSet::Equispaced);
  add_end_pyramids(b, 1);
  add_neighbour(b);
  const mesh::Mesh m = b.build();
  EXPECT_FALSE(has_parallelogram_base(m, 0, 1e-10));  // A D C B: a trapezoid
  EXPECT_TRUE(has_parallelogram_base(m, 3, 1e-10));   // the cube's square bottom
  EXPECT_EQ(refused_pyramids(m), 2u);
}

TEST(PyramidColumns, ColumnUnderTwoTrapezoidPyramidsBecomesPrismsAndTetsAtEveryOrder) {
  for (int order = 1; order <= 4; ++order)
    for (NodeSet set : {NodeSet::Equispaced, NodeSet::GLL}) {
      SCOPED_TRACE("order " + std::to_string(order) + (set == NodeSet::GLL ? " GLL" : " equispaced"));
      MeshBuilder b(order, set);
      add_column(b, 3);
      add_end_pyramids(b, 3);
      add_neighbour(b);
      const mesh::Mesh in = b.build();
      ASSERT_TRUE(checks::check_conformity(in).ok());
      const PyramidColumns out = split_pyramid_columns(in, 1e-11);

      EXPECT_EQ(out.stats.pyramids_refused, 2u);
      EXPECT_EQ(out.stats.columns, 1u);
      EXPECT_EQ(out.stats.hexes_split, 3u);
      EXPECT_EQ(out.stats.pyramids_split, 2u);
      EXPECT_EQ(out.stats.boundary_quads_split, 0u);
      const std::map<Shape, int> expected{{Shape::Hexahedron, 1}, {Shape::Prism, 6}, {Shape::Tetrahedron, 4},
                                          {Shape::Pyramid, 1}};
      EXPECT_EQ(shapes(out.mesh), expected);
      EXPECT_EQ(refused_pyramids(out.mesh), 0u);

      const checks::ConformityResult conformity = checks::check_conformity(out.mesh);
      for (const checks::FaceProblem& p : conformity.problems) ADD_FAILURE() << p.describe(out.mesh);
      // Straight trapezoids: the two prisms fill their hex exactly at every order, as the tets their pyramid.
      const checks::MeshVolume before = checks::mesh_volume(in), after = checks::mesh_volume(out.mesh);
      EXPECT_NEAR(after.element_volume, before.element_volume, 1e-12);
      EXPECT_LT(after.boundary_relative_error(), 1e-12);
      EXPECT_EQ(mesh::count_unreferenced_nodes(out.mesh), 0u);
      EXPECT_TRUE(certify_mesh(out.mesh).all_valid());
    }
}

TEST(PyramidColumns, AMeshWithNothingRefusedComesBackMovedNotCopied) {
  MeshBuilder b(2, NodeSet::GLL);
  add_column(b, 2);
  add_neighbour(b);
  mesh::Mesh in = b.build();
  const std::size_t elements = in.elements().size();
  const Eigen::Vector3d* nodes = in.nodes().data();
  const PyramidColumns out = split_pyramid_columns(std::move(in), 1e-11);
  EXPECT_EQ(out.stats.pyramids_refused, 0u);
  EXPECT_EQ(out.mesh.elements().size(), elements);
  EXPECT_EQ(out.mesh.nodes().data(), nodes);  // the same node array: moved through
}

TEST(PyramidColumns, CurvedColumnStaysConformingAndValid) {
  const Deformation bend = [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(x.x() + 0.08 * std::sin(1.3 * x.z()), x.y() + 0.05 * x.x() * x.x(), x.z() + 0.04 * x.y() * x.x());
  };
  for (int order = 2; order <= 4; ++order) {
    SCOPED_TRACE("order " + std::to_string(order));
    MeshBuilder b(order, NodeSet::GLL, bend);
    add_column(b, 4);
    add_end_pyramids(b, 4);
    add_neighbour(b);
    const mesh::Mesh in = b.build();
    const PyramidColumns out = split_pyramid_columns(in, 1e-11);
    EXPECT_EQ(out.stats.hexes_split, 5u);  // bent, the cube's square bottom is no parallelogram either
    EXPECT_EQ(refused_pyramids(out.mesh), 0u);
    const checks::ConformityResult conformity = checks::check_conformity(out.mesh);
    for (const checks::FaceProblem& p : conformity.problems) ADD_FAILURE() << p.describe(out.mesh);
    // The pieces interpolate their parent's map at order P: the volume moves by that error only.
    EXPECT_NEAR(checks::mesh_volume(out.mesh).element_volume, checks::mesh_volume(in).element_volume, 1e-3);
    EXPECT_LT(checks::mesh_volume(out.mesh).boundary_relative_error(), 1e-9);
    EXPECT_TRUE(certify_mesh(out.mesh).all_valid());
  }
}

TEST(PyramidColumns, ColumnEndingOnTheBoundarySplitsTheBoundaryQuad) {
  MeshBuilder b(2, NodeSet::GLL);
  add_column(b, 2);
  b.add(Shape::Pyramid, {at(kA, 0), at(kD, 0), at(kC, 0), at(kB, 0), Eigen::Vector3d(0.6, 0.5, -0.7)});
  const mesh::Mesh in = b.build([](const Eigen::Vector3d& c) { return c.z() > 1.99 ? "outlet" : ""; });
  const PyramidColumns out = split_pyramid_columns(in, 1e-11);
  EXPECT_EQ(out.stats.hexes_split, 2u);
  EXPECT_EQ(out.stats.boundary_quads_split, 1u);
  std::map<Shape, int> outlet;
  for (const mesh::BoundaryFace& f : out.mesh.boundary_faces())
    if (out.mesh.group_names()[f.group] == "outlet") ++outlet[f.shape];
  EXPECT_EQ(outlet, (std::map<Shape, int>{{Shape::Triangle, 2}}));
  const checks::ConformityResult conformity = checks::check_conformity(out.mesh);
  for (const checks::FaceProblem& p : conformity.problems) ADD_FAILURE() << p.describe(out.mesh);
  EXPECT_LT(checks::mesh_volume(out.mesh).boundary_relative_error(), 1e-12);  // triangles keep the outward order
}

TEST(PyramidColumns, MeshWithParallelogramPyramidsOnlyIsReturnedAsItIs) {
  MeshBuilder b(3, NodeSet::GLL);
  add_neighbour(b);
  const mesh::Mesh in = b.build();
  const PyramidColumns out = split_pyramid_columns(in, 1e-11);
  EXPECT_EQ(out.stats.pyramids_refused, 0u);
  EXPECT_EQ(out.mesh.num_nodes(), in.num_nodes());
  ASSERT_EQ(out.mesh.elements().size(), in.elements().size());
  for (std::size_t e = 0; e < in.elements().size(); ++e) EXPECT_EQ(out.mesh.element_nodes(e), in.element_nodes(e));
}

TEST(PyramidColumns, ColumnRunningIntoAPrismIsRefusedByName) {
  MeshBuilder b(1, NodeSet::Equispaced);
  add_column(b, 1);
  b.add(Shape::Pyramid, {at(kA, 0), at(kD, 0), at(kC, 0), at(kB, 0), Eigen::Vector3d(0.6, 0.5, -0.7)});
  // A prism standing on the hex's top face with its quad face 0 1 4 3 = B A D C.
  b.add(Shape::Prism, {at(kB, 1), at(kA, 1), Eigen::Vector3d(0.5, -0.2, 2.0), at(kC, 1), at(kD, 1),
                       Eigen::Vector3d(0.7, 1.2, 2.0)});
  const mesh::Mesh in = b.build();
  EXPECT_THAT([&] { split_pyramid_columns(in, 1e-11); },
              ::testing::ThrowsMessage<std::invalid_argument>(::testing::AllOf(
                  ::testing::HasSubstr("runs into"), ::testing::HasSubstr("prism 2"),
                  ::testing::HasSubstr("1 of the 1 refused pyramids' columns end so"))));
}

TEST(PyramidColumns, HexNeedingPrismsAlongTwoAxesIsRefusedByName) {
  // A cube with vertex 6 pulled out: its top (z) and right (x) faces are no parallelograms; a
  // pyramid stands on each.
  const Vertices v{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1.3, 1.2, 1.25}, {0, 1, 1}};
  MeshBuilder b(1, NodeSet::Equispaced);
  b.add(Shape::Hexahedron, v);
  b.add(Shape::Pyramid, {v[4], v[5], v[6], v[7], Eigen::Vector3d(0.5, 0.5, 2.0)});
  b.add(Shape::Pyramid, {v[1], v[2], v[6], v[5], Eigen::Vector3d(2.0, 0.5, 0.5)});
  const mesh::Mesh in = b.build();
  ASSERT_EQ(refused_pyramids(in), 2u);
  EXPECT_THAT([&] { split_pyramid_columns(in, 1e-11); },
              ::testing::ThrowsMessage<std::invalid_argument>(::testing::AllOf(::testing::HasSubstr("two axes"),
                                                                             ::testing::HasSubstr("hexahedron 0"))));
}

}  // namespace
}  // namespace semimesh::ho
