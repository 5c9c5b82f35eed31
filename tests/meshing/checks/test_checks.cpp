// The mesh checks on small hand-made meshes whose answers are known by hand.
#include "semimesh/checks/conformity.hpp"
#include "semimesh/checks/validity.hpp"
#include "semimesh/checks/volume.hpp"
#include "semimesh/ho/basis.hpp"
#include "semimesh/mesh/node_layout.hpp"

#include "face_nodes.hpp"  // meshing/src/checks

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

namespace semimesh::checks {
namespace {

using mesh::Mesh;
using mesh::NodeId;
using Kind = FaceProblem::Kind;

// Adds an element of order 1 or 2 (edge midpoints shared through `midpoints`, in ho::edges order).
std::size_t add(Mesh& m, ho::Shape shape, std::vector<NodeId> vertices, std::map<std::pair<NodeId, NodeId>, NodeId>& midpoints) {
  if (m.order() == 2) {
    for (const auto& e : ho::edges(shape)) {
      NodeId a = vertices[e[0]], b = vertices[e[1]];
      auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = midpoints.find(key);
      if (it == midpoints.end()) it = midpoints.emplace(key, m.add_node(0.5 * (m.node(a) + m.node(b)))).first;
      vertices.push_back(it->second);
    }
  }
  return m.add_element(shape, vertices);
}

// Boundary faces (group "outer") on every element face not listed in `interior`, in the element's
// outward vertex order.
void close_boundary(Mesh& m, const std::vector<std::vector<NodeId>>& interior) {
  const std::size_t n = m.elements().size();
  for (std::size_t e = 0; e < n; ++e) {
    const mesh::Element& el = m.elements()[e];
    for (const auto& f : ho::faces(el.shape)) {
      std::vector<NodeId> v;
      for (int i : f) v.push_back(el.vertices[i]);
      std::vector<NodeId> sorted = v;
      std::sort(sorted.begin(), sorted.end());
      bool inner = false;
      for (auto s : interior) {
        std::sort(s.begin(), s.end());
        inner = inner || s == sorted;
      }
      if (inner) continue;
      std::vector<NodeId> nodes = v;
      if (m.order() == 2)  // the face's edge midpoints, in the triangle's edge order (01, 12, 20)
        for (int i = 0; i < 3; ++i) {
          const auto edge = m.find_edge(v[i], v[(i + 1) % 3]);
          nodes.push_back(m.edge_nodes(edge)[1]);
        }
      m.add_boundary_face("outer", ho::Shape::Triangle, nodes);
    }
  }
}

// Two unit tets on either side of the face (0, 1, 2) in the plane z = 0.
struct TwoTets {
  Mesh mesh;
  std::map<std::pair<NodeId, NodeId>, NodeId> midpoints;
  explicit TwoTets(int order = 1, bool with_boundary = true) : mesh(order) {
    for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                     Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -1)})
      mesh.add_node(p);
    add(mesh, ho::Shape::Tetrahedron, {0, 1, 2, 3}, midpoints);
    add(mesh, ho::Shape::Tetrahedron, {0, 2, 1, 4}, midpoints);
    if (with_boundary) close_boundary(mesh, {{0, 1, 2}});
  }
};

bool has_problem(const ConformityResult& r, Kind kind, std::vector<NodeId> vertices) {
  std::sort(vertices.begin(), vertices.end());
  for (const FaceProblem& p : r.problems)
    if (p.kind == kind && p.vertices == vertices) return true;
  return false;
}

void expect_same(const ConformityResult& a, const ConformityResult& b) {
  EXPECT_EQ(a.interior_faces, b.interior_faces);
  EXPECT_EQ(a.boundary_faces, b.boundary_faces);
  ASSERT_EQ(a.problems.size(), b.problems.size());
  for (std::size_t i = 0; i < a.problems.size(); ++i) {
    EXPECT_EQ(a.problems[i].kind, b.problems[i].kind);
    EXPECT_EQ(a.problems[i].vertices, b.problems[i].vertices);
    EXPECT_EQ(a.problems[i].elements, b.problems[i].elements);
    EXPECT_EQ(a.problems[i].boundary_faces, b.problems[i].boundary_faces);
  }
}

TEST(Conformity, TwoTetsSharingAFaceConform) {
  for (int order : {1, 2}) {
    TwoTets t(order);
    const ConformityResult r = check_conformity(t.mesh);
    EXPECT_TRUE(r.ok()) << (r.problems.empty() ? "" : r.problems[0].describe(t.mesh));
    EXPECT_EQ(r.interior_faces, 1u);
    EXPECT_EQ(r.boundary_faces, 6u);
    expect_same(r, check_conformity_brute_force(t.mesh));
  }
}

