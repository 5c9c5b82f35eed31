// The layer of prisms the curving tests build on a surface mesh: each body node's top node is the
// next id (body id + 1).
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <string>
#include <utility>
#include <vector>

namespace semimesh::ho {

/// The prism on body triangle (a, b, c) and its top (a + 1, b + 1, c + 1), its vertices ordered so
/// that it grows along its body face's normal, and the body face as boundary face `group`, seen
/// from the fluid (counter-clockwise from outside).
inline void add_outward_prism(mesh::Mesh& m, mesh::NodeId a, mesh::NodeId b, mesh::NodeId c, int region,
                              const std::string& group) {
  if ((m.node(b) - m.node(a)).cross(m.node(c) - m.node(a)).dot(m.node(a + 1) - m.node(a)) < 0) std::swap(b, c);
  m.add_element(Shape::Prism, {a, b, c, a + 1, b + 1, c + 1}, region);
  m.add_boundary_face(group, Shape::Triangle, {a, c, b});
}

/// The prisms on an (n + 1) x (n + 1) grid of body nodes (row-major, i then j), each cell cut into
/// two triangles along its (0, 0) - (1, 1) diagonal.
inline void add_outward_prism_grid(mesh::Mesh& m, const std::vector<mesh::NodeId>& body, int n, int region,
                                   const std::string& group) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const auto id = [&](int a, int b) { return body[static_cast<std::size_t>((i + a) * (n + 1) + j + b)]; };
      add_outward_prism(m, id(0, 0), id(1, 0), id(1, 1), region, group);
      add_outward_prism(m, id(0, 0), id(1, 1), id(0, 1), region, group);
    }
}

}  // namespace semimesh::ho
