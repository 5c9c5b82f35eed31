// `semimesh cad-info`: load a CAD model through the backend registry and describe it.
#pragma once

#include "semimesh/cad/registry.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace semimesh::app {

struct CadInfoOptions {
  std::string backend;              ///< empty: chosen from the source's extension, or "naca"
  std::string source;               ///< file path (or backend-specific source); may be empty
  std::vector<std::string> params;  ///< "key=value" strings
  bool json = false;
};

/// The backend cad-info would use for these options.
std::string choose_backend(const cad::Registry& registry, const CadInfoOptions& options);

/// Parses "key=value" strings; throws CadError(BadParameter) on a string without '=' or key.
cad::Params parse_params(const std::vector<std::string>& key_values);

/// Loads the model and writes the report (a table, or one JSON object) to `out`.
/// Throws cad::CadError on bad input; writes nothing to `out` in that case.
void run_cad_info(const cad::Registry& registry, const CadInfoOptions& options, std::ostream& out);

}  // namespace semimesh::app
