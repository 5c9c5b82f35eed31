// Isoparametric splitting of near-field elements into thin layers (paper, section "High-order mesh
// generation": the coarse curved element is subdivided in its reference space and every node of
// every sub-element is placed by the coarse element's own map chi, so the sub-elements inherit the
// curvature and, for a valid chi, the validity of the coarse element).
//
// Convention (near_field.hpp): prisms have vertices 0,1,2 on the body and 3,4,5 on the skin, hexes
// 0..3 on the body and 4..7 on the skin; the layer direction is reference zeta and the first
// (thinnest) layer touches the body. For split_hex_direction the first layer touches the face at
// reference coordinate -1 of the chosen direction.
#pragma once

#include "semimesh/ho/mesh_validity.hpp"
#include "semimesh/mesh/mesh.hpp"
#include "semimesh/params/table.hpp"
#include "semimesh/progress.hpp"

#include <Eigen/Core>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace semimesh::ho {

/// `layers` sub-layers whose thicknesses grow by `ratio` from the body outwards (ratio >= 1).
struct LayerDistribution {
  int layers = 5;
  double ratio = 2.0;
};

/// Reference positions z_0 = -1 < z_1 < ... < z_N = 1 of the layer interfaces: thicknesses h r^k,
/// k = 0..N-1, summing to the reference length 2 (what every split uses).
std::vector<double> layer_interfaces(int layers, double ratio);

/// One row per key of LayerDistribution (the config's [boundary_layer] section).
const params::Table<LayerDistribution>& layer_keys();

/// Position-dependent growth ratio (e.g. decaying to 1 along a wake). It is evaluated at each body
/// vertex of an element and the layer interfaces are interpolated linearly between the vertices,
/// so two neighbours see the same distribution on their shared vertical edges and faces (a ratio
/// per element would break conformity across shared side faces).
using RatioField = std::function<double(const Eigen::Vector3d&)>;

/// Figures of a split. Heights are straight distances between consecutive nodes along the vertical
/// edges of the split elements; achieved_ratio is the mean over those edges of
/// (last layer height / first layer height)^(1 / (layers - 1)) (1 for a single layer).
struct SplitStats {
  double first_cell_height_min = 0.0;
  double first_cell_height_max = 0.0;
  double achieved_ratio = 1.0;
  int elements_in = 0;
  int elements_out = 0;
};

/// Returns a new mesh of the same order and node set in which every prism/hex of `layer_elements`
/// (indices into mesh.elements()) is replaced by `layers` sub-elements stacked along reference zeta;
/// every other element and every boundary face is copied (boundary faces on a split element's side
/// face are split with it). Element order: input order, each split element replaced in place by its
/// sub-elements from the body outwards. Node ids of the input are kept (ids 0..mesh.num_nodes()-1
/// are the input nodes with their CAD attachments); the nodes inside the split elements' side faces
/// and volumes that only the coarse elements used are left unreferenced. New nodes carry no CAD
/// attachment. Throws std::invalid_argument naming the element when it is not a prism/hex, an
/// index is out of range, layers < 1 or a ratio < 1.
mesh::Mesh split_layers(const mesh::Mesh& mesh, const std::vector<std::size_t>& layer_elements,
                        const LayerDistribution& distribution, const RatioField& ratio = {},
                        SplitStats* stats = nullptr);

/// A layer distribution with its optional per-vertex ratio field: one boundary layer (a family:
/// e.g. the wing's, the wall's).
struct SplitFamily {
  LayerDistribution distribution;
  RatioField ratio;
};

/// An element to split, along one reference direction (0 xi, 1 eta, 2 zeta; prisms: 2) or two
/// (hexes: direction[1] >= 0, e.g. a root junction hex across both wall normals), each with the
/// family (index into the families) whose layers it takes. A ratio field on the second direction
/// is read at the top of the first (a junction hex: along its wall foot, where the wall layer's
/// prisms meet it), so it varies along the third direction only.
struct LayerSplit {
  std::size_t element = 0;
  std::array<int, 2> direction{2, -1};
  std::array<int, 2> family{0, 0};
};

