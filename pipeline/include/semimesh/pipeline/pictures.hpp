// The pictures `semimesh run --pictures` writes beside the mesh (io/pictures.hpp draws them): where
// to cut and what to zoom on is decided here from the body's boundary faces (group "wing") and the
// regions present.
#pragma once

#include "semimesh/checks/validity.hpp"
#include "semimesh/mesh/mesh.hpp"

#include <string>
#include <vector>

namespace semimesh::pipeline {

struct Picture {
  std::string suffix;  ///< file name after the basename, e.g. "_cut_le.svg"
  std::string svg;
};

/// Spanwise cuts (the span is z, the wall at the body's lowest z) at `station` (fraction of the
/// span): around the body, zoomed at the leading and trailing edges, across the root junction and
/// along the wake when those regions exist; the body's surface mesh along y and along x; the scaled
/// Jacobian histogram per element type. Throws std::invalid_argument when the mesh has no "wing"
/// boundary faces.
std::vector<Picture> mesh_pictures(const mesh::Mesh& mesh, const checks::ValidityResult& validity, double station);

}  // namespace semimesh::pipeline
