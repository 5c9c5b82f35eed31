// The inner nodes a face or an element takes from its boundary nodes: the extension (harmonic;
// transfinite for quadrilaterals and prisms) that curve_mesh gives every face and volume off the
// CAD (curve_mesh.hpp, steps 2 and 3), for a stage
// that moves edge or face nodes after curving (the H-type weld) and must carry the move inwards as
// curving would have.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <Eigen/Core>

namespace semimesh::ho {

/// x: (num_nodes(shape, order), 3) in canonical order. The rows of the nodes on the shape's
/// boundary (a face: its vertices and edge nodes; a volume: its vertices, edge and face nodes) are
/// kept; the others are overwritten with their extension. Shapes: triangle,
/// quadrilateral and the 3D shapes.
void extend_inward(Shape shape, int order, NodeSet set, Eigen::MatrixXd& x);

}  // namespace semimesh::ho
