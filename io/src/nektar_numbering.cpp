#include "nektar_numbering.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>

namespace semimesh::io {
namespace {

std::runtime_error element_error(std::size_t e, const std::string& what) {
  return std::runtime_error("Nektar++ XML: element " + std::to_string(e) + ": " + what);
}

/// Union-find over node ids (path halving).
struct Lines {
  std::vector<std::uint32_t> parent;
  explicit Lines(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void join(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

/// Height of each vertex (by its id in `n`): 0, or above every base vertex of the pyramids it is the
/// apex of.
std::vector<std::uint32_t> apex_heights(const mesh::Mesh& m, const NektarNumbering& n) {
  std::vector<std::uint32_t> h(n.vertex_node.size(), 0);
  auto index = [&](mesh::NodeId v) { return n.vertex_id(v); };
  std::vector<std::size_t> pyramids;
  for (std::size_t e = 0; e < m.elements().size(); ++e)
    if (m.elements()[e].shape == ho::Shape::Pyramid) pyramids.push_back(e);
  auto raise = [&](std::size_t e) {  // true if the apex had to move up
    const auto& v = m.elements()[e].vertices;
    const std::uint32_t need = 1 + std::max({h[index(v[0])], h[index(v[1])], h[index(v[2])], h[index(v[3])]});
    std::uint32_t& apex = h[index(v[4])];
    return apex < need ? (apex = need, true) : false;
  };
  for (std::size_t pass = 0; pass <= pyramids.size(); ++pass) {
    bool changed = false;
    for (std::size_t e : pyramids) changed = raise(e) || changed;
    if (!changed) return h;
  }
  for (std::size_t e : pyramids)
    if (raise(e))
      throw element_error(e, "the pyramid's apex is a base vertex of a pyramid whose apex is below it (e.g. two "
                             "pyramids sharing a triangle): no vertex numbering collapses both at their apexes");
  return h;
}

double triple(const mesh::Mesh& m, const std::array<mesh::NodeId, 8>& v, int o, int a, int b, int c) {
  const Eigen::Vector3d x0 = m.node(v[o]);
  return (m.node(v[a]) - x0).dot((m.node(v[b]) - x0).cross(m.node(v[c]) - x0));
}

/// Nektar axes at vertex 0 (TetGeom: 1 2 3; the others: 1 3 4).
double corner_jacobian(const mesh::Mesh& m, ho::Shape shape, const std::array<mesh::NodeId, 8>& v) {
  return shape == ho::Shape::Tetrahedron ? triple(m, v, 0, 1, 2, 3) : triple(m, v, 0, 1, 3, 4);
}

std::array<mesh::NodeId, 8> number_tet(const mesh::Mesh& m, const mesh::Element& el, const NektarNumbering& n) {
  std::array<mesh::NodeId, 8> v{};
  std::copy_n(el.vertices.begin(), 4, v.begin());
  std::sort(v.begin(), v.begin() + 4, [&](mesh::NodeId a, mesh::NodeId b) { return n.vertex_id(a) < n.vertex_id(b); });
  if (triple(m, v, 0, 1, 2, 3) < 0) std::swap(v[0], v[1]);  // the two lowest: mirror keeps 2, 3 highest
  return v;
}

std::array<mesh::NodeId, 8> number_prism(const mesh::Mesh& m, std::size_t e, const NektarNumbering& n) {
  const auto& g = m.elements()[e].vertices;  // Gmsh: triangles 0 1 2 / 3 4 5, lateral edges k - k+3
  auto peak = [&](int first) {
    int best = first;
    for (int k = first + 1; k < first + 3; ++k)
      if (n.vertex_id(g[k]) > n.vertex_id(g[best])) best = k;
    return best;
  };
  const int k = peak(0);
  if (peak(3) != k + 3)
    throw element_error(e, "the prism's two triangles have their highest vertex on different lateral edges "
                           "(vertices on one prism stack line must rank together)");
  const int b = (k + 1) % 3, c = (k + 2) % 3;
  std::array<mesh::NodeId, 8> v{g[b], g[c], g[c + 3], g[b + 3], g[k], g[k + 3], 0, 0};
  if (triple(m, v, 0, 1, 3, 4) < 0) v = {g[c], g[b], g[b + 3], g[c + 3], g[k], g[k + 3], 0, 0};
  return v;
}

}  // namespace

char nektar_tag(ho::Shape shape) {
  switch (shape) {
    case ho::Shape::Tetrahedron: return 'A';
    case ho::Shape::Pyramid: return 'P';
    case ho::Shape::Prism: return 'R';
    case ho::Shape::Hexahedron: return 'H';
    default: throw std::invalid_argument("Nektar++ XML: " + ho::to_string(shape) + " is not a volume element");
  }
}

const std::vector<std::vector<int>>& nektar_faces(ho::Shape shape) {
  // The third vertex of each triangle is the element's collapsed vertex for that face.
  static const std::vector<std::vector<int>> tet{{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 2, 3}};
  static const std::vector<std::vector<int>> pyr{{0, 1, 2, 3}, {0, 1, 4}, {1, 2, 4}, {3, 2, 4}, {0, 3, 4}};
  static const std::vector<std::vector<int>> pri{{0, 1, 2, 3}, {0, 1, 4}, {1, 2, 5, 4}, {3, 2, 5}, {0, 3, 5, 4}};
  static const std::vector<std::vector<int>> hex{{0, 1, 2, 3}, {0, 1, 5, 4}, {1, 2, 6, 5},
                                                 {3, 2, 6, 7}, {0, 3, 7, 4}, {4, 5, 6, 7}};
  switch (shape) {
    case ho::Shape::Tetrahedron: return tet;
    case ho::Shape::Pyramid: return pyr;
    case ho::Shape::Prism: return pri;
    case ho::Shape::Hexahedron: return hex;
    default: throw std::invalid_argument("Nektar++ XML: " + ho::to_string(shape) + " is not a volume element");
  }
}

std::array<mesh::NodeId, 8> nektar_element_vertices(const mesh::Mesh& m, const NektarNumbering& numbering,
                                                    std::size_t e) {
  const auto& el = m.elements()[e];
  if (el.shape == ho::Shape::Tetrahedron) return number_tet(m, el, numbering);
  if (el.shape == ho::Shape::Prism) return number_prism(m, e, numbering);
  return el.vertices;  // pyramids and hexes: Gmsh's numbering is Nektar's
}

NektarNumbering number_for_nektar(const mesh::Mesh& m) {
  NektarNumbering out;
  const std::size_t n = m.num_nodes();
  {
    std::vector<char> is_vertex(n, 0);
    for (const auto& el : m.elements())
      for (int k = 0; k < ho::num_vertices(el.shape); ++k) is_vertex[el.vertices[k]] = 1;
    for (const auto& bf : m.boundary_faces())
      for (int k = 0; k < ho::num_vertices(bf.shape); ++k) is_vertex[bf.vertices[k]] = 1;
    for (mesh::NodeId v = 0; v < n; ++v)
      if (is_vertex[v]) out.vertex_node.push_back(v);
  }
  // The prism lines and apex heights are kept per vertex, not per node (a twentieth of the nodes
  // at order 4), by the vertices' ids in ascending node order (so a line's smallest id is its
  // smallest node) until they are given the final ids.
  const std::size_t count = out.vertex_node.size();
  out.index_vertices();
  Lines lines(count);
  for (const auto& el : m.elements())
    if (el.shape == ho::Shape::Prism)
      for (int k = 0; k < 3; ++k) lines.join(out.vertex_id(el.vertices[k]), out.vertex_id(el.vertices[k + 3]));
  const std::vector<std::uint32_t> height = apex_heights(m, out);

  std::vector<std::tuple<std::uint32_t, std::uint32_t, mesh::NodeId>> key;
  key.reserve(count);
  for (std::uint32_t i = 0; i < count; ++i) key.emplace_back(height[i], lines.find(i), out.vertex_node[i]);
  std::sort(key.begin(), key.end());
  for (std::size_t i = 0; i < key.size(); ++i) out.vertex_node[i] = std::get<2>(key[i]);
  out.index_vertices();

  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    const auto& el = m.elements()[e];
    const std::array<mesh::NodeId, 8> v = nektar_element_vertices(m, out, e);
    // The rules, checked on the faces as they will be written.
    const auto& faces = nektar_faces(el.shape);
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (faces[f].size() != 3) continue;
      const mesh::NodeId collapsed = v[faces[f][2]];
      for (int k = 0; k < 2; ++k)
        if (out.vertex_id(v[faces[f][k]]) > out.vertex_id(collapsed))
          throw element_error(e, "its local face " + std::to_string(f) + " (a triangle) would not have the "
                                 "element's collapsed vertex as its third vertex (e.g. a pyramid apex that is "
                                 "not above a vertex of a neighbouring triangle)");
    }
    if (!(corner_jacobian(m, el.shape, v) > 0))
      throw element_error(e, "the straight-sided Jacobian at Nektar vertex 0 is not positive (" +
                             std::to_string(corner_jacobian(m, el.shape, v)) + ")");
  }
  return out;
}

std::array<mesh::NodeId, 4> written_face_vertices(const mesh::Mesh& m, const NektarNumbering& numbering,
                                                  std::size_t f) {
  const auto& face = m.faces()[f];
  std::array<mesh::NodeId, 4> v = face.vertices;
  if (face.num_vertices == 3) {
    int top = 0;
    for (int k = 1; k < 3; ++k)
      if (numbering.vertex_id(v[k]) > numbering.vertex_id(v[top])) top = k;
    std::rotate(v.begin(), v.begin() + (top + 1) % 3, v.begin() + 3);
  }
  return v;
}

}  // namespace semimesh::io