TEST(Conformity, FaceSharedByThreeElementsIsReportedWithItsCentroid) {
  TwoTets t(1, false);
  const NodeId far = t.mesh.add_node(Eigen::Vector3d(0, 0, -2));
  add(t.mesh, ho::Shape::Tetrahedron, {0, 2, 1, far}, t.midpoints);
  const ConformityResult r = check_conformity(t.mesh);
  ASSERT_TRUE(has_problem(r, Kind::SharedByMoreThanTwo, {0, 1, 2}));
  const FaceProblem& p = r.problems.front();  // most severe kind sorts first
  EXPECT_EQ(p.kind, Kind::SharedByMoreThanTwo);
  EXPECT_EQ(p.elements, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_NEAR(p.centroid.x(), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(p.centroid.y(), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(p.centroid.z(), 0.0, 1e-15);
  EXPECT_NE(p.describe(t.mesh).find("elements [0 1 2]"), std::string::npos) << p.describe(t.mesh);
  expect_same(r, check_conformity_brute_force(t.mesh));
}

TEST(Conformity, ProblemsCheckedBeforeTheNodesMoveAreLocatedWhereTheNodesAreAtTheEnd) {
  // Located::Later reads no node position (the pipeline runs it while the writers resample them):
  // the nodes moved after the check, locate_problems puts the centroid where they are then.
  TwoTets t(1, false);
  const NodeId far = t.mesh.add_node(Eigen::Vector3d(0, 0, -2));
  add(t.mesh, ho::Shape::Tetrahedron, {0, 2, 1, far}, t.midpoints);
  ConformityResult r = check_conformity(t.mesh, Located::Later);
  ASSERT_TRUE(has_problem(r, Kind::SharedByMoreThanTwo, {0, 1, 2}));
  EXPECT_EQ(r.problems.front().centroid, Eigen::Vector3d::Zero());
  expect_same(r, check_conformity(t.mesh));
  for (NodeId v = 0; v < t.mesh.num_nodes(); ++v) t.mesh.place_node(v, t.mesh.node(v) + Eigen::Vector3d(10, 0, 0));
  locate_problems(t.mesh, r);
  EXPECT_NEAR(r.problems.front().centroid.x(), 10.0 + 1.0 / 3.0, 1e-14);
  EXPECT_NEAR(r.problems.front().centroid.y(), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(r.problems.front().centroid.z(), 0.0, 1e-15);
}

TEST(Conformity, DuplicatedBoundaryFaceIsReported) {
  TwoTets t;
  t.mesh.add_boundary_face("other", ho::Shape::Triangle, {0, 1, 3});
  const ConformityResult r = check_conformity(t.mesh);
  ASSERT_EQ(r.problems.size(), 1u);
  EXPECT_TRUE(has_problem(r, Kind::BoundaryRepeated, {0, 1, 3}));
  EXPECT_EQ(r.problems[0].boundary_faces.size(), 2u);
  EXPECT_NE(r.problems[0].describe(t.mesh).find("(other)"), std::string::npos);
  expect_same(r, check_conformity_brute_force(t.mesh));
}

TEST(Conformity, GapBetweenElementsIsReported) {
  // The second tet uses a copy of node 1 at the same place: the two faces do not match.
  Mesh m(1);
  std::map<std::pair<NodeId, NodeId>, NodeId> none;
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                   Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(1, 0, 0)})
    m.add_node(p);
  add(m, ho::Shape::Tetrahedron, {0, 1, 2, 3}, none);
  add(m, ho::Shape::Tetrahedron, {0, 2, 5, 4}, none);
  close_boundary(m, {{0, 1, 2}, {0, 2, 5}});
  const ConformityResult r = check_conformity(m);
  EXPECT_EQ(r.problems.size(), 2u);
  EXPECT_TRUE(has_problem(r, Kind::Unmatched, {0, 1, 2}));
  EXPECT_TRUE(has_problem(r, Kind::Unmatched, {0, 2, 5}));
  EXPECT_EQ(r.interior_faces, 0u);
  expect_same(r, check_conformity_brute_force(m));
}

TEST(Conformity, OverlapAndMisplacedBoundaryAreReported) {
  Mesh m(1);
  std::map<std::pair<NodeId, NodeId>, NodeId> none;
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                   Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, 2)})
    m.add_node(p);
  add(m, ho::Shape::Tetrahedron, {0, 1, 2, 3}, none);
  add(m, ho::Shape::Tetrahedron, {0, 1, 2, 4}, none);  // on the same side as the first one
  close_boundary(m, {{0, 1, 2}});
  EXPECT_TRUE(has_problem(check_conformity(m), Kind::SameSide, {0, 1, 2}));
  expect_same(check_conformity(m), check_conformity_brute_force(m));

  TwoTets t;
  t.mesh.add_boundary_face("wrong", ho::Shape::Triangle, {0, 2, 1});
  const ConformityResult r = check_conformity(t.mesh);
  ASSERT_EQ(r.problems.size(), 1u);
  EXPECT_TRUE(has_problem(r, Kind::BoundaryOnInteriorFace, {0, 1, 2}));
}

