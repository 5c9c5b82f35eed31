// The exception of the 1D/2D meshing stage. Messages name the surface or curve (id and name) and
// what went wrong, so a user can find the entity in the CAD model.
#pragma once

#include "semimesh/error.hpp"

namespace semimesh::surface {

class SurfaceMeshError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace semimesh::surface
