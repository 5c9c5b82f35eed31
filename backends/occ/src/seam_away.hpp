// A fuselage or hub whose seam (the parameter line where its closed surface starts and ends) would
// run through the body's root once joined: the root loop would then be cut open along the seam and
// joined to the face's outer boundary instead of being a hole in it. Before joining, each face of
// the wall part that wraps around a whole turn is rebuilt with its seam on the far side of the
// surface from the body; the geometry is unchanged.
#pragma once

#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>

#include <string>
#include <vector>

namespace semimesh::occ {

/// `part` (a shell or solid's faces) with every face that covers its surface's whole period in one
/// parameter (its boundary that parameter's seam and the other parameter's two iso-lines) and whose
/// seam lies within a quarter of a period of the foot of `away_from` on it rebuilt on the same
/// surface re-parametrised so that the seam lies half a period away from that foot; the faces are
/// sewn again within `tolerance`. Surfaces of revolution, cylinders, cones, spheres and tori are
/// turned about their axis; B-spline surfaces are made periodic (when closed) and given their
/// origin at a knot inserted there (the same surface, exactly); other faces are kept as they are.
/// Each move is said in `repairs`.
TopoDS_Shape with_seams_away_from(const TopoDS_Shape& part, const gp_Pnt& away_from, double tolerance,
                                  std::vector<std::string>& repairs);

}  // namespace semimesh::occ