TEST(Conformity, BruteForceAgreesOnALargerDamagedMesh) {
  // A 4 x 3 x 3 grid of cubes, six tets each (Kuhn split along the main diagonal), boundary closed,
  // then damaged: one tet removed (a hole), one cube's tets repeated (overlaps), boundary faces added twice.
  const int nx = 4, ny = 3, nz = 3;
  Mesh m(1);
  auto id = [&](int i, int j, int k) { return static_cast<NodeId>((k * (ny + 1) + j) * (nx + 1) + i); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.add_node(Eigen::Vector3d(i, j, k));
  // Kuhn simplices: paths from corner 0 to corner 7 through the 6 permutations of the axes.
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  std::map<std::pair<NodeId, NodeId>, NodeId> none;
  std::vector<std::vector<NodeId>> tets;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& p : perms) {
          int c[3] = {i, j, k};
          std::vector<NodeId> v{id(c[0], c[1], c[2])};
          for (int axis : p) {
            ++c[axis];
            v.push_back(id(c[0], c[1], c[2]));
          }
          const Eigen::Vector3d a = m.node(v[1]) - m.node(v[0]), b = m.node(v[2]) - m.node(v[0]),
                                d = m.node(v[3]) - m.node(v[0]);
          if (a.cross(b).dot(d) < 0) std::swap(v[1], v[2]);
          tets.push_back(v);
        }
  const std::size_t removed = 17;
  for (std::size_t t = 0; t < tets.size(); ++t)
    if (t != removed) add(m, ho::Shape::Tetrahedron, tets[t], none);
  for (std::size_t t = 30; t < 36; ++t) add(m, ho::Shape::Tetrahedron, tets[t], none);
  // Boundary: the outer faces of the grid only (the hole's faces stay unmatched).
  Mesh probe(1);
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    const mesh::Element& el = m.elements()[e];
    for (const auto& f : ho::faces(el.shape)) {
      std::vector<NodeId> v;
      for (int i : f) v.push_back(el.vertices[i]);
      bool outer = true;
      for (int axis = 0; axis < 3 && outer; ++axis) {
        const double c0 = m.node(v[0])[axis];
        const double top = axis == 0 ? nx : axis == 1 ? ny : nz;
        const bool flat = c0 == m.node(v[1])[axis] && c0 == m.node(v[2])[axis];
        outer = !(flat && (c0 == 0 || c0 == top));
      }
      if (!outer) m.add_boundary_face(e % 2 ? "a" : "b", ho::Shape::Triangle, v);
    }
  }
  const ConformityResult fast = check_conformity(m);
  EXPECT_FALSE(fast.ok());
  expect_same(fast, check_conformity_brute_force(m));
}

// The conformity check takes two uses of a face that name the same face and edge entities as giving
// the same nodes, without gathering them: true only when a face's nodes are its vertices and the
// whole runs of those entities (face_sources). Pinned on one element of every shape, order and node
// set, and on boundary faces of both shapes, against the nodes element_nodes_at and
// boundary_face_nodes gather.
std::vector<NodeId> whole_runs(const Mesh& m, std::vector<NodeId> vertices, const std::vector<std::uint32_t>& edges,
                               std::uint32_t face) {
  for (std::uint32_t e : edges) {
    const std::vector<NodeId> along = m.edge_nodes(e);  // its two ends around its inner nodes
    vertices.insert(vertices.end(), along.begin() + 1, along.end() - 1);
  }
  const mesh::Face& f = m.faces()[face];
  const int count = mesh::face_interior_count(f.num_vertices, m.order());
  for (int k = 0; k < count; ++k) vertices.push_back(m.face_pool()[f.first_node + static_cast<std::size_t>(k)]);
  std::sort(vertices.begin(), vertices.end());
  return vertices;
}

Mesh affine_element(ho::Shape shape, int order, ho::NodeSet set);

TEST(Conformity, AFacesNodesAreItsVerticesAndTheWholeRunsOfItsEntities) {
  for (ho::NodeSet set : {ho::NodeSet::Equispaced, ho::NodeSet::GLL})
    for (ho::Shape shape : {ho::Shape::Tetrahedron, ho::Shape::Pyramid, ho::Shape::Prism, ho::Shape::Hexahedron})
      for (int order = 1; order <= 5; ++order) {
        SCOPED_TRACE(ho::to_string(shape) + " order " + std::to_string(order));
        Mesh m = affine_element(shape, order, set);
        const mesh::Element& el = m.elements()[0];
        const auto& sources = detail::face_sources(shape, order, set);
        ASSERT_EQ(sources.size(), ho::faces(shape).size());
        for (std::size_t f = 0; f < sources.size(); ++f) {
          EXPECT_TRUE(sources[f].whole);
          std::vector<NodeId> gathered, vertices;
          m.element_nodes_at(0, detail::nodes_on_faces(shape, order, set)[f], gathered);
          std::sort(gathered.begin(), gathered.end());
          for (int v : ho::faces(shape)[f]) vertices.push_back(el.vertices[static_cast<std::size_t>(v)]);
          std::vector<std::uint32_t> edges;
          for (int k : sources[f].edges) edges.push_back(el.edges[static_cast<std::size_t>(k)]);
          EXPECT_EQ(gathered, whole_runs(m, vertices, edges, el.faces[f])) << "face " << f;
        }
        // Each face also as a boundary face (its nodes as the face entity stores them).
        for (std::size_t f = 0; f < ho::faces(shape).size(); ++f) {
          const ho::Shape face_shape = ho::faces(shape)[f].size() == 3 ? ho::Shape::Triangle : ho::Shape::Quadrilateral;
          const std::size_t b = m.add_boundary_face("outer", face_shape, m.face_nodes(el.faces[f]));
          const mesh::BoundaryFace& bf = m.boundary_faces()[b];
          const detail::FaceSources& own = detail::face_sources(face_shape, order, set).front();
          EXPECT_TRUE(own.whole);
          std::vector<NodeId> gathered = m.boundary_face_nodes(b), vertices;
          std::sort(gathered.begin(), gathered.end());
          for (int v = 0; v < ho::num_vertices(face_shape); ++v) vertices.push_back(bf.vertices[static_cast<std::size_t>(v)]);
          std::vector<std::uint32_t> edges;
          for (int k : own.edges) edges.push_back(bf.edges[static_cast<std::size_t>(k)]);
          EXPECT_EQ(gathered, whole_runs(m, vertices, edges, bf.face)) << "boundary face " << b;
        }
      }
}

