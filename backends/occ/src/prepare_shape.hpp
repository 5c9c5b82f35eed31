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

/// What sewing did: the shape, the tolerance it used, how many edge pairs it joined and how many
/// edges it left free (an open root or tip keeps its loop free at any tolerance).
struct Sewn {
  TopoDS_Shape shape;
  double tolerance = 0.0;
  int joined = 0;
  int free = 0;
};

/// Sews faces whose edges are free within `tolerance`, and while edges stay free, again from the
/// shape as given with ten times the tolerance up to `max_tolerance`, as long as that frees fewer
/// (faces exported one by one leave gaps of their CAD tool's tolerance, which the model's size
/// does not tell). A shape without free edges is returned as it is (so solids keep their
/// structure), with joined = free = 0.
Sewn sew_shape(const TopoDS_Shape& shape, double tolerance, double max_tolerance, FaceNames& names);

/// ShapeFix_Shape, then ShapeFix_Wireframe to fix wire gaps and merge edges shorter than
/// `precision`; 3D curves are built for edges that only have pcurves.
TopoDS_Shape heal_shape(const TopoDS_Shape& shape, double precision, FaceNames& names);

/// Whether some non-degenerated edge bounds a single face (seams excepted).
bool has_free_edges(const TopoDS_Shape& shape);

}  // namespace semimesh::occ
