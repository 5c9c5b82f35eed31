// Welding coincident nodes: the H-type near field gives the far field its skin quads already cut at
// the wing layer's split interfaces (h_shell.hpp), so after the split the far field's nodes on those
// quads and the split elements' new nodes are the same points under two ids. The weld makes them one.
#pragma once

#include "semimesh/mesh/mesh.hpp"
#include "semimesh/progress.hpp"

#include <atomic>
#include <cstddef>
#include <functional>

namespace semimesh::pipeline {

struct Welded {
  mesh::Mesh mesh;
  std::size_t merged = 0;     ///< nodes replaced by another (vertices, inner nodes of welded entities)
  double largest_move = 0.0;  ///< farthest an inner node of a welded entity was from the one it became
  std::size_t carried = 0;    ///< face and element inner nodes re-placed around moved edges
  mesh::Mesh::EntityUpdate entities = mesh::Mesh::EntityUpdate::Remapped;  ///< how (Mesh::replace_nodes)
};

/// `mesh` (taken by value: moved in, it is renumbered in place, never copied) in which every
/// vertex of an open face (a face one element uses and no boundary face covers: each side's copy of
/// a doubled face) that lies within `tolerance` of such a vertex seen before it (in element order)
/// is replaced by that one (the closed rest of the mesh is left alone, however thin its elements),
/// and an edge or face whose vertices were
/// all so welded onto those of another takes that one's inner nodes, matched by their place in it
/// (order along the edge, slot in the face; never by distance: the far field's pre-cut skin quads
/// are straight, the split's pieces of a curved rear interface are not). Where that moved an edge's
/// nodes (beyond `tolerance`), the faces off the CAD with that edge and the elements with a moved
/// edge or face take the harmonic extension of their new boundary, as ho::curve_mesh gives them
/// (ho::extend_inward), so a far-field element follows the split's curved edge. Only the nodes
/// some element or boundary face then uses are kept (in their relative order, with their CAD
/// attachments; the entities renamed and joined in place, or rebuilt where that would differ:
/// Mesh::replace_nodes, whose answer is Welded::entities).
/// Throws std::logic_error (an internal error) naming both faces when a face's welded vertices
/// are another face's in no rotation or reflection, and std::invalid_argument (from
/// Mesh::add_element) when two elements would then give one edge or face different nodes.
/// `progress`: the search (steps "vertices", "edges and faces", "inwards"), then the renumbering
/// ("mesh"), from the calling thread. `beside` (optional): work for the core a rebuild leaves
/// idle, run on a thread of its own at the lowest priority with the mesh being renumbered, the
/// number of its elements done so far (Mesh::replace_nodes' `rebuilt`: element by element in a
/// rebuild, all at once at the end of a remap) and a flag set once the renumbering is over (or
/// failed), after which it must not read the mesh; the weld waits for it before it returns. Its
/// exceptions are dropped: what it did not do, the stages after do.
using BesideRebuild =
    std::function<void(const mesh::Mesh&, const std::atomic<std::size_t>& rebuilt, const std::atomic<bool>& stop)>;
Welded weld_coincident_nodes(mesh::Mesh mesh, double tolerance, const ProgressCallback& progress = {},
                             const BesideRebuild& beside = {});

}  // namespace semimesh::pipeline