// Unit-measure reference elements mapped by x -> A x + b (det A = 2).
// One element of `shape` whose nodes are the affine image x = A r + b of its reference nodes (det A = 2).
Mesh affine_element(ho::Shape shape, int order, ho::NodeSet set) {
  Eigen::Matrix3d a;
  a << 1.0, 0.3, 0.0, 0.0, 2.0, 0.5, 0.0, 0.0, 1.0;
  Mesh m(order, set);
  const Eigen::MatrixX3d r = ho::reference_nodes(shape, order, set);
  std::vector<NodeId> ids;
  for (Eigen::Index i = 0; i < r.rows(); ++i) ids.push_back(m.add_node(a * Eigen::Vector3d(r.row(i)) + Eigen::Vector3d(3, -1, 2)));
  m.add_element(shape, ids);
  return m;
}

// A hexahedron of `order` whose nodes are the trilinear map of a box with its corners moved (not
// affine: its det J varies).
Mesh trilinear_hexahedron(int order, ho::NodeSet set) {
  const Eigen::MatrixX3d corners_r = ho::reference_nodes(ho::Shape::Hexahedron, 1);
  Eigen::MatrixX3d corners = corners_r;
  for (int v = 0; v < 8; ++v) corners.row(v) += 0.1 * Eigen::RowVector3d(std::sin(v), std::cos(3.0 * v), 0.5 * std::sin(2.0 * v));
  Mesh m(order, set);
  const Eigen::MatrixX3d r = ho::reference_nodes(ho::Shape::Hexahedron, order, set);
  std::vector<NodeId> ids;
  for (Eigen::Index i = 0; i < r.rows(); ++i) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int v = 0; v < 8; ++v)
      x += corners.row(v).transpose() * (1 + corners_r(v, 0) * r(i, 0)) * (1 + corners_r(v, 1) * r(i, 1)) *
           (1 + corners_r(v, 2) * r(i, 2)) / 8;
    ids.push_back(m.add_node(x));
  }
  m.add_element(ho::Shape::Hexahedron, ids);
  return m;
}

// The linear affine element of `shape` with each of its faces a boundary face of group "outer".
Mesh single_element(ho::Shape shape) {
  Mesh m = affine_element(shape, 1, ho::NodeSet::Equispaced);
  const std::vector<NodeId> v = m.element_nodes(0);
  for (const auto& f : ho::faces(shape)) {
    std::vector<NodeId> fv;
    for (int i : f) fv.push_back(v[i]);
    m.add_boundary_face("outer", fv.size() == 3 ? ho::Shape::Triangle : ho::Shape::Quadrilateral, fv);
  }
  return m;
}

TEST(Volume, ElementAndBoundaryVolumesOfEveryShape) {
  // Reference volumes: tet 1/6, pyramid 4/3 (base 2 x 2, height 1), prism 1/2 x 2, hex 2^3; times det A = 2.
  const std::map<ho::Shape, double> expected = {{ho::Shape::Tetrahedron, 2.0 / 6.0},
                                                {ho::Shape::Pyramid, 2.0 * 4.0 / 3.0},
                                                {ho::Shape::Prism, 2.0},
                                                {ho::Shape::Hexahedron, 16.0}};
  for (const auto& [shape, volume] : expected) {
    const MeshVolume v = mesh_volume(single_element(shape));
    EXPECT_NEAR(v.element_volume, volume, 1e-12) << ho::to_string(shape);
    EXPECT_NEAR(v.boundary_volume, volume, 1e-12) << ho::to_string(shape);
    EXPECT_EQ(v.boundary_faces_without_element, 0u);
  }
}

TEST(Volume, CurvedElementsMatchTheirBoundaryFlux) {
  TwoTets t(2);
  // Bulge the midpoint of edge (0, 3), which lies on the boundary, outward.
  const auto edge = t.mesh.find_edge(0, 3);
  const NodeId mid = t.mesh.edge_nodes(edge)[1];
  t.mesh.place_node(mid, t.mesh.node(mid) + Eigen::Vector3d(-0.1, -0.1, 0.0));
  const MeshVolume v = mesh_volume(t.mesh);
  EXPECT_GT(v.element_volume, 1.0 / 3.0 + 1e-3);
  EXPECT_NEAR(v.element_volume, v.boundary_volume, 1e-13);
  EXPECT_LT(v.boundary_relative_error(), 1e-12);
}

