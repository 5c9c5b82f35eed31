// The model `semimesh run` meshes for a CAD file configured by `init --cad`, so that cad-info, init
// and run number the faces alike (the ids and the "face_<id>" names the backend gives unnamed
// faces): the file as loaded, or, for a file holding the body alone (no wall sewn to it), the body
// with the wall plane at its root and a box around it built at load, as init's
// geometry.wall_plane and geometry.farfield = {box_chords} make `run` load it. The face ids are
// then the built model's, not the file's.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/cad/registry.hpp"
#include "semimesh/pipeline/config.hpp"
#include "semimesh/surface/root_plane.hpp"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace semimesh::app {

/// The far field init builds around a body-only file: the paper's box is about ten chords on every side.
inline constexpr double kBoxChords = 10.0;

/// A point or direction as written in the config: 12 significant digits, round-off zeros as 0.
std::array<double, 3> rounded(const cad::Vec3& x);

/// An assembly of two overlapping parts (a wing sunk into a fuselage, not joined): the parts'
/// faces as geometry.join entries ("#7", the file's ids) and the box init gives them.
struct AssemblyJoin {
  std::vector<std::string> body, wall;
  std::array<double, 6> box{};
  /// "none", or the box's side on the body's plane of symmetry when the body runs through the wall
  /// part (a full-span wing through a fuselage): a half model, as farfield.symmetry names it.
  std::string symmetry = "none";
  std::string why;  ///< how the box was chosen, for init's header and cad-info
};

struct ModelAsRun {
  std::unique_ptr<cad::Model> model;
  /// Body-only: the root plane found in the file (built at load as the wall, rounded as init
  /// writes it); nothing when the file has its own wall.
  std::optional<surface::RootPlane> root;
  /// An assembly of two overlapping parts, joined at load; nothing otherwise.
  std::optional<AssemblyJoin> join;
};

/// Loads `path` with `backend` and `params`, then, for a body-only file, again with the wall plane
/// and the box built, or for an assembly of exactly two overlapping closed parts, again with them joined in
/// a box kBoxChords of the body's streamwise extent around it, cut inside the wall part's ends along
/// its longest axis (the file's other parameters kept). Throws the loader's error, and the role
/// detection's when a body-only file has no root plane or a wall's seam hides the root.
ModelAsRun load_model_as_run(const cad::Registry& registry, const std::string& backend, const std::string& path,
                             const cad::Params& params = {});

}  // namespace semimesh::app
