// Dropping the nodes no element uses (e.g. the interior nodes of the coarse prisms that
// ho::split_layers replaced), so neither the mesh in memory nor a written file carries them.
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <functional>
#include <unordered_map>
#include <vector>

namespace semimesh::mesh {

/// Number of nodes that no element or boundary face references.
std::size_t count_unreferenced_nodes(const Mesh& mesh);

/// A mesh with the same elements (same order, same shapes, same canonical node lists up to the
/// renumbering), boundary faces, groups and regions, whose nodes are only the referenced ones, kept in their
/// old relative order with their CAD attachments. Edge and face entities are rebuilt in element order.
/// Taken by value: a caller that moves its mesh in gets it back renumbered in place (Mesh::replace_nodes).
Mesh without_unreferenced_nodes(Mesh mesh);

/// The same with every node id v of an element or boundary face replaced by `to[v]` first
/// ([mesh.num_nodes()]; a weld's map onto equal nodes): one rebuild for both. Node v's point and
/// CAD attachment are kept for each id that remains referenced. without_unreferenced_nodes(m) is
/// with_nodes_replaced(m, identity). `done` (optional) receives the fraction of elements rebuilt,
/// about a hundred times.
Mesh with_nodes_replaced(Mesh mesh, const std::vector<NodeId>& to, const std::function<void(double)>& done = {});

/// The same with the kept nodes listed in `moved` (by old id) at their listed points instead
/// (a weld that carries snapped edges inwards); a listed node must have no CAD attachment
/// (std::invalid_argument).
Mesh with_nodes_replaced(Mesh mesh, const std::vector<NodeId>& to,
                         const std::unordered_map<NodeId, Eigen::Vector3d>& moved,
                         const std::function<void(double)>& done = {});

}  // namespace semimesh::mesh
