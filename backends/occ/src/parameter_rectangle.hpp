// Faces that are the whole of their surface over a rectangle of its parameters (a loft's face, an
// OpenVSP component's), which can be rebuilt over a part of that rectangle (body_cut, crease_seam).
#pragma once

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

namespace semimesh::occ {

/// The area of `shape`'s faces, by OCCT's surface integration.
double surface_area(const TopoDS_Shape& shape);

/// Whether `face` covers its surface over its parameter bounds: its area that of the untrimmed
/// rectangle, to 1e-6.
bool is_parameter_rectangle(const TopoDS_Face& face, double tolerance);

}  // namespace semimesh::occ
