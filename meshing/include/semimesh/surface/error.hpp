// The exception of the 1D/2D meshing stage. Messages name the surface or curve (id and name) and
// what went wrong, so a user can find the entity in the CAD model.
#pragma once

#include <stdexcept>
#include <string>

namespace semimesh::surface {

class SurfaceMeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace semimesh::surface
