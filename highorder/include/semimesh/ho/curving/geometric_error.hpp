// Geometric error of a curved mesh (docs/architecture.md, section 4): distance from points of its boundary faces
// to the CAD surface they represent, relative to a reference length (the chord).
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/mesh/mesh.hpp"

#include <vector>

namespace semimesh::ho {

struct GeometricError {
  double max_rel = 0.0;  ///< largest distance / reference_length
  double rms_rel = 0.0;  ///< root mean square over all samples / reference_length
  int samples = 0;       ///< number of points measured
};

/// Samples every boundary face whose vertices lie on one CAD surface (by their attachments) at a
/// lattice of samples_per_edge intervals per edge, maps the samples through the face's own map, and
/// projects each onto the surface (guess: the (u, v) interpolated from the face nodes' parameters).
/// Only faces on `surfaces` when it is not empty (the pipeline's: the body and the wall, which it
/// curves; a curved far field such as a sphere stays straight-sided on purpose).
/// Throws std::invalid_argument for reference_length <= 0 or samples_per_edge < 1.
GeometricError geometric_error(const mesh::Mesh& mesh, const cad::Model& model, double reference_length,
                               int samples_per_edge = 10, const std::vector<int>& surfaces = {});

}  // namespace semimesh::ho
