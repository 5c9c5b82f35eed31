#include "semimesh/surface/surface_mesh.hpp"

#include "boundary_nodes.hpp"
#include "flat_corners.hpp"
#include "mesh_improvement.hpp"
#include "parameter_triangulation.hpp"
#include "semimesh/surface/error.hpp"

#include <utility>

namespace semimesh::surface {

SurfaceMesh mesh_surface(const cad::Model& model, int surface, const CurveMeshes& curves, const SizeField& size,
                         const SurfaceMeshOptions& options) {
  if (surface < 0 || surface >= model.num_surfaces())
    throw SurfaceMeshError("surface id " + std::to_string(surface) + " is out of range: the model has " +
                           std::to_string(model.num_surfaces()) + " surfaces");
  if (!(options.split_factor >= 1.0))
    throw SurfaceMeshError("split_factor must be >= 1, got " + std::to_string(options.split_factor));
  const cad::Surface& face = model.surface(surface);
  SurfaceMesh mesh;
  mesh.surface = surface;
  auto loops = detail::add_boundary_nodes(model, surface, curves, mesh);
  const double grid_step = detail::parameter_grid_step(face, mesh);
  detail::canonicalise_boundary(grid_step, mesh, loops);
  detail::triangulate_parameter_space(model, surface, loops, size, options.split_factor, grid_step, mesh);
  // On a periodic face collapses measured in space would undo the splits of edges that wrap
  // round (short chords near a pole): the refinement's sizes stand there.
  const bool periodic = face.period(0) || face.period(1);
  for (int pass = 0; pass < options.improvement_passes; ++pass) {
    const int collapses = periodic ? 0 : detail::collapse_short_edges(face, size, mesh);
    const int swaps = detail::swap_edges(face, mesh);
    const int moves = detail::smooth_nodes(face, mesh);
    if (collapses == 0 && swaps == 0 && moves == 0) break;
  }
  detail::swap_edges(face, mesh);
  detail::fix_flat_corners(model, surface, mesh);
  detail::remove_pole_triangles(mesh);
  // Counter-clockwise in (u, v) means along du x dv; the fluid side is orientation() * du x dv.
  if (face.orientation() < 0)
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

}  // namespace semimesh::surface
