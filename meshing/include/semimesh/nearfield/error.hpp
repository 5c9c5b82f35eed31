// The exception of the near-field stage. Messages name the CAD surface (id and name) and the place
// (coordinates) where the layer could not be built, and the parameter a user can change.
#pragma once

#include <stdexcept>
#include <string>

namespace semimesh::nearfield {

class NearFieldError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace semimesh::nearfield
