// Mesh data model: shared entities, orientation of shared faces, canonical assembly, CAD setter.
#include "semimesh/mesh/mesh.hpp"
#include "semimesh/mesh/node_layout.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <tuple>

namespace {

using semimesh::ho::NodeSet;
using semimesh::ho::Shape;
using semimesh::mesh::CadAttachment;
using semimesh::mesh::Mesh;
using semimesh::mesh::NodeId;

// Straight-sided map of the reference element onto physical vertices (P1 shape functions written
// here from the Gmsh reference elements, independent of the library).
Eigen::Vector3d straight_map(Shape shape, const std::vector<Eigen::Vector3d>& v, const Eigen::Vector3d& r) {
  if (shape == Shape::Tetrahedron) return (1 - r[0] - r[1] - r[2]) * v[0] + r[0] * v[1] + r[1] * v[2] + r[2] * v[3];
  if (shape == Shape::Triangle) return (1 - r[0] - r[1]) * v[0] + r[0] * v[1] + r[1] * v[2];
  if (shape == Shape::Prism) {  // triangle (0,0) (1,0) (0,1) times [-1, 1]
    const double bottom = (1 - r[2]) / 2, top = (1 + r[2]) / 2;
    const double w[3] = {1 - r[0] - r[1], r[0], r[1]};
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) x += w[k] * (bottom * v[k] + top * v[k + 3]);
    return x;
  }
  if (shape == Shape::Pyramid) {  // base [-1,1]^2 at z = 0 (vertices counter-clockwise from (-1,-1)), apex (0,0,1)
    if (r[2] > 1 - 1e-12) return v[4];
    const double s = r[0] / (1 - r[2]), t = r[1] / (1 - r[2]);
    const std::vector<Eigen::Vector3d> base(v.begin(), v.begin() + 4);
    return (1 - r[2]) * straight_map(Shape::Quadrilateral, base, Eigen::Vector3d(s, t, 0)) + r[2] * v[4];
  }
  if (shape == Shape::Quadrilateral)  // on [-1,1]^2, vertices counter-clockwise from (-1,-1)
    return ((1 - r[0]) * (1 - r[1]) * v[0] + (1 + r[0]) * (1 - r[1]) * v[1] + (1 + r[0]) * (1 + r[1]) * v[2] +
            (1 - r[0]) * (1 + r[1]) * v[3]) / 4.0;
  // Hexahedron on [-1,1]^3, vertices in Gmsh order.
  const std::array<std::array<int, 3>, 8> s = {
      {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}};
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int k = 0; k < 8; ++k)
    x += (1 + s[k][0] * r[0]) * (1 + s[k][1] * r[1]) * (1 + s[k][2] * r[2]) / 8.0 * v[k];
  return x;
}

// Adds the nodes of a straight element, reusing a node already at the same place.
struct NodeMaker {
  Mesh& mesh;
  std::map<std::array<long, 3>, NodeId> by_place;
  std::vector<Eigen::Vector3d> last_positions;

  std::vector<NodeId> element(Shape shape, int order, const std::vector<Eigen::Vector3d>& vertices) {
    const Eigen::MatrixX3d ref = semimesh::ho::reference_nodes(shape, order, NodeSet::Equispaced);
    std::vector<NodeId> ids;
    last_positions.clear();
    for (int i = 0; i < ref.rows(); ++i) {
      const Eigen::Vector3d x = straight_map(shape, vertices, ref.row(i).transpose());
      last_positions.push_back(x);
      const std::array<long, 3> key = {std::lround(x[0] * 1e6), std::lround(x[1] * 1e6), std::lround(x[2] * 1e6)};
      auto it = by_place.find(key);
      if (it == by_place.end()) it = by_place.emplace(key, mesh.add_node(x)).first;
      ids.push_back(it->second);
    }
    return ids;
  }
};

