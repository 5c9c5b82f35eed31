// A body face closed on itself (a skin round a wing's sections, its seam along the trailing edge or
// anywhere; a body of revolution) is cut in two before the body is joined to the wall part: OCCT's
// general fuse left GT_supersonic_delta's closed wing skin whole where the fuselage's intersection
// loop crosses it (the Booleans then lost the wing), and splits the two halves of it right.
#pragma once

#include "prepare_shape.hpp"

#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

namespace semimesh::occ {

/// `part` (a shell's or solid's faces) with every face that has a seam cut across its closed
/// direction into two (OCCT's ShapeUpgrade_ShapeDivideClosed), the second half on a copy of the
/// surface (two faces on one surface handle sharing an edge make it a seam to OCCT), sewn again
/// within `tolerance`; names follow the faces. Said in `repairs` when a face was cut.
TopoDS_Shape with_closed_faces_halved(const TopoDS_Shape& part, double tolerance, FaceNames& names,
                                      std::vector<std::string>& repairs);

}  // namespace semimesh::occ
