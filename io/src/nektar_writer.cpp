#include "semimesh/io/atomic_file.hpp"
#include "semimesh/io/equispaced.hpp"
#include "semimesh/io/nektar.hpp"

#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>

namespace semimesh::io {
namespace {

struct NektarShape {
  char tag;
  std::vector<int> gmsh_vertex;           // Nektar vertex k = Gmsh vertex gmsh_vertex[k]
  std::vector<std::vector<int>> faces;    // Nektar local faces, Nektar vertex numbers
};

const NektarShape& nektar_shape(ho::Shape shape) {
  static const NektarShape tet{'A', {0, 1, 2, 3}, {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 2, 3}}};
  static const NektarShape pyr{'P', {0, 1, 2, 3, 4}, {{0, 1, 2, 3}, {0, 1, 4}, {1, 2, 4}, {3, 2, 4}, {0, 3, 4}}};
  static const NektarShape pri{'R', {0, 2, 5, 3, 1, 4}, {{0, 1, 2, 3}, {0, 1, 4}, {1, 2, 5, 4}, {3, 2, 5}, {0, 3, 5, 4}}};
  static const NektarShape hex{'H', {0, 1, 2, 3, 4, 5, 6, 7},
                               {{0, 1, 2, 3}, {0, 1, 5, 4}, {1, 2, 6, 5}, {3, 2, 6, 7}, {0, 3, 7, 4}, {4, 5, 6, 7}}};
  switch (shape) {
    case ho::Shape::Tetrahedron: return tet;
    case ho::Shape::Pyramid: return pyr;
    case ho::Shape::Prism: return pri;
    case ho::Shape::Hexahedron: return hex;
    default: throw std::invalid_argument("Nektar++ XML: " + ho::to_string(shape) + " is not a volume element");
  }
}

/// Positions in the Gmsh canonical list of a tri/quad of order P, in Nektar's curved-face order.
std::vector<int> nektar_face_order(int num_vertices, int p) {
  const ho::Shape shape = num_vertices == 3 ? ho::Shape::Triangle : ho::Shape::Quadrilateral;
  const Eigen::MatrixX3d ref = ho::reference_nodes(shape, p, ho::NodeSet::Equispaced);
  std::map<std::pair<int, int>, int> at;  // lattice (i, j) -> canonical index
  for (int n = 0; n < ref.rows(); ++n) {
    double u = ref(n, 0), v = ref(n, 1);
    if (num_vertices == 4) u = (u + 1) / 2, v = (v + 1) / 2;
    at[{static_cast<int>(std::lround(u * p)), static_cast<int>(std::lround(v * p))}] = n;
  }
  std::vector<std::pair<int, int>> lattice;
  if (num_vertices == 3) {
    lattice = {{0, 0}, {p, 0}, {0, p}};
    for (int i = 1; i < p; ++i) lattice.push_back({i, 0});
    for (int i = 1; i < p; ++i) lattice.push_back({p - i, i});
    for (int i = 1; i < p; ++i) lattice.push_back({0, p - i});
    for (int j = 1; j < p; ++j)
      for (int i = 1; i + j < p; ++i) lattice.push_back({i, j});
  } else {
    for (int j = 0; j <= p; ++j)
      for (int i = 0; i <= p; ++i) lattice.push_back({i, j});
  }
  std::vector<int> order;
  for (const auto& ij : lattice) order.push_back(at.at(ij));
  return order;
}

}  // namespace

