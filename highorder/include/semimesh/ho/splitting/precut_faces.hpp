// Faces cut in advance at the split's interfaces, made to follow the curved mesh.
//
// The H-type's sharp trailing edge: the fan's prisms stand on a face R-L-H-W of a junction hex
// already cut at the wing layer's interfaces (strips R..L x W..H), so that, once the hex is split,
// the weld joins the hex's pieces and the fan's node for node. The cuts are made on the linear mesh,
// straight. After curving, the hex's face is curved (its edge R-L on a curved wall) and the split
// puts its nodes on that curved face: the fan's nodes must be there too, its strips' every node
// (vertices, edge and face nodes) on the face's own map. Then the split of a fan prism along the
// strip (another family's layers) meets the hex's pieces as well: each strip edge across the cuts
// is the face's map restricted to that cut, a polynomial of degree P its P + 1 nodes hold exactly.
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <cstddef>
#include <vector>

namespace semimesh::ho {

/// A quad face of the mesh with corners a0 = low.front(), a1 = low.back(), b1 = high.back(),
/// b0 = high.front() (a0-a1 and b0-b1 opposite edges), cut across into strips: quad faces
/// low[k] low[k+1] high[k+1] high[k] of other elements. The face itself stays in the mesh (the
/// element beside the strips).
struct PrecutFace {
  std::vector<mesh::NodeId> low, high;  ///< [cuts] along a0 -> a1 and b0 -> b1, ends included
  std::vector<double> fractions;        ///< [cuts] across the face, from 0 at a0-b0 to 1 at a1-b1
};

struct PrecutStats {
  std::size_t faces_moved = 0;  ///< precut faces whose strips had to move
  std::size_t nodes_moved = 0;  ///< nodes placed (strips and the elements' nodes around them)
  double largest_move = 0.0;    ///< farthest a strip node moved
};

/// Moves, in place, the nodes of every strip face onto the precut face's map F: a node at (s, t)
/// of the strip (s across the cuts, from its fractions; t from low to high) goes to F(s, t). The
/// other nodes of the elements using a moved node follow the move by its harmonic extension
/// (edges linearly, then faces and volumes, as curving extends inwards); a moved node that had a
/// CAD attachment loses it (it is no longer the CAD's point). A strip node within `tolerance` of
/// its place stays where it is (the cuts of a planar face are already there: bit for bit).
/// Throws std::invalid_argument naming the nodes when the face or a strip is not a face of the
/// mesh, or the lists do not match.
PrecutStats follow_precut_faces(mesh::Mesh& mesh, const std::vector<PrecutFace>& faces, double tolerance);

}  // namespace semimesh::ho
