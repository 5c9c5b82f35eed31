// Certified validity of a whole mesh: ho::certify_jacobian on every element (in parallel, the
// result independent of the thread count), with the figures a run report needs.
#pragma once

#include "semimesh/ho/validity.hpp"
#include "semimesh/mesh/mesh.hpp"
#include "semimesh/progress.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <atomic>
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
  std::size_t inherited = 0;                   ///< elements whose bounds came from their parent (InheritedBounds
                                               ///< from_parent): the same count at every run
  std::size_t certified_before = 0;            ///< elements that took a certificate computed before (certify_ahead,
                                               ///< certify_behind): speculative work, so a count that depends on timing
  bool all_valid() const { return invalid == 0; }
};

/// Bounds an element got when it was made (a piece of a split element: certify_pieces), for the
/// node positions whose fingerprint it carries: they hold for that element while its nodes are
/// exactly those, whatever the stages after (welding, moving nodes) did to the mesh. Kept only for
/// the elements that have them (a third of the paper's case), in ascending element order.
struct InheritedBounds {
  std::size_t element = 0;        ///< the element's index in the mesh
  std::uint64_t fingerprint = 0;  ///< element_fingerprint when the bounds were derived
  JacobianBounds bounds;
  bool from_parent = true;        ///< derived from the parent's map; false: the element's own certificate,
                                  ///< computed before (certify_ahead, certify_behind)
};

/// A hash of element e's shape, the mesh's order and node set, and the bits of its nodes'
/// coordinates in element order (FNV-1a over 64-bit words).
std::uint64_t element_fingerprint(const mesh::Mesh& mesh, std::size_t e);

/// Certifies every 3D element of `mesh` (its order and node set) with certify_jacobian(..., max_depth,
/// min_scaled_jacobian); an element below that floor counts as invalid (see acceptable()).
/// Throws std::invalid_argument when the mesh holds a 2D element or max_depth < 0. `progress`
/// receives the fraction of elements certified (step "elements"), from one thread, throttled.
/// `inherited` (optional, ascending element indices, each < the number of elements; else
/// std::invalid_argument): an element that has an entry, whose fingerprint is still its own and whose inherited bounds decide it at the floor (all above
/// min_scaled_jacobian x their largest: certify_jacobian would not bisect) takes those bounds and
/// no Bernstein expansion of its own; every other element is certified. With no `inherited` this
/// is the reference: every element certified on its own nodes.
MeshValidity certify_mesh(const mesh::Mesh& mesh, int max_depth = 8, double min_scaled_jacobian = 0.0,
                          const ProgressCallback& progress = {},
                          const std::vector<InheritedBounds>* inherited = nullptr);

/// The certificates certify_mesh(mesh, max_depth, min_scaled_jacobian) computes, of the first
/// elements of `mesh` in order, each with its fingerprint: for a later certify_mesh of a mesh whose
/// first elements these may be, as `inherited` (it takes those it would not bisect and whose nodes
/// are still the same; the same validity either way). Computed ahead on the calling thread alone (one
/// OpenMP thread, its setting restored after: Eigen's products then run on one thread, as inside
/// certify_mesh's parallel loop, the same bits), e.g. beside TetGen's process; when `stop` is set
/// the elements certified so far (checked between elements). Throws as certify_mesh does.
std::vector<InheritedBounds> certify_ahead(const mesh::Mesh& mesh, int max_depth, double min_scaled_jacobian,
                                           const std::atomic<bool>& stop);

/// certify_ahead's certificates of the elements `wanted` (ascending) of a mesh that another thread
/// is still building (Mesh::replace_nodes): element e is read once `built` exceeds e, waiting until
/// it does; from then on its node list and nodes must no longer change. Returns those certified
/// when every wanted element is, or when `stop` is set (checked between elements and while waiting).
/// Throws as certify_ahead does.
std::vector<InheritedBounds> certify_behind(const mesh::Mesh& mesh, const std::vector<std::size_t>& wanted,
                                            const std::atomic<std::size_t>& built, int max_depth,
                                            double min_scaled_jacobian, const std::atomic<bool>& stop);

}  // namespace semimesh::ho