// One element of `shape` whose nodes are a smooth non-polynomial map of its reference nodes.
Mesh bent_element(ho::Shape shape, int order, ho::NodeSet set) {
  Mesh m(order, set);
  const Eigen::MatrixX3d r = ho::reference_nodes(shape, order, set);
  std::vector<NodeId> ids;
  for (Eigen::Index i = 0; i < r.rows(); ++i) {
    const double x = r(i, 0), y = r(i, 1), z = r(i, 2);
    ids.push_back(m.add_node({x + 0.05 * y * z + 0.02 * std::sin(z), 0.15 * std::sin(0.5 * x) + y + 0.03 * x * z,
                              0.1 * (z + 1.0) + 0.04 * std::cos(x) * (1.0 + 0.3 * y)}));
  }
  m.add_element(shape, ids);
  return m;
}

// The boundary flux reads only each face's own nodes (FaceRule): on a bent element of every shape,
// order and node set, with every face a boundary face, it is the element volume (integrated from
// all the nodes, by the divergence theorem: x . dA / 3 over the boundary).
TEST(Volume, FluxThroughEveryFaceOfABentElementIsItsVolume) {
  for (ho::Shape shape : {ho::Shape::Tetrahedron, ho::Shape::Pyramid, ho::Shape::Prism, ho::Shape::Hexahedron})
    for (int order = 1; order <= 6; ++order)
      for (ho::NodeSet set : {ho::NodeSet::Equispaced, ho::NodeSet::GLL}) {
        SCOPED_TRACE(ho::to_string(shape) + " order " + std::to_string(order));
        Mesh m = bent_element(shape, order, set);
        for (std::size_t k = 0; k < ho::faces(shape).size(); ++k) {
          const std::uint32_t f = m.elements()[0].faces[k];
          m.add_boundary_face("outer", m.faces()[f].num_vertices == 3 ? ho::Shape::Triangle : ho::Shape::Quadrilateral,
                              m.face_nodes(f));
        }
        const MeshVolume v = mesh_volume(m);
        EXPECT_GT(v.element_volume, 0.01);
        EXPECT_NEAR(v.boundary_volume, v.element_volume, 1e-12 * v.element_volume);
        const MeshVolume one = mesh_volume_one_thread(m);
        EXPECT_EQ(one.boundary_volume, v.boundary_volume);
      }
}

// `count` separate bent order-2 hexahedra side by side, every face of each a boundary face.
Mesh separate_bent_hexes(int count) {
  Mesh m(2, ho::NodeSet::Equispaced);
  const Eigen::MatrixX3d r = ho::reference_nodes(ho::Shape::Hexahedron, 2, ho::NodeSet::Equispaced);
  for (int h = 0; h < count; ++h) {
    std::vector<NodeId> ids;
    for (Eigen::Index i = 0; i < r.rows(); ++i) {
      const double x = r(i, 0) + 3.0 * h, y = r(i, 1), z = r(i, 2);
      ids.push_back(m.add_node({x + 0.05 * y * z, 0.15 * std::sin(0.5 * x) + y, z + 0.04 * std::cos(x) * y}));
    }
    const std::size_t e = m.add_element(ho::Shape::Hexahedron, ids);
    for (std::uint32_t f : m.elements()[e].faces) m.add_boundary_face("outer", ho::Shape::Quadrilateral, m.face_nodes(f));
  }
  return m;
}

// mesh_volume's threads add the same terms in the same order as its one-thread reference: the same
// bits, over several of the boundary flux's blocks of faces.
TEST(Volume, ThreadsGiveTheOneThreadReferencesSumsBitForBit) {
  const Mesh m = separate_bent_hexes(2000);
  ASSERT_GT(m.boundary_faces().size(), 10000u);
  const MeshVolume threads = mesh_volume(m), one = mesh_volume_one_thread(m);
  EXPECT_EQ(threads.element_volume, one.element_volume);
  EXPECT_EQ(threads.boundary_volume, one.boundary_volume);
  EXPECT_EQ(threads.boundary_faces_without_element, 0u);
  EXPECT_NEAR(threads.boundary_volume, threads.element_volume, 1e-10 * threads.element_volume);
}

// mesh_volume's default rule against `reference` on bent elements of every shape, orders 1-6 and
// both node sets: equal within `tolerance` of the volume.
void expect_exact_rule_matches(VolumeRule reference, double tolerance) {
  for (ho::Shape shape : {ho::Shape::Tetrahedron, ho::Shape::Pyramid, ho::Shape::Prism, ho::Shape::Hexahedron})
    for (int order = 1; order <= 6; ++order)
      for (ho::NodeSet set : {ho::NodeSet::Equispaced, ho::NodeSet::GLL}) {
        SCOPED_TRACE(ho::to_string(shape) + " order " + std::to_string(order));
        const Mesh m = bent_element(shape, order, set);
        const double exact = mesh_volume(m, VolumeRule::Exact).element_volume;
        const double expected = mesh_volume(m, reference).element_volume;
        EXPECT_NEAR(exact, expected, tolerance * std::abs(expected));
      }
}

// The per-shape exact rule against the generous one: both integrate the polynomial det J exactly,
// so they agree to rounding (orders 1..6: the orders runs use and more, kept to a quick test).
TEST(Volume, ExactRuleMatchesTheGenerousReferenceOnEveryShapeAndOrder) {
  expect_exact_rule_matches(VolumeRule::Generous, 1e-13);
}

