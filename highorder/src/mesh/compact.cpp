#include "semimesh/mesh/compact.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace semimesh::mesh {
namespace {

// used[to[v]] for every node v an element or boundary face references.
std::vector<char> referenced(const Mesh& m, const std::vector<NodeId>& to) {
  std::vector<char> used(m.num_nodes(), 0);
  std::vector<NodeId> ids;
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    m.element_nodes(e, ids);
    for (NodeId id : ids) used[to[id]] = 1;
  }
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b)
    for (NodeId id : m.boundary_face_nodes(b)) used[to[id]] = 1;
  return used;
}

std::vector<NodeId> identity(std::size_t n) {
  std::vector<NodeId> to(n);
  for (std::size_t v = 0; v < n; ++v) to[v] = static_cast<NodeId>(v);
  return to;
}

}  // namespace

std::size_t count_unreferenced_nodes(const Mesh& mesh) {
  std::size_t count = 0;
  for (char u : referenced(mesh, identity(mesh.num_nodes()))) count += !u;
  return count;
}

Mesh without_unreferenced_nodes(const Mesh& m) { return with_nodes_replaced(m, identity(m.num_nodes())); }

Mesh with_nodes_replaced(const Mesh& m, const std::vector<NodeId>& to, const std::function<void(double)>& done) {
  return with_nodes_replaced(m, to, {}, done);
}

Mesh with_nodes_replaced(const Mesh& m, const std::vector<NodeId>& to,
                         const std::unordered_map<NodeId, Eigen::Vector3d>& moved,
                         const std::function<void(double)>& done) {
  for (const auto& [id, x] : moved)
    if (m.cad_attachment(id).kind != CadAttachment::None)
      throw std::invalid_argument("with_nodes_replaced: node " + std::to_string(id) +
                                  " is attached to the CAD and cannot be moved off it");
  if (to.size() != m.num_nodes())
    throw std::invalid_argument("with_nodes_replaced: a map of " + std::to_string(to.size()) + " nodes for a mesh of " +
                                std::to_string(m.num_nodes()));
  const std::vector<char> used = referenced(m, to);
  Mesh out(m.order(), m.node_set());
  std::vector<NodeId> new_id(m.num_nodes(), kNoNode);
  for (NodeId id = 0; id < m.num_nodes(); ++id)
    if (used[id]) {
      const auto it = moved.find(id);
      new_id[id] = out.add_node(it == moved.end() ? m.node(id) : it->second, m.cad_attachment(id));
    }
  for (const std::string& g : m.group_names()) out.group_index(g);
  out.copy_regions_from(m);
  if (!m.elements().empty()) out.reserve(m.elements().front().shape, m.elements().size());
  std::vector<NodeId> ids;
  const std::size_t count = m.elements().size(), report_every = std::max<std::size_t>(1, count / 100);
  for (std::size_t e = 0; e < count; ++e) {
    if (done && e % report_every == 0) done(static_cast<double>(e) / static_cast<double>(count));
    m.element_nodes(e, ids);
    for (NodeId& id : ids) id = new_id[to[id]];
    out.add_element(m.elements()[e].shape, ids, m.elements()[e].region);
  }
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b) {
    ids = m.boundary_face_nodes(b);
    for (NodeId& id : ids) id = new_id[to[id]];
    out.add_boundary_face(m.group_names()[m.boundary_faces()[b].group], m.boundary_faces()[b].shape, ids);
  }
  if (done) done(1.0);
  return out;
}

}  // namespace semimesh::mesh
