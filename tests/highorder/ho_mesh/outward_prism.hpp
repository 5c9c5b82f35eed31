// The layer of prisms the curving tests build on a surface mesh: each body node's top node is the
// next id (body id + 1).
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <string>
#include <utility>

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

}  // namespace semimesh::ho