// Every face's nodes lie where the straight map of its stored vertices puts them (so its edges,
// and their directions, are the right ones), and its edge k joins its stored vertices k and k+1.
void expect_straight_faces(const Mesh& mesh) {
  for (std::size_t f = 0; f < mesh.faces().size(); ++f) {
    const auto& face = mesh.faces()[f];
    const Shape shape = face.num_vertices == 3 ? Shape::Triangle : Shape::Quadrilateral;
    std::vector<Eigen::Vector3d> v;
    for (int k = 0; k < face.num_vertices; ++k) {
      v.push_back(mesh.node(face.vertices[k]));
      const NodeId a = face.vertices[k], b = face.vertices[(k + 1) % face.num_vertices];
      const auto& edge = mesh.edges()[face.edges[k]].vertices;
      EXPECT_EQ(edge[0], std::min(a, b)) << "face " << f << " edge " << k;
      EXPECT_EQ(edge[1], std::max(a, b)) << "face " << f << " edge " << k;
    }
    const Eigen::MatrixX3d ref = semimesh::ho::reference_nodes(shape, mesh.order(), NodeSet::Equispaced);
    const auto ids = mesh.face_nodes(f);
    ASSERT_EQ(static_cast<long>(ids.size()), ref.rows());
    for (std::size_t i = 0; i < ids.size(); ++i)
      EXPECT_LT((mesh.node(ids[i]) - straight_map(shape, v, ref.row(i).transpose())).norm(), 1e-12)
          << "face " << f << " node " << i;
  }
}

void expect_rows(const Eigen::MatrixX3d& got, const std::vector<Eigen::Vector3d>& expected) {
  ASSERT_EQ(got.rows(), static_cast<long>(expected.size()));
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_LT((got.row(i).transpose() - expected[i]).norm(), 1e-12) << "node " << i;
}

TEST(MeshModel, TwoTetsShareAFaceInEveryVertexOrder) {
  const std::vector<Eigen::Vector3d> a = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Eigen::Vector3d apex(0.7, 0.8, 0.9);  // beyond face (1,2,3)
  std::array<int, 4> perm = {0, 1, 2, 3};
  int cases = 0;
  do {
    Mesh mesh(4);
    NodeMaker make{mesh, {}, {}};
    mesh.add_element(Shape::Tetrahedron, make.element(Shape::Tetrahedron, 4, a));
    const std::vector<Eigen::Vector3d> base = {a[1], a[2], a[3], apex};
    std::vector<Eigen::Vector3d> b;
    for (int k : perm) b.push_back(base[k]);
    const auto ids = make.element(Shape::Tetrahedron, 4, b);
    const auto expected = make.last_positions;
    mesh.add_element(Shape::Tetrahedron, ids);
    EXPECT_EQ(mesh.faces().size(), 7u);   // 4 + 4 - 1 shared
    EXPECT_EQ(mesh.edges().size(), 9u);   // 6 + 6 - 3 shared
    EXPECT_EQ(mesh.element_nodes(1), ids);
    expect_rows(mesh.element_coordinates(1), expected);
    expect_straight_faces(mesh);
    ++cases;
  } while (std::next_permutation(perm.begin(), perm.end()));
  EXPECT_EQ(cases, 24);
}

