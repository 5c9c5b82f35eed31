// The one-time preparation of a loaded shape: scaling, sewing, healing. Each step carries the
// face names over to the faces it produces.
#pragma once

#include <TopoDS_Shape.hxx>

#include <string>
#include <utility>
#include <vector>

namespace semimesh::occ {

using FaceNames = std::vector<std::pair<TopoDS_Shape, std::string>>;

/// Multiplies every coordinate by `factor` (geometry rewritten, no scaled locations).
TopoDS_Shape scale_shape(const TopoDS_Shape& shape, double factor, FaceNames& names);

/// Sews faces whose edges are free within `tolerance`; a shape without free edges is returned
/// as it is (so solids keep their structure).
TopoDS_Shape sew_shape(const TopoDS_Shape& shape, double tolerance, FaceNames& names);

/// ShapeFix_Shape, then ShapeFix_Wireframe to fix wire gaps and merge edges shorter than
/// `precision`; 3D curves are built for edges that only have pcurves.
TopoDS_Shape heal_shape(const TopoDS_Shape& shape, double precision, FaceNames& names);

/// Whether some non-degenerated edge bounds a single face (seams excepted).
bool has_free_edges(const TopoDS_Shape& shape);

}  // namespace semimesh::occ
