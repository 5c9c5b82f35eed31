// Test helper: writes one curved element per shape and order in every format, for the independent
// readers in tests/io/*.py. The element is the image of the reference element under a polynomial
// map of degree P (so every Lagrange element of order P reproduces it exactly); verify_*.py define
// the same map and compare.
//
// usage: io_write_samples OUTDIR
//   OUTDIR/{tet,pyr,pri,hex}_P.msh       MSH 4.1, P = 1..9 (kMaxMshOrder), equispaced nodes
//   OUTDIR/{...}_P_v22.msh               MSH 2.2
//   OUTDIR/{...}_P_gll.msh               MSH 4.1 written from a GLL-node mesh (resampled), P >= 2
//   OUTDIR/{...}_P_invalid.msh           MSH 4.1 of a folded element (det J = 1 - 3 y < 0 in part), P >= 2
//   OUTDIR/{...}_P_bin.msh               MSH 4.1 binary
//   OUTDIR/{...}_P.vtu, {...}_P_z.vtu    VTU ASCII and compressed binary
//   OUTDIR/{...}_P.xml, {...}_P_z.xml    Nektar++ XML plain and compressed
// Each file also holds every face of the element as a boundary face (groups "tri", "quad").
//   OUTDIR/fix_{NAME}_P.xml, _P_z.xml    multi-element fixtures for the Nektar++ rules, P = 1, 2, 4:
//     tets_ab / tets_ba (two tets sharing a face, created in both orders), stack (three prisms
//     stacked, triangles listed from different vertices, a tet on top), pyr_tet (a pyramid and a
//     tet sharing a triangle), hex_prism (a hex and a prism sharing a quad); outer faces in group "wall".
#include "semimesh/io/gmsh_types.hpp"
#include "semimesh/io/msh.hpp"
#include "semimesh/io/nektar.hpp"
#include "semimesh/io/vtu.hpp"

#include "semimesh/ho/basis.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <map>
#include <cstdio>
#include <exception>
#include <string>

namespace {

using semimesh::ho::NodeSet;
using semimesh::ho::Shape;

// Must match curved_map() in tests/io/sample_map.py.
Eigen::Vector3d curved_map(const Eigen::Vector3d& r, int p) {
  const double a = r[0], b = r[1], c = r[2];
  const double s1 = 0.3 * a + 0.5 * b - 0.2 * c + 0.1;
  const double s2 = -0.4 * a + 0.2 * b + 0.6 * c - 0.3;
  const double s3 = 0.5 * a - 0.3 * b + 0.4 * c + 0.2;
  const double k = 0.1 / p;  // keeps det J > 0 on every reference element up to order 9
  return {a + k * std::pow(s1, p) + 0.05 * s2, b + k * std::pow(s2, p) + 0.05 * s3, c + k * std::pow(s3, p) + 0.05 * s1};
}

// Folded: y' = y - 1.5 y^2, so det J = 1 - 3y changes sign inside every reference element.
Eigen::Vector3d folded_map(const Eigen::Vector3d& r) { return {r[0], r[1] - 1.5 * r[1] * r[1], r[2]}; }

template <typename Map>
semimesh::mesh::Mesh one_element(Shape shape, int order, NodeSet set, Map map) {
  semimesh::mesh::Mesh mesh(order, set);
  const Eigen::MatrixX3d ref = semimesh::ho::reference_nodes(shape, order, set);
  std::vector<semimesh::mesh::NodeId> ids;
  for (int i = 0; i < ref.rows(); ++i) ids.push_back(mesh.add_node(map(ref.row(i).transpose())));
  mesh.add_element(shape, ids);
  for (std::size_t f = 0; f < mesh.faces().size(); ++f) {
    const bool tri = mesh.faces()[f].num_vertices == 3;
    mesh.add_boundary_face(tri ? "tri" : "quad", tri ? Shape::Triangle : Shape::Quadrilateral, mesh.face_nodes(f));
  }
  return mesh;
}

// ---- multi-element fixtures --------------------------------------------------------------------

using Vertices = std::vector<Eigen::Vector3d>;

/// Elements given by their straight-sided vertices, nodes shared by position, then gently curved.
class Fixture {
 public:
  explicit Fixture(int order) : order_(order) {}
  void add(Shape shape, Vertices v) {
    orient(shape, v);
    elements_.push_back({shape, v});
  }
  semimesh::mesh::Mesh build() const {
    semimesh::mesh::Mesh mesh(order_, NodeSet::Equispaced);
    std::map<std::array<long long, 3>, semimesh::mesh::NodeId> at;
    for (const auto& [shape, v] : elements_) {
      const Eigen::MatrixXd lift =
          semimesh::ho::interpolation_matrix(semimesh::ho::LagrangeBasis(shape, 1, NodeSet::Equispaced),
                                             semimesh::ho::LagrangeBasis(shape, order_, NodeSet::Equispaced));
      Eigen::MatrixX3d corners(v.size(), 3);
      for (std::size_t k = 0; k < v.size(); ++k) corners.row(k) = v[k].transpose();
      const Eigen::MatrixX3d x = lift * corners;
      std::vector<semimesh::mesh::NodeId> ids;
      for (int i = 0; i < x.rows(); ++i) {
        const std::array<long long, 3> key{std::llround(x(i, 0) * 1e9), std::llround(x(i, 1) * 1e9),
                                           std::llround(x(i, 2) * 1e9)};
        auto it = at.find(key);
        if (it == at.end()) it = at.emplace(key, mesh.add_node(warp(x.row(i).transpose()))).first;
        ids.push_back(it->second);
      }
      mesh.add_element(shape, ids);
    }
    // Faces used by one element only are the boundary.
    std::map<std::size_t, int> uses;
    for (const auto& el : mesh.elements())
      for (int f = 0; f < static_cast<int>(semimesh::ho::faces(el.shape).size()); ++f) ++uses[el.faces[f]];
    for (const auto& [f, n] : uses)
      if (n == 1)
        mesh.add_boundary_face("wall", mesh.faces()[f].num_vertices == 3 ? Shape::Triangle : Shape::Quadrilateral,
                               mesh.face_nodes(f));
    return mesh;
  }

