// A wing component exported as one face closed round its sections (OpenVSP writes each component
// so), its seam the sharp trailing edge: the meshing finds a sharp trailing edge as a curve between
// two body faces, and a seam is a curve of one. Such a face is split into two along the iso-line
// halfway round from its seam, the same surface on each side: the trailing edge becomes a curve
// between two faces and the geometry is unchanged.
#pragma once

#include "prepare_shape.hpp"

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

namespace semimesh::occ {

/// Whether one of the face's edges is a seam of it (its surface closes on itself across the face).
bool has_seam(const TopoDS_Face& face);

/// `body` (a shell's or solid's faces) with every face whose seam is a crease (the surface's
/// normals on its two sides more than 20 degrees apart, at every sample along it) and which covers
/// its surface over a whole parameter rectangle replaced by its two halves, sewn again within
/// `tolerance`; names follow the faces. Each split is said in `repairs`.
TopoDS_Shape with_crease_seams_split(const TopoDS_Shape& body, double tolerance, FaceNames& names,
                                     std::vector<std::string>& repairs);

}  // namespace semimesh::occ
