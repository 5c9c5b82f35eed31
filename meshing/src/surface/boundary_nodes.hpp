// The boundary of a surface mesh: the curve mesh nodes of its loops, mapped into the surface's
// parameter space. Nodes at CAD vertices appear once even when two curve uses meet there.
#pragma once

#include "semimesh/surface/surface_mesh.hpp"

#include <vector>

namespace semimesh::surface::detail {

/// Fills `mesh.uv/points/origin` with the boundary nodes and returns the loops as closed chains of
/// node ids in walking order ([loops][nodes], the last node joins back to the first).
/// Throws SurfaceMeshError when a curve node is off the surface or a curve is used twice.
std::vector<std::vector<int>> add_boundary_nodes(const cad::Model& model, int surface, const CurveMeshes& curves,
                                                 SurfaceMesh& mesh);

/// "surface 3 ('wall')": how errors name a surface.
std::string surface_label(const cad::Model& model, int surface);

}  // namespace semimesh::surface::detail
