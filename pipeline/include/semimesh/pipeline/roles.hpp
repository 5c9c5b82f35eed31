// Which surfaces of the loaded model play which role in the run: the config's [geometry] body,
// wall, farfield and [wake] te_base, each a list of surface names or ids ("#7"), or "auto": found by
// surface::detect_cad_roles from the model's topology and geometry. A named role overrides the
// detected one; a named wall is where the detection looks for the body.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/pipeline/config.hpp"

#include <optional>
#include <string>
#include <vector>

namespace semimesh::pipeline {

struct Roles {
  std::vector<int> body, farfield;
  int wall = -1;
  std::optional<int> te_base;  ///< only resolved for the H topology, the one that needs it
};

/// The word that asks for detection.
inline const std::string kAutoRole = "auto";

/// The surface a role entry names: a surface name, or "#N" for surface id N. Throws ConfigError
/// naming the key, the entry and the model's surfaces.
int surface_ref(const cad::Model& model, const std::string& key, const std::string& entry);

/// The roles of `config` on `model`. Throws ConfigError on a name the model lacks, and the
/// detection's error (surface::CadRoleError) when an "auto" role cannot be found.
Roles resolve_roles(const cad::Model& model, const Config& config);

}  // namespace semimesh::pipeline