void write_nektar_xml(const mesh::Mesh& mesh, const std::string& path) {
  std::optional<mesh::Mesh> resampled;
  if (mesh.node_set() != ho::NodeSet::Equispaced) resampled = to_equispaced(mesh);
  const mesh::Mesh& m = resampled ? *resampled : mesh;
  const int p = m.order();

  std::map<mesh::NodeId, std::size_t> vertex_id;  // ordered: deterministic ids
  for (const auto& el : m.elements())
    for (int k = 0; k < ho::num_vertices(el.shape); ++k) vertex_id.emplace(el.vertices[k], 0);
  for (const auto& bf : m.boundary_faces())
    for (int k = 0; k < ho::num_vertices(bf.shape); ++k) vertex_id.emplace(bf.vertices[k], 0);
  std::size_t next = 0;
  for (auto& [node, id] : vertex_id) id = next++;

  AtomicFile out(path);
  out.print("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<NEKTAR>\n  <GEOMETRY DIM=\"3\" SPACE=\"3\">\n");
  out.print("    <VERTEX>\n");
  for (const auto& [node, id] : vertex_id) {
    const auto& x = m.node(node);
    out.print("      <V ID=\"{}\">{} {} {}</V>\n", id, x[0], x[1], x[2]);
  }
  out.print("    </VERTEX>\n    <EDGE>\n");
  for (std::size_t e = 0; e < m.edges().size(); ++e)
    out.print("      <E ID=\"{}\">{} {}</E>\n", e, vertex_id.at(m.edges()[e].vertices[0]),
              vertex_id.at(m.edges()[e].vertices[1]));
  out.print("    </EDGE>\n    <FACE>\n");
  for (std::size_t f = 0; f < m.faces().size(); ++f) {
    const auto& face = m.faces()[f];
    const int n = face.num_vertices;
    out.print("      <{} ID=\"{}\">", n == 3 ? 'T' : 'Q', f);
    for (int k = 0; k < n; ++k) out.print(" {}", m.find_edge(face.vertices[k], face.vertices[(k + 1) % n]));
    out.print(" </{}>\n", n == 3 ? 'T' : 'Q');
  }
  out.print("    </FACE>\n    <ELEMENT>\n");
  std::map<char, std::vector<std::size_t>> by_tag;
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    const auto& el = m.elements()[e];
    const NektarShape& ns = nektar_shape(el.shape);
    out.print("      <{} ID=\"{}\">", ns.tag, e);
    for (const auto& face : ns.faces) {
      std::vector<mesh::NodeId> v;
      for (int k : face) v.push_back(el.vertices[ns.gmsh_vertex[k]]);
      out.print(" {}", m.find_face(v));
    }
    out.print(" </{}>\n", ns.tag);
    by_tag[ns.tag].push_back(e);
  }
  out.print("    </ELEMENT>\n");

  if (p >= 2) {
    out.print("    <CURVED>\n");
    std::size_t curve = 0;
    for (std::size_t e = 0; e < m.edges().size(); ++e) {
      out.print("      <E ID=\"{}\" EDGEID=\"{}\" NUMPOINTS=\"{}\" TYPE=\"PolyEvenlySpaced\">", curve++, e, p + 1);
      for (mesh::NodeId id : m.edge_nodes(e)) out.print(" {} {} {}", m.node(id)[0], m.node(id)[1], m.node(id)[2]);
      out.print(" </E>\n");
    }
    const std::vector<int> tri_order = nektar_face_order(3, p), quad_order = nektar_face_order(4, p);
    for (std::size_t f = 0; f < m.faces().size(); ++f) {
      const bool tri = m.faces()[f].num_vertices == 3;
      if (tri && p < 3) continue;  // no interior points: the edges define the face
      const auto ids = m.face_nodes(f);
      const auto& order = tri ? tri_order : quad_order;
      out.print("      <F ID=\"{}\" FACEID=\"{}\" NUMPOINTS=\"{}\" TYPE=\"PolyEvenlySpaced\">", curve++, f,
                order.size());
      for (int k : order) out.print(" {} {} {}", m.node(ids[k])[0], m.node(ids[k])[1], m.node(ids[k])[2]);
      out.print(" </F>\n");
    }
    out.print("    </CURVED>\n");
  }

  out.print("    <COMPOSITE>\n");
  std::size_t composite = 0;
  std::string domain;
  auto id_list = [&](const std::vector<std::size_t>& ids) {
    std::string s;
    for (std::size_t i = 0; i < ids.size(); ++i) s += (i ? "," : "") + std::to_string(ids[i]);
    return s;
  };
  for (const auto& [tag, ids] : by_tag) {
    domain += (domain.empty() ? "" : ",") + std::to_string(composite);
    out.print("      <C ID=\"{}\"> {}[{}] </C>\n", composite++, tag, id_list(ids));
  }
  std::vector<std::vector<std::size_t>> group_faces(m.group_names().size());
  for (const auto& bf : m.boundary_faces()) group_faces[bf.group].push_back(bf.face);
  for (std::size_t g = 0; g < group_faces.size(); ++g)
    out.print("      <!-- boundary group '{}' -->\n      <C ID=\"{}\"> F[{}] </C>\n", m.group_names()[g], composite++,
              id_list(group_faces[g]));
  out.print("    </COMPOSITE>\n    <DOMAIN> C[{}] </DOMAIN>\n  </GEOMETRY>\n</NEKTAR>\n", domain);
  out.commit();
}

}  // namespace semimesh::io
