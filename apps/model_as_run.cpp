#include "model_as_run.hpp"

#include "semimesh/pipeline/pipeline.hpp"
#include "semimesh/surface/cad_roles.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace semimesh::app {

std::array<double, 3> rounded(const cad::Vec3& x) {
  const double scale = std::max(1.0, x.cwiseAbs().maxCoeff());
  std::array<double, 3> out{};
  for (int k = 0; k < 3; ++k)
    out[k] = std::abs(x[k]) < 1e-12 * scale ? 0.0 : std::stod(fmt::format("{:.12g}", x[k]));
  return out;
}

ModelAsRun load_model_as_run(const cad::Registry& registry, const std::string& backend, const std::string& path,
                             const cad::Params& params) {
  ModelAsRun out{registry.load(backend, cad::Source{path, params}), std::nullopt};
  if (surface::has_wall_with_root_loop(*out.model)) return out;
  // Separate parts reaching into each other are no body on a wall, whatever else they look like
  // (a wing's own trailing-edge seam meeting its open root would pass for a fuselage's).
  surface::refuse_overlapping_parts(*out.model);
  // A wall may be there whose seam hides the root (its planar faces would be taken for root caps).
  surface::refuse_seam_through_root(*out.model);
  std::optional<surface::RootPlane> root = surface::find_root_plane(*out.model);
  if (!root) surface::detect_cad_roles(*out.model);  // throws, saying what is missing
  pipeline::GeometryConfig load;
  load.backend = backend;
  load.source = path;
  load.wall_plane.point = rounded(root->point);
  load.wall_plane.normal = rounded(root->normal);
  load.farfield_shape.box_chords = kBoxChords;
  cad::Source source = pipeline::cad_source(load);
  for (const auto& [key, value] : params.all())
    if (!source.params.has(key)) source.params.set(key, value);
  out.model = registry.load(backend, source);
  out.root = std::move(root);
  return out;
}

}  // namespace semimesh::app