// The default rule integrates prisms and hexahedra by factors (sum factorisation); the quadrature
// of every element with the full (points, nodes) products is its reference: the same points and
// weights, so equal to rounding on curved elements of every shape, order and node set.
TEST(Volume, FactoredQuadratureMatchesTheFullQuadratureOnEveryShapeAndOrder) {
  expect_exact_rule_matches(VolumeRule::Quadrature, 1e-14);
}

// The closed form of affine elements (det A times the reference volume) against the quadrature of
// the same elements, and both against the volumes by hand; the bent elements above are not affine
// and go through the quadrature in both rules.
TEST(Volume, ClosedFormOfAffineElementsMatchesTheQuadratureOnEveryShapeAndOrder) {
  const std::map<ho::Shape, double> by_hand = {{ho::Shape::Tetrahedron, 2.0 / 6.0},
                                               {ho::Shape::Pyramid, 2.0 * 4.0 / 3.0},
                                               {ho::Shape::Prism, 2.0},
                                               {ho::Shape::Hexahedron, 16.0}};
  for (const auto& [shape, volume] : by_hand)
    for (int order = 1; order <= 6; ++order)
      for (ho::NodeSet set : {ho::NodeSet::Equispaced, ho::NodeSet::GLL}) {
        SCOPED_TRACE(ho::to_string(shape) + " order " + std::to_string(order));
        const Mesh m = affine_element(shape, order, set);
        const double closed = mesh_volume(m, VolumeRule::Exact).element_volume;
        const double reference = mesh_volume(m, VolumeRule::Quadrature).element_volume;
        EXPECT_NEAR(closed, reference, 1e-13 * volume);
        EXPECT_NEAR(closed, volume, 1e-13 * volume);
      }
}

// The checks give the volume check the integrals their certification found: an affine element's
// is det A times the reference volume, the very closed form mesh_volume computes itself, so the sum
// is the same bits; a trilinear hexahedron's is its trilinear element's, its volume to rounding; a
// bent element has none (NaN) and is integrated on its nodes. An element's
// known integral is taken as given (a doctored one shows), and a list of the wrong size is refused.
TEST(Volume, TakesTheIntegralsTheCertificationFound) {
  for (ho::Shape shape : {ho::Shape::Tetrahedron, ho::Shape::Pyramid, ho::Shape::Prism, ho::Shape::Hexahedron})
    for (int order = 1; order <= 4; ++order) {
      SCOPED_TRACE(ho::to_string(shape) + " order " + std::to_string(order));
      const Mesh affine = affine_element(shape, order, ho::NodeSet::GLL);
      const ValidityResult certified = check_validity(affine);
      ASSERT_EQ(certified.integrals.size(), 1u);
      ASSERT_TRUE(std::isfinite(certified.integrals[0]));
      const MeshVolume taken = mesh_volume(affine, VolumeRule::Exact, &certified.integrals);
      EXPECT_EQ(taken.known, 1u);
      EXPECT_EQ(taken.element_volume, mesh_volume(affine).element_volume);
      std::vector<double> doctored = certified.integrals;
      doctored[0] *= 2.0;
      EXPECT_EQ(mesh_volume(affine, VolumeRule::Exact, &doctored).element_volume, 2.0 * taken.element_volume);

      const std::vector<double> too_many(2, 1.0);
      EXPECT_THROW(mesh_volume(affine, VolumeRule::Exact, &too_many), std::invalid_argument);
      if (order == 1) continue;  // a tetrahedron of order 1 is affine, however bent its vertices

      if (shape == ho::Shape::Hexahedron) {  // a trilinear one: its volume to rounding
        const Mesh trilinear = trilinear_hexahedron(order, ho::NodeSet::GLL);
        const ValidityResult trilinear_certified = check_validity(trilinear);
        ASSERT_TRUE(std::isfinite(trilinear_certified.integrals[0]));
        const MeshVolume trilinear_volume = mesh_volume(trilinear, VolumeRule::Exact, &trilinear_certified.integrals);
        EXPECT_EQ(trilinear_volume.known, 1u);
        EXPECT_NEAR(trilinear_volume.element_volume, mesh_volume(trilinear).element_volume,
                    1e-13 * trilinear_volume.element_volume);
      }

      const Mesh bent = bent_element(shape, order, ho::NodeSet::GLL);
      const ValidityResult bent_certified = check_validity(bent);
      ASSERT_TRUE(std::isnan(bent_certified.integrals[0]));
      const MeshVolume bent_volume = mesh_volume(bent, VolumeRule::Exact, &bent_certified.integrals);
      EXPECT_EQ(bent_volume.known, 0u);
      EXPECT_EQ(bent_volume.element_volume, mesh_volume(bent).element_volume);
    }
}

