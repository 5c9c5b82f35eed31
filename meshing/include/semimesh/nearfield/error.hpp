// The exception of the near-field stage. Messages name the CAD surface (id and name) and the place
// (coordinates) where the layer could not be built, and the parameter a user can change.
#pragma once

#include "semimesh/error.hpp"

namespace semimesh::nearfield {

class NearFieldError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace semimesh::nearfield