TEST(MeshModel, TwoHexesShareAQuadInEveryOrientation) {
  // Hex A on [0,1]^3; hex B on [1,2]x[0,1]^2 listed with its vertices rotated/reflected so that
  // the shared face x = 1 appears in all 8 dihedral orientations.
  const std::vector<Eigen::Vector3d> a = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                          {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::set<std::vector<NodeId>> distinct_faces_seen;
  for (int rot = 0; rot < 4; ++rot)
    for (int flip = 0; flip < 2; ++flip) {
      Mesh mesh(3);
      NodeMaker make{mesh, {}, {}};
      mesh.add_element(Shape::Hexahedron, make.element(Shape::Hexahedron, 3, a));
      // B's reference x-axis points along +x; rotate (y,z) about the x axis, optionally mirror
      // (handedness does not matter to the data model).
      std::vector<Eigen::Vector3d> b;
      for (const auto& p : a) {
        double y = p[1] - 0.5, z = p[2] - 0.5;
        for (int r = 0; r < rot; ++r) std::tie(y, z) = std::make_pair(-z, y);
        if (flip) y = -y;
        b.emplace_back(p[0] + 1.0, y + 0.5, z + 0.5);
      }
      const auto ids = make.element(Shape::Hexahedron, 3, b);
      const auto expected = make.last_positions;
      mesh.add_element(Shape::Hexahedron, ids);
      EXPECT_EQ(mesh.faces().size(), 11u);
      EXPECT_EQ(mesh.edges().size(), 20u);
      EXPECT_EQ(mesh.element_nodes(1), ids);
      // Any subset of the canonical positions, in any order, without assembling the rest.
      const std::vector<int> positions{63, 0, 17, 8, 40, 7, 25};
      std::vector<NodeId> subset;
      mesh.element_nodes_at(1, positions, subset);
      ASSERT_EQ(subset.size(), positions.size());
      for (std::size_t k = 0; k < positions.size(); ++k) EXPECT_EQ(subset[k], ids[positions[k]]) << positions[k];
      expect_rows(mesh.element_coordinates(1), expected);
      expect_straight_faces(mesh);
      distinct_faces_seen.insert(std::vector<NodeId>(mesh.elements()[1].face_orientation.begin(),
                                                     mesh.elements()[1].face_orientation.end()));
    }
  EXPECT_GE(distinct_faces_seen.size(), 4u);  // the shared face really met several orientations
}

// The vertex permutations that map the shape's edges onto its edges and its faces onto its faces
// (its rotations and reflections).
std::vector<std::vector<int>> symmetries(Shape shape) {
  const int n = semimesh::ho::num_vertices(shape);
  const auto sorted = [](std::vector<int> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  std::set<std::vector<int>> edges, faces;
  for (const auto& e : semimesh::ho::edges(shape)) edges.insert(sorted({e[0], e[1]}));
  for (const auto& f : semimesh::ho::faces(shape)) faces.insert(sorted(f));
  std::vector<int> perm(n);
  std::iota(perm.begin(), perm.end(), 0);
  std::vector<std::vector<int>> out;
  do {
    bool kept = true;
    for (const auto& e : semimesh::ho::edges(shape)) kept = kept && edges.count(sorted({perm[e[0]], perm[e[1]]}));
    for (const auto& f : semimesh::ho::faces(shape)) {
      std::vector<int> image;
      for (int v : f) image.push_back(perm[v]);
      kept = kept && faces.count(sorted(image));
    }
    if (kept) out.push_back(perm);
  } while (std::next_permutation(perm.begin(), perm.end()));
  return out;
}

// Mesh::assemble gathers an element's nodes by runs (its vertices, each edge's nodes forwards or
// backwards, each face's as stored or through its slots, its interior's); its reference gathers
// them slot by slot. Pinned together: an element and the same element listed from every symmetry
// of its shape (so its edges meet both directions and its faces every orientation code), at orders
// 1 to 5, and boundary faces on its faces listed from each of their rotations and reflections.
TEST(MeshModel, AssemblyByRunsGivesTheSlotBySlotReferencesNodes) {
  const std::map<Shape, std::vector<Eigen::Vector3d>> vertices{
      {Shape::Tetrahedron, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
      {Shape::Pyramid, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0.7}}},
      {Shape::Prism, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}},
      {Shape::Hexahedron, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}}};
  int elements = 0, boundary_faces = 0;
  std::set<int> codes_met;
  for (const auto& [shape, v] : vertices)
    for (int order = 1; order <= 5; ++order) {
      Mesh mesh(order);
      NodeMaker make{mesh, {}, {}};
      mesh.add_element(shape, make.element(shape, order, v));
      for (const std::vector<int>& perm : symmetries(shape)) {
        std::vector<Eigen::Vector3d> moved;
        for (int k : perm) moved.push_back(v[k]);
        const std::vector<NodeId> ids = make.element(shape, order, moved);
        const std::size_t e = mesh.add_element(shape, ids);
        EXPECT_EQ(mesh.element_nodes(e), ids);
        for (int f = 0; f < static_cast<int>(semimesh::ho::faces(shape).size()); ++f)
          codes_met.insert(mesh.elements()[e].face_orientation[f]);
      }
      for (const auto& f : semimesh::ho::faces(shape)) {
        const Shape face_shape = f.size() == 3 ? Shape::Triangle : Shape::Quadrilateral;
        std::vector<Eigen::Vector3d> corners;
        for (int k : f) corners.push_back(v[k]);
        for (const std::vector<int>& perm : symmetries(face_shape)) {
          std::vector<Eigen::Vector3d> moved;
          for (int k : perm) moved.push_back(corners[k]);
          const std::vector<NodeId> ids = make.element(face_shape, order, moved);
          const std::size_t b = mesh.add_boundary_face("skin", face_shape, ids);
          EXPECT_EQ(mesh.boundary_face_nodes(b), ids);
          EXPECT_EQ(mesh.boundary_face_nodes(b), mesh.boundary_face_nodes_by_slots(b));
          ++boundary_faces;
        }
      }
      for (std::size_t e = 0; e < mesh.elements().size(); ++e, ++elements)
        EXPECT_EQ(mesh.element_nodes(e), mesh.element_nodes_by_slots(e)) << semimesh::ho::to_string(shape) << " order "
                                                                          << order << " element " << e;
    }
  EXPECT_EQ(codes_met.size(), 8u);  // every orientation code of a quadrilateral (a triangle's are among them)
  // The runs are those of every layout the mesh can use (node_layout refuses one out of blocks).
  for (Shape shape : {Shape::Triangle, Shape::Quadrilateral, Shape::Tetrahedron, Shape::Pyramid, Shape::Prism,
                      Shape::Hexahedron})
    for (int order = 1; order <= semimesh::ho::kMaxOrder; ++order)
      EXPECT_NO_THROW(semimesh::mesh::node_layout(shape, order)) << semimesh::ho::to_string(shape) << " " << order;
  EXPECT_EQ(elements, 5 * (1 + 24) + 5 * (1 + 8) + 5 * (1 + 12) + 5 * (1 + 48));
  EXPECT_EQ(boundary_faces, 5 * (4 * 6) + 5 * (4 * 6 + 8) + 5 * (2 * 6 + 3 * 8) + 5 * (6 * 8));
}