TEST(Volume, AMissingElementShowsInTheBoundaryVolume) {
  TwoTets t;
  // Boundary faces of the first tet are there, so without the second the closed volume is 1/6 +
  // the flux of the second's boundary faces through nothing (they have no element: skipped).
  Mesh one(1);
  for (std::size_t n = 0; n < t.mesh.num_nodes(); ++n) one.add_node(t.mesh.node(static_cast<NodeId>(n)));
  one.add_element(ho::Shape::Tetrahedron, {0, 1, 2, 3});
  one.add_boundary_face("outer", ho::Shape::Triangle, {0, 1, 3});
  one.add_boundary_face("outer", ho::Shape::Triangle, {0, 4, 1});  // belongs to no element
  const MeshVolume v = mesh_volume(one);
  EXPECT_NEAR(v.element_volume, 1.0 / 6.0, 1e-13);
  EXPECT_EQ(v.boundary_faces_without_element, 1u);
  EXPECT_GT(v.boundary_relative_error(), 0.5);  // two of the tet's four faces are not boundary faces
}

surface::SurfaceMesh quad_surface(std::vector<Eigen::Vector3d> corners) {
  surface::SurfaceMesh s;
  s.points = std::move(corners);
  s.quads.push_back({0, 1, 2, 3});
  return s;
}

TEST(Volume, BoxMinusBodyFromSurfaceMeshes) {
  // Body: the cube [0,1]^2 x [0,1] on the wall z = 0 (faces counter-clockwise seen from outside the
  // solid, the bottom left open); box: [-2,2]^2 x [0,3] (faces counter-clockwise seen from inside).
  using V = Eigen::Vector3d;
  std::vector<surface::SurfaceMesh> body = {
      quad_surface({V(0, 0, 1), V(1, 0, 1), V(1, 1, 1), V(0, 1, 1)}),  // top, normal +z
      quad_surface({V(0, 0, 0), V(1, 0, 0), V(1, 0, 1), V(0, 0, 1)}),  // y = 0, normal -y
      quad_surface({V(1, 1, 0), V(0, 1, 0), V(0, 1, 1), V(1, 1, 1)}),  // y = 1, normal +y
      quad_surface({V(0, 1, 0), V(0, 0, 0), V(0, 0, 1), V(0, 1, 1)}),  // x = 0, normal -x
      quad_surface({V(1, 0, 0), V(1, 1, 0), V(1, 1, 1), V(1, 0, 1)}),  // x = 1, normal +x
  };
  std::vector<surface::SurfaceMesh> box = {
      quad_surface({V(-2, -2, 3), V(-2, 2, 3), V(2, 2, 3), V(2, -2, 3)}),    // top, normal -z
      quad_surface({V(-2, -2, 0), V(-2, -2, 3), V(2, -2, 3), V(2, -2, 0)}),  // y = -2, normal +y
      quad_surface({V(2, 2, 0), V(2, 2, 3), V(-2, 2, 3), V(-2, 2, 0)}),      // y = 2, normal -y
      quad_surface({V(-2, 2, 0), V(-2, 2, 3), V(-2, -2, 3), V(-2, -2, 0)}),  // x = -2, normal +x
      quad_surface({V(2, -2, 0), V(2, -2, 3), V(2, 2, 3), V(2, 2, 0)}),      // x = 2, normal -x
  };
  surface::SurfaceMesh wall = quad_surface({V(-2, -2, 0), V(2, -2, 0), V(2, 2, 0), V(-2, 2, 0)});
  std::vector<const surface::SurfaceMesh*> body_ptr, box_ptr;
  for (const auto& s : body) body_ptr.push_back(&s);
  for (const auto& s : box) box_ptr.push_back(&s);
  EXPECT_NEAR(volume_under_surfaces(body_ptr, V(5, 5, 0), V(0, 0, 1)), 1.0, 1e-14);
  const VolumeCheck check = check_volume(TwoTets().mesh, body_ptr, box_ptr, wall);
  EXPECT_NEAR(check.body_volume, 1.0, 1e-14);
  EXPECT_NEAR(check.box_volume, 48.0, 1e-12);
  EXPECT_NEAR(check.expected_volume(), 47.0, 1e-12);
  EXPECT_NEAR(check.expected_relative_error(), std::abs(1.0 / 3.0 - 47.0) / 47.0, 1e-12);
}

surface::SurfaceMesh triangle_surface(std::vector<Eigen::Vector3d> points, std::vector<std::array<int, 3>> triangles) {
  surface::SurfaceMesh s;
  s.points = std::move(points);
  s.triangles = std::move(triangles);
  return s;
}