/// Splits every listed element in one pass, each along its own direction(s): an element split in
/// one direction into N pieces (the family's layers), in two into N_a x N_b pieces, ordered
/// k_b N_a + k_a (k = 0 the body side of each direction). Every face cut by a split is cut the same
/// way from both sides, so the pieces conform node for node at any order. A split element whose
/// cut face is shared with an element that does not cut it the same way (not split, or split by
/// another family or with other body-side vertices) is refused (std::invalid_argument naming both
/// elements). `stats` gets one SplitStats per family (first-cell heights along its directions);
/// (*first_piece)[e] is the output index of input element e's first piece (its copy when not split).
/// `progress` receives the fraction of split elements done (step "elements"), per block of elements,
/// from the calling thread.
/// `inherited` (optional) gets the bounds of det J pieces inherit from their coarse element
/// (certify_pieces), by output element in ascending order, for certify_mesh: given for the pieces of an element whose
/// interfaces are constant over it (no ratio field, or one giving the family's ratio at all its
/// bottom vertices: each piece is then the coarse map composed with an affine map), and whose
/// bounds need no bisection; absent for the rest (copied elements, pieces of an element whose
/// interfaces vary: its pieces are then the interpolant of a map of higher degree, not the coarse
/// map composed with an affine one).
mesh::Mesh split_layers(const mesh::Mesh& mesh, const std::vector<LayerSplit>& split,
                        const std::vector<SplitFamily>& families, std::vector<SplitStats>* stats,
                        std::vector<std::size_t>* first_piece, const ProgressCallback& progress = {},
                        std::vector<InheritedBounds>* inherited = nullptr);
/// The bounds split_layers' `inherited` derives for the pieces of elements whose interfaces are
/// constant (certify_pieces), derived before the split: e.g. beside TetGen's process, from a
/// curved mesh whose elements are the first ones of the mesh split later. Each element's entry
/// carries a fingerprint of what the bounds were derived from (its shape, the order and node set,
/// its coarse nodes' coordinates and its pieces' reference boxes, bit for bit): split_layers takes
/// an entry whose fingerprint is still that of the element it splits, else derives the bounds
/// itself, so the bounds are the same either way.
class PieceBoundsAhead {
 public:
  struct Entry {
    std::size_t element = 0;
    std::uint64_t fingerprint = 0;
    std::vector<std::optional<JacobianBounds>> bounds;  ///< [pieces] as certify_pieces gives them
  };
  /// `entries` in ascending element order (else std::invalid_argument).
  explicit PieceBoundsAhead(std::vector<Entry> entries = {});
  /// The entry of `element` if it has one with this fingerprint, else null.
  const std::vector<std::optional<JacobianBounds>>* find(std::size_t element, std::uint64_t fingerprint) const;
  std::size_t size() const { return entries_.size(); }
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::vector<Entry> entries_;
};

/// The entries of PieceBoundsAhead for the listed elements of `mesh` (those with an index in it;
/// `split` and `families` as split_layers takes them) whose interfaces are constant, in ascending
/// element order, on the calling thread alone (one OpenMP thread: the same bits as inside the
/// split's parallel loop). When `stop` is set, the entries derived so far (checked between
/// elements). Throws what split_layers throws for a bad list or family.
PieceBoundsAhead piece_bounds_ahead(const mesh::Mesh& mesh, const std::vector<LayerSplit>& split,
                                    const std::vector<SplitFamily>& families, const std::atomic<bool>& stop);

/// The output's edges and faces: Canonical, as add_element makes them element by element;
/// Adopted, every entity of the input under its id (the elements that are not split come over
/// without a lookup: mesh::Mesh::adopt_all_entities), then the pieces' new ones, with the input's
/// entities that only split elements used left unused: for a caller that renumbers the entities
/// next (mesh::Mesh::replace_nodes, without_unreferenced_nodes), which then gives the Canonical
/// output's.
enum class SplitEntities { Canonical, Adopted };

/// The same on a mesh given up: its nodes move into the output instead of being copied, so they
/// are held once. The mesh is left without nodes (only the moved-from mesh's destruction or
/// assignment is then meaningful). `ahead` (optional): pieces' bounds derived before, taken where
/// they still hold (PieceBoundsAhead).
mesh::Mesh split_layers(mesh::Mesh&& mesh, const std::vector<LayerSplit>& split,
                        const std::vector<SplitFamily>& families, std::vector<SplitStats>* stats,
                        std::vector<std::size_t>* first_piece, const ProgressCallback& progress = {},
                        std::vector<InheritedBounds>* inherited = nullptr,
                        SplitEntities entities = SplitEntities::Canonical, const PieceBoundsAhead* ahead = nullptr);

/// The same for hexahedra along reference direction `direction` (0 xi, 1 eta, 2 zeta), e.g. the
/// second wall-normal direction of root junction blocks. Throws for a non-hex element or a
/// direction outside 0..2.
mesh::Mesh split_hex_direction(const mesh::Mesh& mesh, const std::vector<std::size_t>& hexes, int direction,
                               const LayerDistribution& distribution, SplitStats* stats = nullptr);

}  // namespace semimesh::ho