TEST(MeshModel, SharedNodesAreOwnedOnceEvenIfGivenTwice) {
  // Two order-2 tets whose shared face nodes are given as separate, coincident nodes.
  Mesh mesh(2);
  NodeMaker first{mesh, {}, {}};
  const std::vector<Eigen::Vector3d> a = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const auto ida = first.element(Shape::Tetrahedron, 2, a);
  mesh.add_element(Shape::Tetrahedron, ida);
  NodeMaker second{mesh, {}, {}};  // knows none of the first element's nodes
  const std::vector<Eigen::Vector3d> b = {a[1], a[3], a[2], {1, 1, 1}};
  auto idb = second.element(Shape::Tetrahedron, 2, b);
  // Vertices must be shared ids (they key the entities); edge nodes may be duplicates.
  idb[0] = ida[1];
  idb[1] = ida[3];
  idb[2] = ida[2];
  mesh.add_element(Shape::Tetrahedron, idb);
  const auto nodes_b = mesh.element_nodes(1);
  std::set<NodeId> used(ida.begin(), ida.end());
  used.insert(nodes_b.begin(), nodes_b.end());
  EXPECT_EQ(used.size(), 10u + 10u - 6u);  // the shared triangle's 6 nodes are stored once
  expect_rows(mesh.element_coordinates(1), second.last_positions);
}

