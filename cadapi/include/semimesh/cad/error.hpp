// The one exception type of the CAD layer. Messages are written for the user: they name the file,
// the entity or the parameter at fault and what was expected.
#pragma once

#include <stdexcept>
#include <string>

namespace semimesh::cad {

class CadError : public std::runtime_error {
 public:
  enum class Kind {
    UnknownBackend,       ///< no backend of that name is known
    BackendUnavailable,   ///< known, but not built into this binary
    FileNotFound,         ///< the source path does not exist or cannot be opened
    FileUnreadable,       ///< the file exists but cannot be parsed (corrupt, wrong format)
    NoGeometry,           ///< the file parsed but holds no usable solid/faces
    BadParameter,         ///< a generator or load parameter is out of range or malformed
    Geometry,             ///< an evaluation or query failed on a given entity
  };

  CadError(Kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  Kind kind() const { return kind_; }

 private:
  Kind kind_;
};

}  // namespace semimesh::cad
