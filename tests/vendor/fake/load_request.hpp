// What the fake kernel is asked to load: NACA generator parameters from the path ("naca:k=v;..."
// or a *.vcad text file) and the kernel's own load options.
#pragma once

#include "fake_error.hpp"

#include "semimesh/cad/source.hpp"

#include <optional>
#include <string>

namespace semimesh::vendor_fake {

struct LoadRequest {
  cad::Params naca;                 ///< generator parameters, e.g. "naca.code" = "0012"
  bool from_file = false;           ///< parameters came from a *.vcad file (bad ones: VC_ERR_BAD_FILE)
  std::optional<vc_unit> units;     ///< option "units": the unit the model declares
  std::optional<double> tolerance;  ///< option "tolerance": the model tolerance
};

/// Parses `path` and `options` (see vc_model_load). A *.vcad file is:
///   # comments and blank lines anywhere
///   vcad 1                 <- first significant line (format and version)
///   naca.code = 0012       <- one generator parameter per line
/// Options: units=m|mm|cm|in|ft, tolerance=<positive number>, naca.<key>=<value> (overrides the path).
/// Throws FakeError (FILE_NOT_FOUND, BAD_FILE, BAD_PARAM, UNKNOWN_OPTION).
LoadRequest parse_load_request(const char* path, const char* options);

}  // namespace semimesh::vendor_fake
