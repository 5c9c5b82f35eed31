// Repair of invalid curved elements by relaxing their free nodes toward the straight-sided element.
//
// For each listed element that is not certified valid (certify_jacobian), the nodes that carry no
// CAD attachment are blended between their straight position x_lin (the element's linear map at the
// node's reference position) and their curved one: x(t) = x_lin + t (x_curved - x_lin), t in [0, 1].
//  1. First only the element's own volume-interior nodes move; the largest t found by bisection for
//     which the element is certified valid is kept.
//  2. If t = 0 is not enough, every non-CAD node of the element moves (its edge and face nodes too,
//     e.g. on the skin), and the t kept must leave every element sharing a moved node valid.
//  3. A shell prism (face 0-1-2 curved on the body, straight outer face) whose curved body face
//     folds it against the straight outer face: every non-CAD node moves towards its straight
//     position plus the body face's displacement below it (the column follows the curved body,
//     outer face included); the first of t = 1, 3/4, 1/2, 1/4 that leaves it and every element
//     sharing a moved node acceptable is kept (the far-field elements on the skin get curved).
//  4. Otherwise the nodes on the CAD (its boundary face) cause the inversion: the element is left as
//     it was and reported with its id, centroid and the CAD surface.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/mesh/mesh.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

namespace semimesh::ho {

/// An element repair could not make valid.
struct RepairFailure {
  std::size_t element = 0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< mean of its vertices
  std::string reason;                                  ///< names the element, the place and the CAD surface
};

struct RepairStats {
  int checked = 0;               ///< elements listed
  int already_valid = 0;         ///< listed but certified valid: left alone
  int repaired_interior = 0;     ///< made valid by moving volume-interior nodes only (step 1)
  int repaired_free_nodes = 0;   ///< made valid by also moving non-CAD edge/face nodes (step 2)
  int repaired_body_following = 0;  ///< made valid by curving its column like the body face (step 3)
  double min_blend = 1.0;        ///< smallest blending parameter t kept by a repair (1: none needed)
  std::vector<RepairFailure> failures;  ///< step 4, in the order of `elements`
};

struct Repaired {
  mesh::Mesh mesh;
  RepairStats stats;
};

/// A copy of `mesh` whose listed elements are repaired in order (3D elements; the mesh's order and
/// node set); `model` is the CAD the attachments refer to (used to name the surface in a failure).
/// Nodes with a CAD attachment never move. Throws std::invalid_argument for an index out of range
/// or a 2D element. An element counts as repaired when acceptable(bounds, min_scaled_jacobian)
/// (0: proven valid).
Repaired repair_invalid(const mesh::Mesh& mesh, const cad::Model& model, const std::vector<std::size_t>& elements,
                        double min_scaled_jacobian = 0.0);

}  // namespace semimesh::ho
