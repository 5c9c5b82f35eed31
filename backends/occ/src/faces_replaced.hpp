// Faces of a part replaced by pieces of them (a closed face by its halves), the part sewn again and
// the file's names carried to the pieces: the shared step of the load's face splits.
#pragma once

#include "prepare_shape.hpp"

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <functional>
#include <vector>

namespace semimesh::occ {

/// The pieces a face is replaced by; none (or one) keeps it as it is.
using FacePieces = std::function<std::vector<TopoDS_Face>(const TopoDS_Face&)>;

struct FacesReplaced {
  TopoDS_Shape shape;  ///< `part` itself when no face was replaced
  int replaced = 0;    ///< faces replaced
};

/// `part` (a shell's or solid's faces) with every face that `pieces_of` cuts replaced by its
/// pieces, sewn again within `tolerance`; every name of a replaced face goes to each of its pieces.
FacesReplaced with_faces_replaced(const TopoDS_Shape& part, double tolerance, FaceNames& names,
                                  const FacePieces& pieces_of);

}  // namespace semimesh::occ
