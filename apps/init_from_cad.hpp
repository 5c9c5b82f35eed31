// `semimesh init --cad FILE`: a configuration for a CAD file, with the roles found in it
// (surface::detect_cad_roles) written out by name, and every length of the defaults (which are the
// paper's case for a chord of 1) scaled by the body's root chord, so `semimesh run` meshes the file
// as the paper's case meshes its wing.
#pragma once

#include "semimesh/cad/registry.hpp"
#include "semimesh/pipeline/config.hpp"

#include <string>
#include <vector>

namespace semimesh::app {

/// The config keys that are lengths in model units: scaled by the chord.
const std::vector<std::string>& length_keys();

struct CadConfig {
  pipeline::Config config;
  std::string summary;  ///< the roles and the chord, as comment lines for the file's header
  std::vector<std::string> warnings;  ///< what the user should check (a doubtful unit), one sentence each
};

/// Loads `cad_path` (backend from its extension), finds the roles and the chord. `source_text` is
/// what the config's geometry.source says (the path relative to the config's folder). Throws the
/// loader's or the detection's error.
CadConfig config_for_cad(const cad::Registry& registry, const std::string& cad_path, const std::string& source_text);

}  // namespace semimesh::app