TEST(MeshModel, RejectsNonConformingOrMisorderedNodes) {
  Mesh mesh(3);
  NodeMaker make{mesh, {}, {}};
  const std::vector<Eigen::Vector3d> a = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.add_element(Shape::Tetrahedron, make.element(Shape::Tetrahedron, 3, a));
  auto ids = make.element(Shape::Tetrahedron, 3, {a[1], a[2], a[3], {1, 1, 1}});
  std::swap(ids[4], ids[5]);  // the two nodes inside edge 0 (shared with the first tet) swapped
  EXPECT_THROW(mesh.add_element(Shape::Tetrahedron, ids), std::invalid_argument);
  EXPECT_THROW(mesh.add_element(Shape::Tetrahedron, std::vector<NodeId>(5, 0)), std::invalid_argument);
  EXPECT_THROW(mesh.add_element(Shape::Triangle, std::vector<NodeId>(10, 0)), std::invalid_argument);
  EXPECT_THROW(Mesh(0), std::invalid_argument);
}

TEST(MeshModel, BoundaryFaceSharesTheVolumeFace) {
  Mesh mesh(4);
  NodeMaker make{mesh, {}, {}};
  const std::vector<Eigen::Vector3d> a = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.add_element(Shape::Tetrahedron, make.element(Shape::Tetrahedron, 4, a));
  // Bottom face z = 0 seen from outside: (0, 2, 1).
  const auto ids = make.element(Shape::Triangle, 4, {a[0], a[2], a[1]});
  const auto expected = make.last_positions;
  const std::size_t nodes_before = mesh.num_nodes();
  mesh.add_boundary_face("wall", Shape::Triangle, ids);
  EXPECT_EQ(mesh.num_nodes(), nodes_before);  // no new node: all on the tet's face
  EXPECT_EQ(mesh.faces().size(), 4u);
  EXPECT_EQ(mesh.group_names(), std::vector<std::string>{"wall"});
  const auto got = mesh.boundary_face_nodes(0);
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_LT((mesh.node(got[i]) - expected[i]).norm(), 1e-12);
}

TEST(MeshModel, EdgeAndFaceNodeListsFollowTheStoredDirection) {
  Mesh mesh(5);
  NodeMaker make{mesh, {}, {}};
  const std::vector<Eigen::Vector3d> a = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.add_element(Shape::Tetrahedron, make.element(Shape::Tetrahedron, 5, a));
  for (std::size_t e = 0; e < mesh.edges().size(); ++e) {
    const auto ids = mesh.edge_nodes(e);
    ASSERT_EQ(ids.size(), 6u);
    EXPECT_LT(ids.front(), ids.back());
    const Eigen::Vector3d p0 = mesh.node(ids.front()), p1 = mesh.node(ids.back());
    for (std::size_t k = 0; k < ids.size(); ++k)
      EXPECT_LT((mesh.node(ids[k]) - (p0 + (p1 - p0) * (k / 5.0))).norm(), 1e-12);
  }
  for (std::size_t f = 0; f < mesh.faces().size(); ++f) {
    const auto& face = mesh.faces()[f];
    std::vector<Eigen::Vector3d> v;
    for (int k = 0; k < 3; ++k) v.push_back(mesh.node(face.vertices[k]));
    const Eigen::MatrixX3d ref = semimesh::ho::reference_nodes(Shape::Triangle, 5, NodeSet::Equispaced);
    const auto ids = mesh.face_nodes(f);
    ASSERT_EQ(static_cast<long>(ids.size()), ref.rows());
    for (std::size_t i = 0; i < ids.size(); ++i)
      EXPECT_LT((mesh.node(ids[i]) - straight_map(Shape::Triangle, v, ref.row(i).transpose())).norm(), 1e-12);
  }
}

