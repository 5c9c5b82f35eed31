// Certified validity of a whole mesh: ho::certify_jacobian on every element (in parallel, the
// result independent of the thread count), with the figures a run report needs.
#pragma once

#include "semimesh/ho/validity.hpp"
#include "semimesh/mesh/mesh.hpp"
#include "semimesh/progress.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace semimesh::ho {

struct MeshValidity {
  std::vector<JacobianBounds> bounds;          ///< [elements] certified det J bounds
  std::size_t invalid = 0;                     ///< elements not acceptable(): not proven valid (unproven
                                               ///< included) or below the scaled-Jacobian floor
  std::size_t unproven = 0;                    ///< of those, the ones whose sign could not be decided
  double min_scaled_jacobian = 1.0;            ///< over all elements (scaled_jacobian(bounds)); 1 for no elements
  double median_scaled_jacobian = 1.0;         ///< lower median over all elements; 1 for no elements
  std::vector<std::size_t> invalid_elements;   ///< [invalid] element indices, ascending
  std::vector<Eigen::Vector3d> invalid_centroids;  ///< [invalid] mean of each invalid element's vertices
  bool all_valid() const { return invalid == 0; }
};

/// Certifies every 3D element of `mesh` (its order and node set) with certify_jacobian(..., max_depth,
/// min_scaled_jacobian); an element below that floor counts as invalid (see acceptable()).
/// Throws std::invalid_argument when the mesh holds a 2D element or max_depth < 0. `progress`
/// receives the fraction of elements certified (step "elements"), from one thread, throttled.
MeshValidity certify_mesh(const mesh::Mesh& mesh, int max_depth = 8, double min_scaled_jacobian = 0.0,
                          const ProgressCallback& progress = {});

}  // namespace semimesh::ho
