// A wall part written as a grid of patches of one smooth skin (OpenVSP writes a fuselage as
// quadrants around and sections along, each an untrimmed bicubic B-spline) is joined into one face
// before the join: the wall layer and the junction stand on one wall face, and a root crossing a
// patch boundary (or a wall layer ending at one) would otherwise be refused.
#pragma once

#include <TopoDS_Shape.hxx>
#include <TopoDS_Shell.hxx>

#include <string>
#include <vector>

namespace semimesh::occ {

/// `faces` with every two untrimmed B-spline faces that meet side to side (the same control points
/// along the shared side within `tolerance`, the same degrees and knots across it, their normals
/// within a degree of each other along it) made one B-spline face, C0 at the joint, until no two
/// do; the surface is exact (its control points are the patches'). Faces that join nothing are
/// kept as they are; `faces` itself is returned when nothing joins. Said in `repairs`.
TopoDS_Shape with_patches_joined(const TopoDS_Shell& faces, double tolerance, std::vector<std::string>& repairs);

}  // namespace semimesh::occ