TEST(MeshModel, CadAttachmentMovesWithTheNode) {
  Mesh mesh(1);
  const NodeId free_node = mesh.add_node({0, 0, 0});
  const NodeId on_curve = mesh.add_node({1, 0, 0}, {CadAttachment::Curve, 7, 0.25, 0.0});
  mesh.place_node(free_node, {0, 0, 1});
  EXPECT_EQ(mesh.node(free_node), Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(mesh.cad_attachment(free_node).kind, CadAttachment::None);
  EXPECT_THROW(mesh.place_node(on_curve, {2, 0, 0}), std::logic_error);
  EXPECT_EQ(mesh.node(on_curve), Eigen::Vector3d(1, 0, 0));
  mesh.place_node_on_cad(on_curve, {2, 0, 0}, {CadAttachment::Curve, 7, 0.5, 0.0});
  EXPECT_EQ(mesh.node(on_curve), Eigen::Vector3d(2, 0, 0));
  EXPECT_EQ(mesh.cad_attachment(on_curve).u, 0.5);
  EXPECT_EQ(mesh.cad_attachment(on_curve).entity, 7);
  mesh.place_node_on_cad(on_curve, {3, 0, 0}, {});
  EXPECT_EQ(mesh.cad_attachment(on_curve).kind, CadAttachment::None);
  mesh.place_node(on_curve, {4, 0, 0});
}

// copy_nodes: the nodes and attachments add_node of each would give, into the room reserved; a
// mesh with nodes already refuses it.
TEST(MeshModel, CopiedNodesAreTheOnesAddedOneByOne) {
  Mesh source(1);
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector3d x(i, 0.5 * i, -i);
    source.add_node(x, i % 7 == 0 ? CadAttachment{CadAttachment::Surface, i % 3, 0.1 * i, 0.2} : CadAttachment{});
  }
  Mesh copy(3), reference(3);
  copy.reserve_nodes(80);
  const Eigen::Vector3d* room = copy.nodes().data();
  copy.copy_nodes(source);
  for (NodeId v = 0; v < source.num_nodes(); ++v) reference.add_node(source.node(v), source.cad_attachment(v));
  EXPECT_EQ(copy.nodes(), reference.nodes());
  EXPECT_EQ(copy.nodes().data(), room) << "the reserved room is used, not reallocated";
  for (NodeId v = 0; v < source.num_nodes(); ++v) {
    EXPECT_EQ(copy.cad_attachment(v).kind, reference.cad_attachment(v).kind) << v;
    EXPECT_EQ(copy.cad_attachment(v).entity, reference.cad_attachment(v).entity) << v;
    EXPECT_EQ(copy.cad_attachment(v).u, reference.cad_attachment(v).u) << v;
  }
  EXPECT_THROW(copy.copy_nodes(source), std::logic_error);
}

TEST(MeshModel, ElementsKeepTheirRegion) {
  Mesh m(1);
  NodeMaker maker{m, {}, {}};
  EXPECT_EQ(m.region_names(), std::vector<std::string>{"fluid"});
  const int layer = m.region_index("wing_layer");
  const int far = m.region_index("farfield");
  EXPECT_EQ(m.region_index("wing_layer"), layer);  // found, not created twice
  const Eigen::Vector3d o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  m.add_element(Shape::Tetrahedron, maker.element(Shape::Tetrahedron, 1, {o, x, y, z}), far);
  m.add_element(Shape::Tetrahedron, maker.element(Shape::Tetrahedron, 1, {x, y, z, Eigen::Vector3d(1, 1, 1)}), layer);
  EXPECT_EQ(m.elements()[0].region, far);
  EXPECT_EQ(m.elements()[1].region, layer);
  EXPECT_THROW(m.add_element(Shape::Tetrahedron, maker.element(Shape::Tetrahedron, 1, {o, x, y, -z}), 3),
               std::invalid_argument);

  Mesh copy(2);
  copy.copy_regions_from(m);
  EXPECT_EQ(copy.region_names(), m.region_names());
  Mesh other(1);
  other.region_index("wake");
  EXPECT_THROW(other.copy_regions_from(m), std::logic_error);
}

