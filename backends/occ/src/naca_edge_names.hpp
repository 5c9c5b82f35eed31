// Curve names of the generated NACA wing, as the analytic backend gives them (mock_cad/naca.hpp).
#pragma once

#include <TopoDS_Shape.hxx>

#include <string>
#include <utility>
#include <vector>

namespace semimesh::occ {

/// Names every edge of the NACA wing `shape` by the named faces it joins (`face_names`, faces of
/// `shape`): upper+lower -> leading_edge (the aft one, sharp TE: trailing_edge), upper+te_base ->
/// te_upper, tip+upper -> tip_upper, wall+upper -> root_upper, ..., two box faces or the wall
/// (z = zmin) and a box face -> box_<a>_<b> in axis order. An edge of a single wing face (no
/// wall) is a root edge. Throws cad::CadError(Geometry) for an edge no analytic curve matches.
std::vector<std::pair<TopoDS_Shape, std::string>> naca_wing_edge_names(
    const TopoDS_Shape& shape, const std::vector<std::pair<TopoDS_Shape, std::string>>& face_names);

}  // namespace semimesh::occ
