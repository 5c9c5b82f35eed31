// Welding coincident nodes: the H-type near field gives the far field its skin quads already cut at
// the wing layer's split interfaces (h_shell.hpp), so after the split the far field's nodes on those
// quads and the split elements' new nodes are the same points under two ids. The weld makes them one.
#pragma once

#include "semimesh/mesh/mesh.hpp"
#include "semimesh/progress.hpp"

#include <cstddef>

namespace semimesh::pipeline {

struct Welded {
  mesh::Mesh mesh;
  std::size_t merged = 0;  ///< nodes replaced by an equal one
};

/// A copy of `mesh` in which every node that lies within `tolerance` of a node seen before it is
/// replaced by that node, and only the nodes some element or boundary face then uses are kept (in
/// their relative order, with their CAD attachments: one rebuild of the mesh for the weld and the
/// compaction, as mesh::with_nodes_replaced). Only
/// elements with a vertex coinciding with another element's vertex are searched for their other
/// nodes (a weld starts at the vertices). An edge or face whose vertices were all welded onto
/// those of another then takes that one's inner nodes, each the nearest (the split's interfaces,
/// interpolated between the vertices', are not where a straight skin quad has its nodes). Throws std::invalid_argument (from Mesh::add_element)
/// when two elements would then give one edge or face different nodes.
/// `progress`: the search (steps "vertices", "nodes", "edges and faces"), then the rebuild ("mesh"),
/// from the calling thread.
Welded weld_coincident_nodes(const mesh::Mesh& mesh, double tolerance, const ProgressCallback& progress = {});

}  // namespace semimesh::pipeline