// 6 x 6 x 6 hexes of order 1 (882 edges, 756 faces), the lookups sized first for `edges` and
// `faces` (0: not at all, so they grow many times).
Mesh hex_lattice(std::size_t edges, std::size_t faces) {
  Mesh mesh(1);
  if (edges + faces > 0) mesh.reserve_lookups(edges, faces);
  NodeMaker make{mesh, {}, {}};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) {
        std::vector<Eigen::Vector3d> v;
        for (const auto& c : std::vector<std::array<int, 3>>{
                 {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}})
          v.emplace_back(i + c[0], j + c[1], k + c[2]);
        mesh.add_element(Shape::Hexahedron, make.element(Shape::Hexahedron, 1, v));
      }
  return mesh;
}

TEST(MeshModel, FindsEveryEdgeAndFaceByItsVerticesInAnyOrder) {
  // Grown, sized exactly, sized too small and too large: the same entities, each found.
  const Mesh grown = hex_lattice(0, 0);
  for (const auto& [edges, faces] : std::vector<std::pair<std::size_t, std::size_t>>{{0, 0}, {882, 756}, {10, 20}, {5000, 9000}}) {
    SCOPED_TRACE("lookups sized for " + std::to_string(edges) + " edges, " + std::to_string(faces) + " faces");
    const Mesh mesh = hex_lattice(edges, faces);
    ASSERT_EQ(mesh.edges().size(), 882u);
    ASSERT_EQ(mesh.faces().size(), 756u);
    for (std::size_t e = 0; e < mesh.edges().size(); ++e) {
      const auto& v = mesh.edges()[e].vertices;
      ASSERT_EQ(v, grown.edges()[e].vertices);
      ASSERT_EQ(mesh.find_edge(v[0], v[1]), static_cast<long>(e));
      ASSERT_EQ(mesh.find_edge(v[1], v[0]), static_cast<long>(e));
    }
    for (std::size_t f = 0; f < mesh.faces().size(); ++f) {
      ASSERT_EQ(mesh.faces()[f].vertices, grown.faces()[f].vertices);
      std::vector<NodeId> v(mesh.faces()[f].vertices.begin(), mesh.faces()[f].vertices.begin() + 4);
      ASSERT_EQ(mesh.find_face(v), static_cast<long>(f));
      std::reverse(v.begin(), v.end());
      ASSERT_EQ(mesh.find_face(v), static_cast<long>(f));
      std::rotate(v.begin(), v.begin() + 1, v.end());
      ASSERT_EQ(mesh.find_face(v), static_cast<long>(f));
    }
    // Vertices 0 and the lattice's far corner share no edge; three vertices of a quad are no face.
    EXPECT_EQ(mesh.find_edge(0, static_cast<NodeId>(mesh.num_nodes() - 1)), -1);
    const auto& quad = mesh.faces()[0].vertices;
    EXPECT_EQ(mesh.find_face({quad[0], quad[1], quad[2]}), -1);
  }
}

TEST(MeshModel, MemoryPerElementIsModest) {
  // 2 x 2 x 2 hexes of order 4 on a shared lattice.
  Mesh mesh(4);
  NodeMaker make{mesh, {}, {}};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        std::vector<Eigen::Vector3d> v;
        for (const auto& c : std::vector<std::array<int, 3>>{
                 {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}})
          v.emplace_back(i + c[0], j + c[1], k + c[2]);
        mesh.add_element(Shape::Hexahedron, make.element(Shape::Hexahedron, 4, v));
      }
  EXPECT_EQ(mesh.num_nodes(), 9u * 9u * 9u);
  EXPECT_EQ(mesh.edges().size(), 54u);  // 3 directions x 2 x 3 x 3
  EXPECT_EQ(mesh.faces().size(), 36u);  // 3 directions x 3 x 2 x 2
  const double per_element = static_cast<double>(mesh.memory_bytes()) / mesh.elements().size();
  EXPECT_GT(per_element, 125 * 24.0 / 8);   // at least the coordinates, shared ~8 ways
  EXPECT_LT(per_element, 125 * 24.0 * 4);   // far less than 4 private copies of the nodes
}

}  // namespace
