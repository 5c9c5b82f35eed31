// Gmsh element type numbers of complete (non-serendipity) Lagrange elements, orders 1..9
// (the highest order Gmsh 4.8 has for prisms, pyramids and hexes).
// Values from gmsh's GmshDefines.h, verified with gmsh.model.mesh.getElementType(family, order)
// (python3-gmsh 4.8) and by tests/io/verify_msh.py.
#pragma once

#include "semimesh/ho/element_type.hpp"

namespace semimesh::io {

constexpr int kMaxMshOrder = 9;

/// Gmsh type of (shape, order); throws std::invalid_argument for Segment or order outside [1, kMaxMshOrder].
int gmsh_element_type(ho::Shape shape, int order);

/// Inverse of gmsh_element_type: false if `type` is not one of those elements (points, lines,
/// serendipity or incomplete elements...).
bool gmsh_shape_and_order(int type, ho::Shape& shape, int& order);

}  // namespace semimesh::io