// A curved wall: no plane closes the fluid, so the wall's own flux counts. The box [-2,2]^2 x [0,3]
// stands on a roof z = 0.5 (1 - |x| / 2) (two planar quads, the ridge along y at x = 0): the fluid
// is 48 minus the roof's prism, 4 x (4 x 0.5 / 2) = 4. Faces counter-clockwise seen from the fluid.
TEST(Volume, CurvedWallBoundsTheFluidWithItsOwnFlux) {
  using V = Eigen::Vector3d;
  std::vector<surface::SurfaceMesh> box = {
      quad_surface({V(-2, -2, 3), V(-2, 2, 3), V(2, 2, 3), V(2, -2, 3)}),    // top, normal -z
      quad_surface({V(-2, 2, 0), V(-2, 2, 3), V(-2, -2, 3), V(-2, -2, 0)}),  // x = -2, normal +x
      quad_surface({V(2, -2, 0), V(2, -2, 3), V(2, 2, 3), V(2, 2, 0)}),      // x = 2, normal -x
      // y = -2 and y = 2: pentagons over the roof's gable, normals +y and -y
      triangle_surface({V(-2, -2, 0), V(0, -2, 0.5), V(2, -2, 0), V(2, -2, 3), V(-2, -2, 3)}, {{0, 4, 3}, {0, 3, 1}, {1, 3, 2}}),
      triangle_surface({V(-2, 2, 0), V(0, 2, 0.5), V(2, 2, 0), V(2, 2, 3), V(-2, 2, 3)}, {{0, 3, 4}, {0, 1, 3}, {1, 2, 3}}),
  };
  const surface::SurfaceMesh roof =
      triangle_surface({V(-2, -2, 0), V(0, -2, 0.5), V(0, 2, 0.5), V(-2, 2, 0), V(2, -2, 0), V(2, 2, 0)},
                       {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}});
  std::vector<const surface::SurfaceMesh*> box_ptr;
  for (const auto& s : box) box_ptr.push_back(&s);
  const VolumeCheck check = check_volume_curved_wall(TwoTets().mesh, {}, box_ptr, roof);
  EXPECT_NEAR(check.body_volume, 0.0, 1e-14);
  EXPECT_NEAR(check.expected_volume(), 44.0, 1e-12);
  // The planar formula, closing the fluid by the wall's mean plane, misses the roof.
  EXPECT_GT(std::abs(check_volume(TwoTets().mesh, {}, box_ptr, roof).expected_volume() - 44.0), 1.0);
}

// On a planar wall (with the body's footprint as its hole) both formulas agree.
TEST(Volume, CurvedWallFormulaAgreesWithThePlanarOneOnAPlane) {
  using V = Eigen::Vector3d;
  std::vector<surface::SurfaceMesh> body = {
      quad_surface({V(0, 0, 1), V(1, 0, 1), V(1, 1, 1), V(0, 1, 1)}),
      quad_surface({V(0, 0, 0), V(1, 0, 0), V(1, 0, 1), V(0, 0, 1)}),
      quad_surface({V(1, 1, 0), V(0, 1, 0), V(0, 1, 1), V(1, 1, 1)}),
      quad_surface({V(0, 1, 0), V(0, 0, 0), V(0, 0, 1), V(0, 1, 1)}),
      quad_surface({V(1, 0, 0), V(1, 1, 0), V(1, 1, 1), V(1, 0, 1)}),
  };
  std::vector<surface::SurfaceMesh> box = {
      quad_surface({V(-2, -2, 3), V(-2, 2, 3), V(2, 2, 3), V(2, -2, 3)}),
      quad_surface({V(-2, -2, 0), V(-2, -2, 3), V(2, -2, 3), V(2, -2, 0)}),
      quad_surface({V(2, 2, 0), V(2, 2, 3), V(-2, 2, 3), V(-2, 2, 0)}),
      quad_surface({V(-2, 2, 0), V(-2, 2, 3), V(-2, -2, 3), V(-2, -2, 0)}),
      quad_surface({V(2, -2, 0), V(2, -2, 3), V(2, 2, 3), V(2, 2, 0)}),
  };
  // The wall z = 0 around the body's square [0,1]^2: four quads, normal +z.
  const surface::SurfaceMesh wall = triangle_surface(
      {V(-2, -2, 0), V(2, -2, 0), V(2, 2, 0), V(-2, 2, 0), V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0)},
      {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}});
  std::vector<const surface::SurfaceMesh*> body_ptr, box_ptr;
  for (const auto& s : body) body_ptr.push_back(&s);
  for (const auto& s : box) box_ptr.push_back(&s);
  const VolumeCheck planar = check_volume(TwoTets().mesh, body_ptr, box_ptr, wall);
  const VolumeCheck curved = check_volume_curved_wall(TwoTets().mesh, body_ptr, box_ptr, wall);
  EXPECT_NEAR(planar.expected_volume(), 47.0, 1e-12);
  EXPECT_NEAR(curved.expected_volume(), 47.0, 1e-12);
}

TEST(Validity, InvertedElementIsCountedAndLocated) {
  TwoTets t;
  ValidityResult ok = check_validity(t.mesh);
  EXPECT_EQ(ok.elements, 2u);
  EXPECT_EQ(ok.invalid, 0u);
  EXPECT_NEAR(ok.min_scaled_jacobian, 1.0, 1e-12);  // affine elements: constant det J

  Mesh m(1);
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                   Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -1)})
    m.add_node(p);
  m.add_element(ho::Shape::Tetrahedron, {0, 1, 2, 3});
  m.add_element(ho::Shape::Tetrahedron, {0, 1, 2, 4});  // negative orientation
  const ValidityResult bad = check_validity(m);
  EXPECT_EQ(bad.invalid, 1u);
  ASSERT_EQ(bad.worst.size(), 1u);
  EXPECT_EQ(bad.worst[0].element, 1u);
  EXPECT_NEAR(bad.worst[0].centroid.z(), -0.25, 1e-15);
  EXPECT_LT(bad.min_scaled_jacobian, 0.0);
}

}  // namespace
}  // namespace semimesh::checks
