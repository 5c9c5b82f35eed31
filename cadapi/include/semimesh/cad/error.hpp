// The one exception type of the CAD layer. Messages are written for the user: they name the file,
// the entity or the parameter at fault and what was expected.
#pragma once

#include "semimesh/error.hpp"

#include <string>

namespace semimesh::cad {

/// Its cause is an internal error for a failed query (Geometry) and bad input for everything else.
class CadError : public Error {
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

  CadError(Kind kind, const std::string& message)
      : Error(kind == Kind::Geometry ? Cause::Internal : Cause::BadInput, message), kind_(kind) {}
  Kind kind() const { return kind_; }

 private:
  Kind kind_;
};

}  // namespace semimesh::cad
