// A body cut by a plane: the part beyond it (on the side its normal points to) taken away. Two uses:
// a tip pinched to zero thickness (a knife-edge or pointed tip, as OpenVSP closes its wings) that no
// layer can wrap, cut blunt where the user says (geometry.body_cut); and, in a join, a pinched
// section inside the wall part (an OpenVSP wing's centreline section flattened to a line) trimmed
// back to where the section has thickness, inside the wall, which changes nothing of the joined
// shape. The opening the cut leaves is closed flat afterwards with the body's other planar loops.
#pragma once

#include "prepare_shape.hpp"

#include <TopoDS_Shape.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>

#include <string>

namespace semimesh::occ {

/// A plane and the side of it to take away: the one `normal` points to.
struct CutPlane {
  gp_Pnt point;
  gp_Dir normal;
  std::string label;  ///< how the user wrote it, for messages
};

/// `body` (a shell, or solids) without its part beyond `cut`: a face the plane crosses along one of
/// its iso-parameter lines is rebuilt over the parameters kept; the rest is split by OCCT's splitter
/// with a face on the plane and its pieces sorted by side. A shell stays open along the cut (a
/// planar free loop), a solid is closed by the cut's face. Faces in `names` pass their names on to
/// what is left of them. Throws cad::CadError(BadParameter) naming `cut.label` when the plane
/// misses the body (nothing beyond it), leaves nothing of it, or a piece stays whole across it.
TopoDS_Shape cut_beyond(const TopoDS_Shape& body, const CutPlane& cut, double fuzzy, FaceNames& names);

}  // namespace semimesh::occ
