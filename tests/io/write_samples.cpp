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
#include "semimesh/io/gmsh_types.hpp"
#include "semimesh/io/msh.hpp"
#include "semimesh/io/nektar.hpp"
#include "semimesh/io/vtu.hpp"

#include <cmath>
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
  } catch (const std::exception& e) {
    std::fprintf(stderr, "io_write_samples: %s\n", e.what());
    return 1;
  }
  return 0;
}