 private:
  static double volume(const Vertices& v, int a, int b, int c) {
    return (v[a] - v[0]).dot((v[b] - v[0]).cross(v[c] - v[0]));
  }
  /// Swaps vertices so that the Gmsh numbering is right-handed.
  static void orient(Shape shape, Vertices& v) {
    if (shape == Shape::Tetrahedron && volume(v, 1, 2, 3) < 0) std::swap(v[1], v[2]);
    if (shape == Shape::Prism && volume(v, 1, 2, 3) < 0) std::swap(v[1], v[2]), std::swap(v[4], v[5]);
  }
  static Eigen::Vector3d warp(const Eigen::Vector3d& x) {
    return x + 0.02 * Eigen::Vector3d(std::sin(3 * x[1] + 1), std::sin(2 * x[2] + 0.5), std::sin(2.5 * x[0]));
  }
  int order_;
  std::vector<std::pair<Shape, Vertices>> elements_;
};

void write_fixtures(const std::string& dir) {
  using V = Eigen::Vector3d;
  const Vertices tet_a{V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)};
  const Vertices tet_b{V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), V(1, 1, 1)};
  for (int p : {1, 2, 4}) {
    Fixture ab(p), ba(p), stack(p), pyr_tet(p), hex_prism(p);
    ab.add(Shape::Tetrahedron, tet_a), ab.add(Shape::Tetrahedron, tet_b);
    ba.add(Shape::Tetrahedron, tet_b), ba.add(Shape::Tetrahedron, tet_a);
    const double z[] = {0, 0.3, 0.6, 1.0};
    const V tri[] = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)};
    for (int layer = 0; layer < 3; ++layer) {
      Vertices v;
      for (int half = 0; half < 2; ++half)
        for (int k = 0; k < 3; ++k) v.push_back(tri[(k + layer) % 3] + V(0, 0, z[layer + half]));
      stack.add(Shape::Prism, v);
    }
    stack.add(Shape::Tetrahedron, {V(0, 0, 1), V(1, 0, 1), V(0, 1, 1), V(0.3, 0.3, 1.5)});
    const V apex(0.5, 0.5, 0.7);
    pyr_tet.add(Shape::Pyramid, {V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0), apex});
    pyr_tet.add(Shape::Tetrahedron, {V(1, 0, 0), V(1, 1, 0), apex, V(1.6, 0.5, 0.3)});
    hex_prism.add(Shape::Hexahedron, {V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0), V(0, 0, 1), V(1, 0, 1),
                                      V(1, 1, 1), V(0, 1, 1)});
    hex_prism.add(Shape::Prism, {V(1, 0, 0), V(1.5, 0, 0.5), V(1, 0, 1), V(1, 1, 0), V(1.5, 1, 0.5), V(1, 1, 1)});
    const std::pair<const char*, const Fixture*> all[] = {
        {"tets_ab", &ab}, {"tets_ba", &ba}, {"stack", &stack}, {"pyr_tet", &pyr_tet}, {"hex_prism", &hex_prism}};
    for (const auto& [name, fixture] : all) {
      const auto mesh = fixture->build();
      const std::string base = dir + "/fix_" + name + "_" + std::to_string(p);
      semimesh::io::write_nektar_xml(mesh, base + ".xml", semimesh::io::NektarEncoding::Plain);
      semimesh::io::write_nektar_xml(mesh, base + "_z.xml");
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTDIR\n", argv[0]);
    return 1;
  }
  const std::string dir = argv[1];
  const std::pair<Shape, const char*> shapes[] = {
      {Shape::Tetrahedron, "tet"}, {Shape::Pyramid, "pyr"}, {Shape::Prism, "pri"}, {Shape::Hexahedron, "hex"}};
  try {
    for (const auto& [shape, name] : shapes)
      for (int p = 1; p <= semimesh::io::kMaxMshOrder; ++p) {
        const std::string base = dir + "/" + name + "_" + std::to_string(p);
        auto curved = [p](const Eigen::Vector3d& r) { return curved_map(r, p); };
        const auto mesh = one_element(shape, p, NodeSet::Equispaced, curved);
        semimesh::io::write_msh(mesh, base + ".msh");
        semimesh::io::write_msh(mesh, base + "_v22.msh", semimesh::io::MshVersion::V22);
        semimesh::io::write_msh(mesh, base + "_bin.msh", semimesh::io::MshVersion::V41,
                                semimesh::io::MshEncoding::Binary);
        semimesh::io::write_vtu(mesh, base + ".vtu", semimesh::io::VtuEncoding::Ascii);
        semimesh::io::write_vtu(mesh, base + "_z.vtu");
        semimesh::io::write_nektar_xml(mesh, base + ".xml", semimesh::io::NektarEncoding::Plain);
        semimesh::io::write_nektar_xml(mesh, base + "_z.xml");
        if (p >= 2) {
          semimesh::io::write_msh(one_element(shape, p, NodeSet::GLL, curved), base + "_gll.msh");
          semimesh::io::write_msh(one_element(shape, p, NodeSet::Equispaced, folded_map), base + "_invalid.msh");
        }
      }
    write_fixtures(dir);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "io_write_samples: %s\n", e.what());
    return 1;
  }
  return 0;
}
