#include "semimesh/mesh/compact.hpp"

#include <vector>

namespace semimesh::mesh {
namespace {

std::vector<char> referenced(const Mesh& m) {
  std::vector<char> used(m.num_nodes(), 0);
  std::vector<NodeId> ids;
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    m.element_nodes(e, ids);
    for (NodeId id : ids) used[id] = 1;
  }
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b)
    for (NodeId id : m.boundary_face_nodes(b)) used[id] = 1;
  return used;
}

}  // namespace

std::size_t count_unreferenced_nodes(const Mesh& mesh) {
  std::size_t count = 0;
  for (char u : referenced(mesh)) count += !u;
  return count;
}

Mesh without_unreferenced_nodes(const Mesh& m) {
  const std::vector<char> used = referenced(m);
  Mesh out(m.order(), m.node_set());
  std::vector<NodeId> new_id(m.num_nodes(), kNoNode);
  for (NodeId id = 0; id < m.num_nodes(); ++id)
    if (used[id]) new_id[id] = out.add_node(m.node(id), m.cad_attachment(id));
  for (const std::string& g : m.group_names()) out.group_index(g);
  out.copy_regions_from(m);
  if (!m.elements().empty()) out.reserve(m.elements().front().shape, m.elements().size());
  std::vector<NodeId> ids;
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    m.element_nodes(e, ids);
    for (NodeId& id : ids) id = new_id[id];
    out.add_element(m.elements()[e].shape, ids, m.elements()[e].region);
  }
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b) {
    ids = m.boundary_face_nodes(b);
    for (NodeId& id : ids) id = new_id[id];
    out.add_boundary_face(m.group_names()[m.boundary_faces()[b].group], m.boundary_faces()[b].shape, ids);
  }
  return out;
}

}  // namespace semimesh::mesh
