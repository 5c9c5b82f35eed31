#include "semimesh/ho/splitting/split_layers.hpp"

#include "inside_nodes.hpp"
#include "lattice_lines.hpp"
#include "parallel_for.hpp"
#include "reference_lattice.hpp"
#include "sparse_rows.hpp"
#include "split_by_keys.hpp"
#include "semimesh/ho/basis.hpp"
#include "semimesh/ho/validity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>

namespace semimesh::ho {

std::vector<double> layer_interfaces(int layers, double ratio) {
  std::vector<double> thickness(layers);
  double total = 0.0, h = 1.0;
  for (int k = 0; k < layers; ++k) {
    thickness[k] = h;
    total += h;
    h *= ratio;
  }
  std::vector<double> z(layers + 1, -1.0);
  for (int k = 0; k < layers; ++k) z[k + 1] = z[k] + 2.0 * thickness[k] / total;
  z[layers] = 1.0;
  return z;
}

namespace {

using detail::LatticePoint;
using mesh::NodeId;


/// The body side of a shape for one split direction.
struct DirectionData {
  std::vector<int> bottom;  // local vertices on the face at coordinate -1
  std::vector<int> top_of;  // [vertices] partner on the opposite face (-1 if none)
  std::vector<int> across;  // [vertices] the local edge from a bottom vertex to its top_of (-1 if none)
  std::vector<std::array<int, 2>> bottom_edges;
  std::vector<int> side_face;  // [bottom_edges] the local face standing on it
};

/// What does not change from one element of a shape to the next.
struct ShapeData {
  Shape shape;
  std::vector<LatticePoint> lattice;        // [nodes] canonical lattice coordinates
  std::map<LatticePoint, int> index;        // lattice point -> canonical index
  Eigen::MatrixX3d reference;               // (nodes, 3) reference nodes of the mesh's node set
  LagrangeBasis basis;                      // order P, the mesh's node set
  std::map<int, DirectionData> directions;  // by split direction, filled on demand
  std::map<std::array<int, 2>, detail::LatticeLines> lines;  // by a plan's directions, filled on demand
};

DirectionData make_direction_data(const ShapeData& data, int order, int direction) {
  DirectionData d;
  const int nv = num_vertices(data.shape);
  d.top_of.assign(nv, -1);
  for (int v = 0; v < nv; ++v) {
    if (data.lattice[v][direction] != 0) continue;
    d.bottom.push_back(v);
    LatticePoint partner = data.lattice[v];
    partner[direction] = order;
    d.top_of[v] = data.index.at(partner);
  }
  const auto local_edge = [&](int a, int b) {
    const auto& all = edges(data.shape);
    for (std::size_t k = 0; k < all.size(); ++k)
      if ((all[k][0] == a && all[k][1] == b) || (all[k][0] == b && all[k][1] == a)) return static_cast<int>(k);
    throw std::logic_error("split: no local edge joins vertices " + std::to_string(a) + " and " + std::to_string(b));
  };
  const auto local_face = [&](std::array<int, 4> corners) {
    std::sort(corners.begin(), corners.end());
    const auto& all = faces(data.shape);
    for (std::size_t k = 0; k < all.size(); ++k) {
      if (all[k].size() != 4) continue;
      std::array<int, 4> f{all[k][0], all[k][1], all[k][2], all[k][3]};
      std::sort(f.begin(), f.end());
      if (f == corners) return static_cast<int>(k);
    }
    throw std::logic_error("split: no local face stands on a bottom edge");
  };
  d.across.assign(nv, -1);
  for (int v : d.bottom) d.across[v] = local_edge(v, d.top_of[v]);
  for (const auto& e : edges(data.shape))
    if (data.lattice[e[0]][direction] == 0 && data.lattice[e[1]][direction] == 0) {
      d.bottom_edges.push_back(e);
      d.side_face.push_back(local_face({e[0], e[1], d.top_of[e[0]], d.top_of[e[1]]}));
    }
  return d;
}

/// Where lattice point h lies strictly inside the segment from a to b: {along, steps}, h being `along`
/// of the segment's `steps` lattice steps from a; std::nullopt elsewhere.
std::optional<std::array<int, 2>> place_on_segment(const LatticePoint& a, const LatticePoint& b, const LatticePoint& h) {
  int steps = 0, along = 0;
  for (int c = 0; c < 3; ++c) steps = std::max(steps, std::abs(b[c] - a[c]));
  for (int c = 0; c < 3; ++c) along = std::max(along, std::abs(h[c] - a[c]));
  for (int c = 0; c < 3; ++c)
    if ((h[c] - a[c]) * steps != (b[c] - a[c]) * along) return std::nullopt;
  if (along <= 0 || along >= steps) return std::nullopt;
  return std::array<int, 2>{along, steps};
}

/// A new node's name (key_of): its kind, then what names it; kinds 1 and 2 (on a coarse edge
/// or side face) carry that entity's id last, where its slots are kept (slot_of).
using NodeKey = std::array<std::int64_t, 8>;
constexpr std::uint32_t kNoBlock = 0xffffffffu;  // a coarse entity without slots yet

// Split elements whose sub-node positions are held at once (bounds the memory of the parallel pass).
constexpr std::size_t kSplitBlock = 1024;

/// How one element is split: up to two directions (-1: none), each with its family.
struct Plan {
  std::array<int, 2> direction{-1, -1};
  std::array<int, 2> family{0, 0};
  bool split() const { return direction[0] >= 0; }
  bool two() const { return direction[1] >= 0; }
};

/// How a split cuts one face of an element, per split direction crossing it: the direction's family
/// and the face's vertices on that direction's bottom (sorted; unused entries kNoNode). A value
/// with room for both directions of a hexahedron: the side-face checks ask for every face of every
/// split element, and vectors there cost an allocation each.
struct FaceCut {
  int family = 0;
  std::array<NodeId, 4> bottom{mesh::kNoNode, mesh::kNoNode, mesh::kNoNode, mesh::kNoNode};
  bool operator==(const FaceCut& o) const { return family == o.family && bottom == o.bottom; }
  bool operator<(const FaceCut& o) const { return std::tie(family, bottom) < std::tie(o.family, o.bottom); }
};
struct FaceCuts {
  std::array<FaceCut, 2> cut{};
  int count = 0;
  bool empty() const { return count == 0; }
  void add(const FaceCut& c) { cut[count++] = c; }
  void sort() {
    if (count == 2 && cut[1] < cut[0]) std::swap(cut[0], cut[1]);
  }
  bool operator==(const FaceCuts& o) const {
    return count == o.count && std::equal(cut.begin(), cut.begin() + count, o.cut.begin());
  }
};

/// One distinct node of the pieces of an element split by a plan, named without the element
/// (what key_of computes from the element, worked out once per shape, plan and layer counts).
struct SubNode {
  enum class Kind : std::uint8_t {
    Coarse,  ///< a coarse node: `local`
    Edge,    ///< on the coarse edge `local` across the layers, at level `level`
    Face,    ///< on the coarse side face `local` standing on bottom edge (a, b), `along` of `steps`
    Inside,  ///< inside the element: no other element names it
    Keyed,   ///< on a face cut both ways: named by key_of at `point`, `g`
  };
  Kind kind = Kind::Coarse;
  int local = 0;
  int a = 0, b = 0, along = 0, steps = 0, level = 0;
  LatticePoint point{};
  std::array<int, 2> g{0, 0};
  int first_row = 0;  ///< piece * nodes + i of its first use: the row of the positions it is placed at
};

/// Every distinct node of an element's pieces in the order of first use (piece by piece, node by
/// node, the order in which they are made), and for every piece's node which one it is.
struct SplitRecipe {
  std::vector<SubNode> nodes;
  std::vector<std::uint32_t> node_of;  ///< [pieces * nodes] index into `nodes`
};

class Splitter {
 public:
  /// `give_nodes`: the input itself, whose nodes then move into the output instead of being copied
  /// (the input keeps its topology only; coordinates are read from the output, same ids).
  Splitter(const mesh::Mesh& in, std::vector<SplitFamily> families, std::string caller,
           mesh::Mesh* give_nodes = nullptr, SplitEntities entities = SplitEntities::Canonical)
      : in_(in),
        give_nodes_(give_nodes),
        adopt_(entities == SplitEntities::Adopted),
        families_(std::move(families)),
        caller_(std::move(caller)),
        out_(in.order(), in.node_set()),
        stats_(families_.size()) {}

  /// The steps: check the families and the list, plan each listed element, check that split
  /// neighbours cut their shared faces alike, then the output mesh: the input's nodes, each element
  /// copied or replaced by its pieces in input order, the boundary faces cut with their element.
  mesh::Mesh run(const std::vector<LayerSplit>& split, std::vector<SplitStats>* stats,
                 std::vector<std::size_t>* first_piece, const ProgressCallback& progress = {},
                 std::vector<InheritedBounds>* inherited = nullptr);
  /// run names every node by key_of (split_element_by_keys): the reference.
  void name_nodes_by_keys() { by_keys_ = true; }
  /// run's inherited bounds taken from `ahead` where they still hold (null: none).
  void take_bounds_from(const PieceBoundsAhead* ahead) { ahead_ = ahead; }
  /// PieceBoundsAhead's entries for the listed elements of the input (piece_bounds_ahead).
  std::vector<PieceBoundsAhead::Entry> bounds_ahead(const std::vector<LayerSplit>& split, const std::atomic<bool>& stop);

 private:
  /// Throws unless there is a family and each has layers >= 1 and a constant ratio >= 1.
  void check_families() const;
  /// Throws naming the element when one entry of the list cannot be split as asked (index, shape,
  /// direction, family).
  void check_split_entry(const LayerSplit& entry) const;
  /// Fills plans_ and the shape caches; returns [input elements] the entry's index in `split`, or -1.
  std::vector<int> plan_elements(const std::vector<LayerSplit>& split);
  /// The output starts as the input's nodes (with their CAD attachments), groups and regions.
  /// Returns the number of elements the output will have.
  std::size_t copy_nodes_groups_and_regions();
  /// Every input element into the output in input order, split ones as their pieces (with their
  /// inherited bounds when asked); returns [split element j, in `split`'s order] the output index
  /// of its first piece (the pieces' node lists are then read from the output, never kept).
  std::vector<std::size_t> add_elements(const std::vector<int>& position, std::size_t split_count,
                                        std::vector<std::size_t>* first_piece, const ProgressCallback& progress,
                                        std::vector<InheritedBounds>* inherited);
  /// Input elements [from, end) copied as they are.
  void copy_elements(std::size_t from, std::size_t end, std::vector<std::size_t>* first_piece);
  /// The pieces of one split element, with the bounds certify_pieces derived for them when asked.
  void add_pieces(std::size_t element, const std::vector<std::vector<NodeId>>& pieces,
                  const std::vector<std::optional<JacobianBounds>>& bounds, std::vector<InheritedBounds>* inherited);
  /// Each inherited entry's element_fingerprint, taken from the finished output.
  void fingerprint_pieces(std::vector<InheritedBounds>& inherited) const;
  /// Each input boundary face: one per piece lying on it when its element's split cuts it, else copied.
  void add_boundary_faces(const std::vector<LayerSplit>& split, const std::vector<int>& position,
                          const std::vector<std::size_t>& first_out);
  /// Does piece `piece` of `element` lie on the element's face with local vertices `local`?
  bool piece_on_face(std::size_t element, std::size_t piece, const std::vector<int>& local) const;
  /// [families] the figures gathered while splitting.
  std::vector<SplitStats> split_stats() const;

  ShapeData& shape_data(Shape shape);
  const DirectionData& direction_data(Shape shape, int direction);
  const ShapeData& data_of(std::size_t element) const { return shapes_.at(in_.elements()[element].shape); }
  const DirectionData& direction_of(std::size_t element, int slot) const {
    return data_of(element).directions.at(plans_[element].direction[slot]);
  }
  int layers(std::size_t element, int slot) const {
    return plans_[element].direction[slot] < 0 ? 1 : families_[plans_[element].family[slot]].distribution.layers;
  }
  /// Basis values (their entries that are not 0: sparse_rows.hpp) at every sub-node of every piece
  /// for elements of this shape and plan whose families have constant ratios (cached).
  const detail::SparseRows& uniform_values(Shape shape, const Plan& plan);
  /// Reference points of every node of every piece, piece (k_a, k_b) at rows (k_b N_a + k_a) nodes;
  /// `interface(s, r, k)` gives interface k of direction slot s at reference point r.
  template <typename Interface>
  Eigen::MatrixX3d sub_points(const ShapeData& data, const Plan& plan, const Interface& interface) const;
  /// Throws naming both elements when a split element's face cut by its split is shared with an
  /// element that does not cut it the same way (same families, same body-side vertices).
  void check_side_faces(const std::vector<LayerSplit>& split);
  /// Per split direction of a face of an element: (family, sorted body-side vertex ids).
  FaceCuts cuts(std::size_t element, std::uint32_t face) const;

  struct SplitGeometry {
    Eigen::MatrixX3d x;                                // (pieces * nodes, 3)
    std::array<std::vector<double>, 2> first_heights;  // per direction slot: [bottom vertices]
    std::array<std::vector<double>, 2> ratios;
    std::vector<std::optional<JacobianBounds>> bounds;  // [pieces] inherited (certify_pieces), when asked
  };
  /// Per direction slot, the layer interfaces at each bottom vertex of that direction (calls the
  /// ratio field at the vertices' points in `at`; serial). Empty for a slot whose ratio is constant
  /// over the element.
  using VertexInterfaces = std::array<std::vector<std::vector<double>>, 2>;
  VertexInterfaces interfaces_of(std::size_t element, const mesh::Mesh& at) const;
  /// Per direction slot, the interfaces of constant ratio the family's own (one for no split).
  std::array<std::vector<double>, 2> uniform_interfaces(std::size_t element) const;
  SplitGeometry place_sub_nodes(std::size_t element, const VertexInterfaces& z_of_vertex) const;
  /// The reference boxes of the pieces of an element split with constant interfaces `z` per slot.
  std::vector<ReferenceBox> piece_boxes(std::size_t element, const std::array<std::vector<double>, 2>& z) const;
  /// Piece node lists of one coarse element into pieces_, body-side pieces first; creates the new
  /// nodes, each named once through the element's recipe.
  void split_element(std::size_t element, const SplitGeometry& geometry);
  /// The same, every node of every piece named by key_of and looked up: the reference.
  void split_element_by_keys(std::size_t element, const SplitGeometry& geometry);
  /// The recipe of an element's shape, plan and layer counts (made on first use).
  const SplitRecipe& recipe_of(std::size_t element);
  /// What key_of names the node at lattice point `l`, refined coordinates `g`, of an element of
  /// `data`'s shape split by `plan` into (na, nb) layers, without the element.
  SubNode describe(const ShapeData& data, const Plan& plan, int na, int nb, const LatticePoint& l,
                   const std::array<int, 2>& g);
  /// Stats of one split element.
  void add_figures(std::size_t element, const SplitGeometry& geometry);
  NodeKey key_of(std::size_t element, const std::vector<NodeId>& coarse, const LatticePoint& l,
                 const std::array<int, 2>& g) const;
  NodeId node_for(const NodeKey& key, const Eigen::Vector3d& x);
  /// Where the node of this key is kept (kNoNode until made).
  NodeId& slot_of(const NodeKey& key);
  double ratio_at(const Eigen::Vector3d& x, std::size_t element, int family) const;

  const mesh::Mesh& in_;
  mesh::Mesh* give_nodes_;
  bool adopt_;  // SplitEntities::Adopted
  std::vector<SplitFamily> families_;
  std::string caller_;
  mesh::Mesh out_;
  std::vector<Plan> plans_;  // [input elements]
  std::map<Shape, ShapeData> shapes_;
  std::map<std::tuple<Shape, int, int, int, int>, detail::SparseRows> uniform_;
  // The nodes made so far, by where they are (key_of): on a coarse edge or face shared with
  // neighbours, in a block of slots of that entity in `slots_` (4 bytes a node: a map of every key
  // held ~1 GB on the paper's case; a vector per entity ~50 MB of headers and allocations), made at
  // its first node and large enough for any split of it; inside the element, only while it is
  // split; the rare rest by key.
  std::vector<std::uint32_t> edge_block_, face_block_;  // [input edges], [input faces]: first slot, or kNoBlock
  std::vector<NodeId> slots_;
  std::size_t edge_block_size_ = 0, face_block_size_ = 0;
  std::size_t nodes_bound_ = 0;  // the most nodes the output can have: room reserved for them
  detail::InsideNodes element_nodes_;       // inside the element being split (split_element_by_keys)
  std::map<NodeKey, NodeId> other_nodes_;
  // Scratch of split_element, reused so that an element costs no allocation: the coarse element's
  // nodes, its pieces' node lists.
  std::vector<NodeId> coarse_;
  std::vector<std::vector<NodeId>> pieces_;
  std::vector<NodeId> recipe_ids_;  // [recipe nodes] this element's ids
  std::map<std::tuple<Shape, int, int, int, int>, SplitRecipe> recipes_;  // by shape, directions, layers
  bool by_keys_ = false;  // split_element_by_keys (the reference) instead of split_element
  struct Figures {
    double height_min = 1e300, height_max = 0.0, ratio_sum = 0.0;
    int vertical_edges = 0, elements = 0;
  };
  std::vector<Figures> stats_;  // [families]
  bool inherit_ = false;        // derive the pieces' bounds (certify_pieces)
  const PieceBoundsAhead* ahead_ = nullptr;  // or take them from here where they hold
};

// What a split element's pieces' bounds are derived from, bit for bit (FNV-1a on 64-bit words, as
// element_fingerprint): its shape, order and node set, coarse nodes (n, 3) and pieces' boxes.
std::uint64_t pieces_fingerprint(Shape shape, int order, NodeSet set, const Eigen::MatrixX3d& x,
                                 const std::vector<ReferenceBox>& boxes) {
  std::uint64_t hash = 14695981039346656037ull;
  const auto mix = [&](std::uint64_t word) {
    hash ^= word;
    hash *= 1099511628211ull;
  };
  const auto mix_double = [&](double d) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &d, sizeof bits);
    mix(bits);
  };
  mix(static_cast<std::uint64_t>(shape));
  mix(static_cast<std::uint64_t>(order));
  mix(static_cast<std::uint64_t>(set));
  mix(static_cast<std::uint64_t>(x.rows()));
  for (Eigen::Index i = 0; i < x.size(); ++i) mix_double(x.data()[i]);
  mix(boxes.size());
  for (const ReferenceBox& box : boxes)
    for (const auto& interval : box) {
      mix_double(interval[0]);
      mix_double(interval[1]);
    }
  return hash;
}

ShapeData& Splitter::shape_data(Shape shape) {
  auto it = shapes_.find(shape);
  if (it != shapes_.end()) return it->second;
  const int order = in_.order();
  ShapeData data{shape,
                 detail::lattice_points(shape, order),
                 detail::lattice_index(shape, order),
                 reference_nodes(shape, order, in_.node_set()),
                 LagrangeBasis(shape, order, in_.node_set()),
                 {},
                 {}};
  return shapes_.emplace(shape, std::move(data)).first->second;
}

const DirectionData& Splitter::direction_data(Shape shape, int direction) {
  ShapeData& data = shape_data(shape);
  auto it = data.directions.find(direction);
  if (it == data.directions.end())
    it = data.directions.emplace(direction, make_direction_data(data, in_.order(), direction)).first;
  return it->second;
}

template <typename Interface>
Eigen::MatrixX3d Splitter::sub_points(const ShapeData& data, const Plan& plan, const Interface& interface) const {
  const int da = plan.direction[0], db = plan.direction[1];
  const int na = families_[plan.family[0]].distribution.layers;
  const int nb = plan.two() ? families_[plan.family[1]].distribution.layers : 1;
  const int nn = static_cast<int>(data.reference.rows());
  Eigen::MatrixX3d q(na * nb * nn, 3);
  for (int kb = 0; kb < nb; ++kb)
    for (int ka = 0; ka < na; ++ka)
      for (int i = 0; i < nn; ++i) {
        Eigen::RowVector3d r = data.reference.row(i);
        // The second direction first (its interfaces do not depend on where the point is along
        // either split direction: see place_sub_nodes), so the first one's interfaces are read
        // where the point lands across it.
        if (plan.two()) {
          const double y0 = interface(1, r, kb), y1 = interface(1, r, kb + 1);
          r(db) = y0 + 0.5 * (r(db) + 1.0) * (y1 - y0);
        }
        const double z0 = interface(0, r, ka), z1 = interface(0, r, ka + 1);
        r(da) = z0 + 0.5 * (r(da) + 1.0) * (z1 - z0);
        q.row((kb * na + ka) * nn + i) = r;
      }
  return q;
}

const detail::SparseRows& Splitter::uniform_values(Shape shape, const Plan& plan) {
  const auto key = std::make_tuple(shape, plan.direction[0], plan.family[0], plan.direction[1], plan.family[1]);
  auto it = uniform_.find(key);
  if (it != uniform_.end()) return it->second;
  const ShapeData& data = shape_data(shape);
  std::array<std::vector<double>, 2> z;
  for (int slot = 0; slot < (plan.two() ? 2 : 1); ++slot) {
    const LayerDistribution& d = families_[plan.family[slot]].distribution;
    z[slot] = layer_interfaces(d.layers, d.ratio);
  }
  const Eigen::MatrixX3d q =
      sub_points(data, plan, [&](int slot, const Eigen::RowVector3d&, int k) { return z[slot][k]; });
  return uniform_.emplace(key, detail::sparse_rows(data.basis.values(q))).first->second;
}

double Splitter::ratio_at(const Eigen::Vector3d& x, std::size_t element, int family) const {
  const SplitFamily& f = families_[family];
  const double r = f.ratio ? f.ratio(x) : f.distribution.ratio;
  if (!(r >= 1.0) || !std::isfinite(r))
    throw std::invalid_argument(caller_ + ": layer ratio " + std::to_string(r) + " at a vertex of element " +
                                std::to_string(element) + " must be a finite number >= 1");
  return r;
}

// Kinds of key_of: 1 on a coarse edge (its ends, level, the edge), 2 on a coarse face (bottom edge,
// top edge, place along, level, the face), 3 inside the element, 4 on a face cut both ways.
NodeId& Splitter::slot_of(const NodeKey& key) {
  auto slot = [&](std::uint32_t& block, std::size_t size, std::size_t i) -> NodeId& {
    if (i >= size) throw std::logic_error(caller_ + ": a node's slot lies beyond its coarse entity's block");
    if (block == kNoBlock) {
      block = static_cast<std::uint32_t>(slots_.size());
      slots_.resize(slots_.size() + size, mesh::kNoNode);
    }
    return slots_[block + i];
  };
  if (key[0] == 1) return slot(edge_block_[key[7]], edge_block_size_, static_cast<std::size_t>(key[3]));
  if (key[0] == 2)
    return slot(face_block_[key[7]], face_block_size_, static_cast<std::size_t>(key[6] * in_.order() + key[5]));
  if (key[0] == 3) {
    return element_nodes_[key];
  }
  return other_nodes_.try_emplace(key, mesh::kNoNode).first->second;
}

NodeId Splitter::node_for(const NodeKey& key, const Eigen::Vector3d& x) {
  NodeId& id = slot_of(key);
  if (id == mesh::kNoNode) id = out_.add_node(x);
  return id;
}

Splitter::VertexInterfaces Splitter::interfaces_of(std::size_t element, const mesh::Mesh& at) const {
  const mesh::Element& el = in_.elements()[element];
  const Plan& plan = plans_[element];
  VertexInterfaces z_of_vertex;
  for (int slot = 0; slot < (plan.two() ? 2 : 1); ++slot) {
    const int family = plan.family[slot];
    if (!families_[family].ratio) continue;
    std::vector<std::vector<double>> z(num_vertices(el.shape));
    bool uniform = true;  // the field gives the family's own ratio at every bottom vertex
    for (int v : direction_of(element, slot).bottom) {
      const double r = ratio_at(at.node(el.vertices[v]), element, family);
      uniform = uniform && r == families_[family].distribution.ratio;
      z[v] = layer_interfaces(layers(element, slot), r);
    }
    // Uniform: the cached basis values of the constant ratio give the same points.
    if (!uniform) z_of_vertex[slot] = std::move(z);
  }
  return z_of_vertex;
}

Splitter::SplitGeometry Splitter::place_sub_nodes(std::size_t element, const VertexInterfaces& z_of_vertex) const {
  const mesh::Element& el = in_.elements()[element];
  const ShapeData& data = data_of(element);
  const Plan& plan = plans_[element];
  const detail::LatticeLines& lines = data.lines.at(plan.direction);
  // The coarse nodes are the output's first ones, same ids.
  const std::vector<NodeId> coarse = in_.element_nodes(element);
  Eigen::MatrixX3d X(coarse.size(), 3);
  for (std::size_t i = 0; i < coarse.size(); ++i) X.row(i) = out_.node(coarse[i]).transpose();

  // Coarse reference points of every node of every piece, then chi at all of them at once. With
  // constant ratios they are the same for every element of a shape and plan: the basis values are
  // cached.
  SplitGeometry out;
  const std::array<std::vector<double>, 2> uniform = uniform_interfaces(element);
  // Interfaces per bottom vertex, interpolated linearly in between (see RatioField). The first
  // direction's at the foot of the point across it; the second's at the foot across it taken at
  // the top of the first (a junction hex: along its wall foot L, where the wall layer's prisms
  // meet it), so they depend on neither split coordinate and match those prisms' side faces.
  const auto interface_at = [&](int slot, const Eigen::RowVector3d& q, int k) {
    if (z_of_vertex[slot].empty()) return uniform[slot][k];
    Eigen::RowVector3d foot = q;
    foot(plan.direction[slot]) = -1.0;
    if (slot == 1) foot(plan.direction[0]) = 1.0;
    const std::array<double, 8> w = detail::linear_weights(el.shape, foot);
    double z = 0.0;
    for (int v : direction_of(element, slot).bottom) z += w[v] * z_of_vertex[slot][v][k];
    return z;
  };
  if (z_of_vertex[0].empty() && z_of_vertex[1].empty()) {
    out.x = detail::multiply(
        uniform_.at(std::make_tuple(el.shape, plan.direction[0], plan.family[0], plan.direction[1], plan.family[1])), X);
    // Constant interfaces: each piece is chi composed with an affine map, so its det J is chi's restricted.
    if (inherit_) {
      const std::vector<ReferenceBox> boxes = piece_boxes(element, uniform);
      const auto* known =
          ahead_ ? ahead_->find(element, pieces_fingerprint(el.shape, in_.order(), in_.node_set(), X, boxes)) : nullptr;
      out.bounds = known ? *known : certify_pieces(el.shape, in_.order(), in_.node_set(), X, boxes);
    }
  } else {
    out.x = detail::map_along_lines(lines, X, sub_points(data, plan, interface_at));
  }

  // Heights along the vertical edges of each direction, for the stats.
  const Eigen::MatrixX3d corners = reference_vertices(el.shape);
  for (int slot = 0; slot < (plan.two() ? 2 : 1); ++slot) {
    const int N = layers(element, slot);
    for (int v : direction_of(element, slot).bottom) {
      const int ks[4] = {0, 1, N - 1, N};
      std::array<Eigen::Vector3d, 4> p;
      for (int j = 0; j < 4; ++j) {
        // Vertex v's line (plane) of nodes: along the other split direction it stays at v's place.
        std::array<double, 2> along{corners(v, plan.direction[0]), plan.two() ? corners(v, plan.direction[1]) : 0.0};
        along[slot] = interface_at(slot, corners.row(v), ks[j]);
        p[j] = detail::map_along_line(lines, X, v, along);
      }
      const double first = (p[1] - p[0]).norm(), last = (p[3] - p[2]).norm();
      out.first_heights[slot].push_back(first);
      out.ratios[slot].push_back(N > 1 ? std::pow(last / first, 1.0 / (N - 1)) : 1.0);
    }
  }
  return out;
}

std::array<std::vector<double>, 2> Splitter::uniform_interfaces(std::size_t element) const {
  const Plan& plan = plans_[element];
  std::array<std::vector<double>, 2> uniform;
  for (int slot = 0; slot < (plan.two() ? 2 : 1); ++slot)
    uniform[slot] = layer_interfaces(layers(element, slot), families_[plan.family[slot]].distribution.ratio);
  return uniform;
}

std::vector<ReferenceBox> Splitter::piece_boxes(std::size_t element, const std::array<std::vector<double>, 2>& z) const {
  const Shape shape = in_.elements()[element].shape;
  const Plan& plan = plans_[element];
  const int na = layers(element, 0), nb = layers(element, 1);
  ReferenceBox whole;
  for (int d = 0; d < 3; ++d) whole[d] = {shape == Shape::Prism && d < 2 ? 0.0 : -1.0, 1.0};
  std::vector<ReferenceBox> boxes;
  for (int kb = 0; kb < nb; ++kb)
    for (int ka = 0; ka < na; ++ka) {  // piece kb N_a + ka, as sub_points orders them
      ReferenceBox box = whole;
      box[plan.direction[0]] = {z[0][ka], z[0][ka + 1]};
      if (plan.two()) box[plan.direction[1]] = {z[1][kb], z[1][kb + 1]};
      boxes.push_back(box);
    }
  return boxes;
}

// The key naming a new node so that every element whose split creates it names it alike: on a
// coarse edge across a layer direction by that edge's ends, on a coarse face cut by one direction
// by the face's body-side edge and its partner, on a face cut by both directions (between two
// junction hexes) by three of its corners, inside the element by the element.
NodeKey Splitter::key_of(std::size_t element, const std::vector<NodeId>& coarse, const LatticePoint& l,
                         const std::array<int, 2>& g) const {
  const ShapeData& data = data_of(element);
  const Plan& plan = plans_[element];
  const int P = in_.order();
  std::array<bool, 2> inside{false, false};
  for (int s = 0; s < (plan.two() ? 2 : 1); ++s) inside[s] = g[s] > 0 && g[s] < layers(element, s) * P;
  if (inside[0] && inside[1]) {
    LatticePoint h = l;
    h[plan.direction[0]] = 0, h[plan.direction[1]] = 0;
    const int v = data.index.at(h);
    if (v < num_vertices(data.shape))
      return {4,    coarse[v], coarse[direction_of(element, 0).top_of[v]], coarse[direction_of(element, 1).top_of[v]],
              g[0], g[1], 0, 0};
    return {3, static_cast<std::int64_t>(element), h[0], h[1], h[2], g[0], 1 + g[1], 0};
  }
  const int s = inside[0] ? 0 : 1, d = plan.direction[s];
  LatticePoint h = l;
  h[d] = 0;
  if (plan.two()) h[plan.direction[1 - s]] = g[1 - s] == 0 ? 0 : P;
  const DirectionData& side = direction_of(element, s);
  const mesh::Element& el = in_.elements()[element];
  for (int v : side.bottom)
    if (data.lattice[v][0] == h[0] && data.lattice[v][1] == h[1] && data.lattice[v][2] == h[2])  // no memcmp call
      return {1, coarse[v], coarse[side.top_of[v]], g[s], 0, 0, 0, el.edges[side.across[v]]};  // across the layer
  for (std::size_t k = 0; k < side.bottom_edges.size(); ++k) {
    const auto& e = side.bottom_edges[k];
    const auto place = place_on_segment(data.lattice[e[0]], data.lattice[e[1]], h);
    if (!place) continue;
    int along = (*place)[0];
    const int steps = (*place)[1];
    // On a coarse side face: name the slot from the lower node id so both neighbours agree.
    NodeId va = coarse[e[0]], vb = coarse[e[1]], ta = coarse[side.top_of[e[0]]], tb = coarse[side.top_of[e[1]]];
    if (va > vb) {
      std::swap(va, vb);
      std::swap(ta, tb);
      along = steps - along;
    }
    return {2, va, vb, ta, tb, along, g[s], el.faces[side.side_face[k]]};
  }
  return {3, static_cast<std::int64_t>(element), h[0], h[1], h[2], g[s], plan.two() ? -1 - s : 0, 0};
}

void Splitter::split_element_by_keys(std::size_t element, const SplitGeometry& geometry) {
  const ShapeData& data = data_of(element);
  const Plan& plan = plans_[element];
  const int P = in_.order(), na = layers(element, 0), nb = layers(element, 1);
  in_.element_nodes(element, coarse_);
  const std::vector<NodeId>& coarse = coarse_;
  const int nn = static_cast<int>(coarse.size());
  const Eigen::MatrixX3d& x = geometry.x;
  element_nodes_.next_element();  // the last element's inner nodes: no other element names them

  std::vector<std::vector<NodeId>>& subs = pieces_;
  subs.resize(static_cast<std::size_t>(na) * nb);
  for (std::vector<NodeId>& piece : subs) piece.resize(nn);
  for (int kb = 0; kb < nb; ++kb)
    for (int ka = 0; ka < na; ++ka)
      for (int i = 0; i < nn; ++i) {
        const LatticePoint& l = data.lattice[i];
        // lattice coordinates along the split directions, refined N times
        const std::array<int, 2> g{ka * P + l[plan.direction[0]], plan.two() ? kb * P + l[plan.direction[1]] : 0};
        const bool end_a = g[0] == 0 || g[0] == na * P, end_b = !plan.two() || g[1] == 0 || g[1] == nb * P;
        const int piece = kb * na + ka;
        if (end_a && end_b) {
          LatticePoint c = l;
          c[plan.direction[0]] = g[0] == 0 ? 0 : P;
          if (plan.two()) c[plan.direction[1]] = g[1] == 0 ? 0 : P;
          subs[piece][i] = coarse[data.index.at(c)];
          continue;
        }
        subs[piece][i] = node_for(key_of(element, coarse, l, g), x.row(piece * nn + i).transpose());
      }
  add_figures(element, geometry);
}

SubNode Splitter::describe(const ShapeData& data, const Plan& plan, int na, int nb, const LatticePoint& l,
                           const std::array<int, 2>& g) {
  const int P = in_.order();
  SubNode node;
  const bool end_a = g[0] == 0 || g[0] == na * P, end_b = !plan.two() || g[1] == 0 || g[1] == nb * P;
  if (end_a && end_b) {
    LatticePoint c = l;
    c[plan.direction[0]] = g[0] == 0 ? 0 : P;
    if (plan.two()) c[plan.direction[1]] = g[1] == 0 ? 0 : P;
    node.local = data.index.at(c);
    return node;
  }
  // As key_of, kind by kind.
  const std::array<int, 2> layer_count{na, nb};
  std::array<bool, 2> inside{false, false};
  for (int s = 0; s < (plan.two() ? 2 : 1); ++s) inside[s] = g[s] > 0 && g[s] < layer_count[s] * P;
  if (inside[0] && inside[1]) {
    LatticePoint h = l;
    h[plan.direction[0]] = 0, h[plan.direction[1]] = 0;
    node.kind = data.index.at(h) < num_vertices(data.shape) ? SubNode::Kind::Keyed : SubNode::Kind::Inside;
    node.point = l, node.g = g;
    return node;
  }
  const int s = inside[0] ? 0 : 1, d = plan.direction[s];
  LatticePoint h = l;
  h[d] = 0;
  if (plan.two()) h[plan.direction[1 - s]] = g[1 - s] == 0 ? 0 : P;
  const DirectionData& side = data.directions.at(plan.direction[s]);
  node.level = g[s];
  for (int v : side.bottom)
    if (data.lattice[v] == h) {
      node.kind = SubNode::Kind::Edge;
      node.local = side.across[v];
      return node;
    }
  for (std::size_t k = 0; k < side.bottom_edges.size(); ++k) {
    const auto& e = side.bottom_edges[k];
    const auto place = place_on_segment(data.lattice[e[0]], data.lattice[e[1]], h);
    if (!place) continue;
    node.kind = SubNode::Kind::Face;
    node.local = side.side_face[k];
    node.a = e[0], node.b = e[1], node.along = (*place)[0], node.steps = (*place)[1];
    return node;
  }
  node.kind = SubNode::Kind::Inside;
  return node;
}

const SplitRecipe& Splitter::recipe_of(std::size_t element) {
  const Plan& plan = plans_[element];
  const int na = layers(element, 0), nb = layers(element, 1);
  const Shape shape = in_.elements()[element].shape;
  const auto key = std::make_tuple(shape, plan.direction[0], plan.direction[1], na, nb);
  if (const auto it = recipes_.find(key); it != recipes_.end()) return it->second;
  const ShapeData& data = data_of(element);
  const int P = in_.order(), nn = static_cast<int>(data.lattice.size());
  SplitRecipe recipe;
  // A node is the same wherever its point of the lattice refined along the split directions is.
  std::map<LatticePoint, std::uint32_t> seen;
  recipe.node_of.resize(static_cast<std::size_t>(na) * nb * nn);
  for (int kb = 0; kb < nb; ++kb)
    for (int ka = 0; ka < na; ++ka)
      for (int i = 0; i < nn; ++i) {
        const LatticePoint& l = data.lattice[i];
        const std::array<int, 2> g{ka * P + l[plan.direction[0]], plan.two() ? kb * P + l[plan.direction[1]] : 0};
        LatticePoint refined = l;
        refined[plan.direction[0]] = g[0];
        if (plan.two()) refined[plan.direction[1]] = g[1];
        const int row = (kb * na + ka) * nn + i;
        const auto [it, added] = seen.try_emplace(refined, static_cast<std::uint32_t>(recipe.nodes.size()));
        if (added) {
          SubNode node = describe(data, plan, na, nb, l, g);
          node.first_row = row;
          recipe.nodes.push_back(node);
        }
        recipe.node_of[row] = it->second;
      }
  return recipes_.emplace(key, std::move(recipe)).first->second;
}

void Splitter::split_element(std::size_t element, const SplitGeometry& geometry) {
  if (by_keys_) return split_element_by_keys(element, geometry);
  const SplitRecipe& recipe = recipe_of(element);
  const mesh::Element& el = in_.elements()[element];
  const int na = layers(element, 0), nb = layers(element, 1);
  in_.element_nodes(element, coarse_);
  const std::vector<NodeId>& coarse = coarse_;
  const int nn = static_cast<int>(coarse.size());
  const Eigen::MatrixX3d& x = geometry.x;
  // Each distinct node once, in the order key_of's reference names them (so the same ids).
  recipe_ids_.resize(recipe.nodes.size());
  const auto made = [&](NodeId& slot, int row) -> NodeId {
    if (slot == mesh::kNoNode) slot = out_.add_node(x.row(row).transpose());
    return slot;
  };
  for (std::size_t k = 0; k < recipe.nodes.size(); ++k) {
    const SubNode& node = recipe.nodes[k];
    NodeId& id = recipe_ids_[k];
    switch (node.kind) {
      case SubNode::Kind::Coarse: id = coarse[node.local]; break;
      case SubNode::Kind::Edge: {  // slot_of reads a coarse edge's or face's key by its id and place only
        NodeKey key{1, 0, 0, node.level, 0, 0, 0, el.edges[node.local]};
        id = made(slot_of(key), node.first_row);
        break;
      }
      case SubNode::Kind::Face: {
        // Named from the lower node id of the bottom edge, so both neighbours agree (key_of).
        const int along = coarse[node.a] > coarse[node.b] ? node.steps - node.along : node.along;
        NodeKey key{2, 0, 0, 0, 0, along, node.level, el.faces[node.local]};
        id = made(slot_of(key), node.first_row);
        break;
      }
      case SubNode::Kind::Inside: id = out_.add_node(x.row(node.first_row).transpose()); break;
      case SubNode::Kind::Keyed:
        id = node_for(key_of(element, coarse, node.point, node.g), x.row(node.first_row).transpose());
        break;
    }
  }
  std::vector<std::vector<NodeId>>& subs = pieces_;
  subs.resize(static_cast<std::size_t>(na) * nb);
  for (std::size_t piece = 0; piece < subs.size(); ++piece) {
    subs[piece].resize(nn);
    const std::uint32_t* of = recipe.node_of.data() + piece * nn;
    for (int i = 0; i < nn; ++i) subs[piece][i] = recipe_ids_[of[i]];
  }
  add_figures(element, geometry);
}

void Splitter::add_figures(std::size_t element, const SplitGeometry& geometry) {
  const Plan& plan = plans_[element];
  for (int slot = 0; slot < (plan.two() ? 2 : 1); ++slot) {
    Figures& f = stats_[plan.family[slot]];
    for (std::size_t j = 0; j < geometry.first_heights[slot].size(); ++j) {
      f.height_min = std::min(f.height_min, geometry.first_heights[slot][j]);
      f.height_max = std::max(f.height_max, geometry.first_heights[slot][j]);
      f.ratio_sum += geometry.ratios[slot][j];
      ++f.vertical_edges;
    }
    ++f.elements;
  }
}

FaceCuts Splitter::cuts(std::size_t element, std::uint32_t face) const {
  FaceCuts result;
  const mesh::Element& el = in_.elements()[element];
  const Plan& plan = plans_[element];
  if (!plan.split()) return result;
  const ShapeData& data = data_of(element);
  for (std::size_t f = 0; f < faces(el.shape).size(); ++f) {
    if (el.faces[f] != face) continue;
    for (int s = 0; s < (plan.two() ? 2 : 1); ++s) {
      FaceCut cut;
      cut.family = plan.family[s];
      int on_bottom = 0;
      for (int v : faces(el.shape)[f])
        if (data.lattice[v][plan.direction[s]] == 0) cut.bottom[on_bottom++] = el.vertices[v];
      if (on_bottom == 0 || on_bottom == static_cast<int>(faces(el.shape)[f].size())) continue;
      // The first on_bottom entries sorted (the unused ones stay kNoNode), by insertion: std::sort on
      // so short a range trips GCC 12's -Warray-bounds.
      for (int i = 1; i < on_bottom; ++i)
        for (int j = i; j > 0 && cut.bottom[j] < cut.bottom[j - 1]; --j) std::swap(cut.bottom[j], cut.bottom[j - 1]);
      result.add(cut);
    }
  }
  result.sort();
  return result;
}

void Splitter::check_side_faces(const std::vector<LayerSplit>& split) {
  // Elements using each face (at most two in a conforming mesh).
  constexpr std::uint32_t kNone = 0xffffffffu;
  std::vector<std::array<std::uint32_t, 2>> users(in_.faces().size(), {kNone, kNone});
  for (std::size_t e = 0; e < in_.elements().size(); ++e) {
    const mesh::Element& el = in_.elements()[e];
    for (std::size_t f = 0; f < faces(el.shape).size(); ++f) {
      auto& u = users[el.faces[f]];
      (u[0] == kNone ? u[0] : u[1]) = static_cast<std::uint32_t>(e);
    }
  }
  // The entries on all cores: the error thrown is the first entry's, as in order.
  detail::parallel_for(split.size(), true, [&](std::size_t j) {
    const LayerSplit& s = split[j];
    const mesh::Element& el = in_.elements()[s.element];
    for (std::size_t f = 0; f < faces(el.shape).size(); ++f) {
      const auto mine = cuts(s.element, el.faces[f]);
      if (mine.empty()) continue;
      const auto& u = users[el.faces[f]];
      const std::uint32_t other = u[0] == s.element ? u[1] : u[0];
      if (other == kNone || cuts(other, el.faces[f]) == mine) continue;
      throw std::invalid_argument(caller_ + ": element " + std::to_string(s.element) + " (" + to_string(el.shape) +
                                  ") is split across its face shared with element " + std::to_string(other) + " (" +
                                  to_string(in_.elements()[other].shape) + "), which is " +
                                  (plans_[other].split() ? "split in another way" : "not split") +
                                  ": the shared face would crack; split both the same way");
    }
  });
}

mesh::Mesh Splitter::run(const std::vector<LayerSplit>& split, std::vector<SplitStats>* stats,
                         std::vector<std::size_t>* first_piece, const ProgressCallback& progress,
                         std::vector<InheritedBounds>* inherited) {
  inherit_ = inherited != nullptr;
  if (inherited) inherited->clear();
  check_families();
  const std::vector<int> position = plan_elements(split);  // also throws for a bad entry
  check_side_faces(split);                                 // before any output: a crack is refused
  if (first_piece) first_piece->assign(in_.elements().size(), 0);
  const std::size_t elements = copy_nodes_groups_and_regions();  // input node ids stay valid in the output
  if (inherited) inherited->reserve(elements);  // an upper bound: the room never filled is never resident
  const std::vector<std::size_t> first_out = add_elements(position, split.size(), first_piece, progress, inherited);
  add_boundary_faces(split, position, first_out);  // the pieces made their faces: these link to them
  if (inherited) fingerprint_pieces(*inherited);
  if (stats) *stats = split_stats();
  return std::move(out_);
}

std::vector<PieceBoundsAhead::Entry> Splitter::bounds_ahead(const std::vector<LayerSplit>& split,
                                                           const std::atomic<bool>& stop) {
  check_families();
  std::vector<LayerSplit> here;  // the entries of elements this mesh has
  for (const LayerSplit& entry : split)
    if (entry.element < in_.elements().size()) here.push_back(entry);
  const std::vector<int> position = plan_elements(here);
  const detail::OneThreadScope one_thread;  // beside another process, on the core it leaves idle
  std::vector<PieceBoundsAhead::Entry> entries;
  for (std::size_t e = 0; e < in_.elements().size() && !stop.load(std::memory_order_relaxed); ++e) {
    if (position[e] < 0) continue;
    const VertexInterfaces z = interfaces_of(e, in_);
    if (!z[0].empty() || !z[1].empty()) continue;  // interfaces that vary: no bounds to inherit
    const Shape shape = in_.elements()[e].shape;
    const Eigen::MatrixX3d x = in_.element_coordinates(e);
    const std::vector<ReferenceBox> boxes = piece_boxes(e, uniform_interfaces(e));
    entries.push_back({e, pieces_fingerprint(shape, in_.order(), in_.node_set(), x, boxes),
                       certify_pieces(shape, in_.order(), in_.node_set(), x, boxes)});
  }
  return entries;
}

void Splitter::check_families() const {
  if (families_.empty()) throw std::invalid_argument(caller_ + ": no layer distribution given");
  for (std::size_t f = 0; f < families_.size(); ++f) {
    const LayerDistribution& d = families_[f].distribution;
    if (d.layers < 1)
      throw std::invalid_argument(caller_ + ": LayerDistribution::layers = " + std::to_string(d.layers) +
                                  " must be >= 1");
    if (!families_[f].ratio) ratio_at(Eigen::Vector3d::Zero(), 0, static_cast<int>(f));  // checks the constant ratio
  }
}

void Splitter::check_split_entry(const LayerSplit& entry) const {
  const std::size_t e = entry.element;
  if (e >= in_.elements().size())
    throw std::invalid_argument(caller_ + ": element index " + std::to_string(e) + " out of range (mesh has " +
                                std::to_string(in_.elements().size()) + " elements)");
  const Shape s = in_.elements()[e].shape;
  const auto& dir = entry.direction;
  for (int slot = 0; slot < 2; ++slot) {
    if (slot == 1 && dir[1] < 0) break;
    if (dir[slot] < 0 || dir[slot] > 2)
      throw std::invalid_argument(caller_ + ": direction " + std::to_string(dir[slot]) + " of element " +
                                  std::to_string(e) + " must be 0 (xi), 1 (eta) or 2 (zeta)");
    if (s != Shape::Hexahedron && !(s == Shape::Prism && dir[slot] == 2 && slot == 0))
      throw std::invalid_argument(caller_ + ": element " + std::to_string(e) + " is a " + to_string(s) +
                                  (dir[slot] == 2 && slot == 0 ? "; only prisms and hexahedra" : "; only hexahedra") +
                                  " can be split in this direction");
    const int family = entry.family[slot];
    if (family < 0 || family >= static_cast<int>(families_.size()))
      throw std::invalid_argument(caller_ + ": family " + std::to_string(family) + " of element " + std::to_string(e) +
                                  " is not one of the " + std::to_string(families_.size()) + " given");
  }
  if (dir[1] == dir[0])
    throw std::invalid_argument(caller_ + ": element " + std::to_string(e) + " lists direction " +
                                std::to_string(dir[0]) + " twice");
}

std::vector<int> Splitter::plan_elements(const std::vector<LayerSplit>& split) {
  plans_.assign(in_.elements().size(), Plan{});
  std::vector<int> position(in_.elements().size(), -1);
  for (std::size_t j = 0; j < split.size(); ++j) {
    check_split_entry(split[j]);
    const std::size_t e = split[j].element;
    if (position[e] >= 0) throw std::invalid_argument(caller_ + ": element " + std::to_string(e) + " is listed twice");
    position[e] = static_cast<int>(j);
    plans_[e] = {split[j].direction, split[j].family};
    const Shape s = in_.elements()[e].shape;
    for (int slot = 0; slot < (plans_[e].two() ? 2 : 1); ++slot) direction_data(s, plans_[e].direction[slot]);
    ShapeData& data = shape_data(s);
    if (!data.lines.count(plans_[e].direction))
      data.lines.emplace(plans_[e].direction,
                         detail::lattice_lines(s, in_.order(), in_.node_set(), plans_[e].direction));
    uniform_values(s, plans_[e]);  // also for a ratio field: elements where it is constant use them
  }
  return position;
}

std::size_t Splitter::copy_nodes_groups_and_regions() {
  // An edge across the layers has its nodes at levels below layers * P; a side face also at
  // places 1..P-1 along its bottom edge (slot level * P + place).
  int most_layers = 1;
  for (const SplitFamily& f : families_) most_layers = std::max(most_layers, f.distribution.layers);
  edge_block_size_ = static_cast<std::size_t>(most_layers) * in_.order();
  face_block_size_ = edge_block_size_ * in_.order();
  edge_block_.assign(in_.edges().size(), kNoBlock);
  face_block_.assign(in_.faces().size(), kNoBlock);
  // Room for every node the pieces could make: grown by doubling, the node array would be resident
  // twice at its last growth (the room never used is never touched, so never resident).
  std::size_t nodes = in_.num_nodes(), elements = in_.elements().size();
  for (std::size_t e = 0; e < in_.elements().size(); ++e) {
    if (!plans_[e].split()) continue;
    const std::size_t pieces = static_cast<std::size_t>(layers(e, 0)) * layers(e, 1);
    nodes += pieces * static_cast<std::size_t>(num_nodes(in_.elements()[e].shape, in_.order()));
    elements += pieces - 1;
  }
  nodes_bound_ = nodes;
  if (!in_.elements().empty()) out_.reserve(in_.elements().front().shape, elements);
  // The pieces' entities, sized ahead (a lookup that grows rehashes every key it holds): about 2.5
  // edges and 3 faces more per new element than the coarse mesh has (the paper's H-type case gains
  // 2.2 and 2.6, its O-type 2.0 and 2.5).
  const std::size_t new_elements = elements - in_.elements().size();
  if (adopt_) out_.adopt_all_entities(in_, give_nodes_);  // a mesh given up gives its lookups too
  out_.reserve_lookups(in_.edges().size() + 5 * new_elements / 2, in_.faces().size() + 3 * new_elements);
  if (give_nodes_) {
    give_nodes_->reserve_nodes(nodes);
    out_.take_nodes(*give_nodes_);
  } else {
    out_.reserve_nodes(nodes);
    for (NodeId id = 0; id < in_.num_nodes(); ++id) out_.add_node(in_.node(id), in_.cad_attachment(id));
  }
  for (const std::string& g : in_.group_names()) out_.group_index(g);
  out_.copy_regions_from(in_);
  return elements;
}

// Blocks of split elements in mesh order: interfaces (user ratio field) serially, the sub-element
// nodes' positions (the costly part) in parallel, then node creation and elements serially in a
// fixed order, so the output does not depend on the thread count.
std::vector<std::size_t> Splitter::add_elements(const std::vector<int>& position, std::size_t split_count,
                                                std::vector<std::size_t>* first_piece, const ProgressCallback& progress,
                                                std::vector<InheritedBounds>* inherited) {
  std::vector<std::size_t> ascending;
  for (std::size_t e = 0; e < in_.elements().size(); ++e)
    if (position[e] >= 0) ascending.push_back(e);
  std::vector<std::size_t> first_out(split_count);
  std::size_t next = 0;  // next input element to emit
  // One block's pieces are made (serially) while the next block's nodes are placed: place_sub_nodes
  // reads the input, the caches made by plan_elements and the coarse nodes of the output, which
  // split_element appends to without reallocating (copy_nodes_groups_and_regions reserved room for
  // every node). The ratio field is called serially, a block ahead (prepare).
  if (out_.nodes().capacity() < nodes_bound_) throw std::logic_error(caller_ + ": the output's nodes are not reserved");
  std::vector<VertexInterfaces> interfaces;  // of the block being placed
  std::size_t interfaces_first = 0;
  detail::overlapped_blocks(
      ascending.size(), true, kSplitBlock,
      [&](std::size_t first, std::size_t count) {
        interfaces.resize(count);
        for (std::size_t k = 0; k < count; ++k) interfaces[k] = interfaces_of(ascending[first + k], out_);
        interfaces_first = first;
      },
      [&](std::size_t i) { return place_sub_nodes(ascending[i], interfaces[i - interfaces_first]); },
      [&](std::size_t i, const SplitGeometry& geometry) {
        const std::size_t e = ascending[i];
        // Never reallocate under the threads reading the nodes: at most a node per row of x is new.
        if (out_.num_nodes() + static_cast<std::size_t>(geometry.x.rows()) > out_.nodes().capacity())
          throw std::logic_error(caller_ + ": no room left for the nodes of element " + std::to_string(e));
        copy_elements(next, e, first_piece);
        split_element(e, geometry);
        first_out[position[e]] = out_.elements().size();
        if (first_piece) (*first_piece)[e] = out_.elements().size();
        add_pieces(e, pieces_, geometry.bounds, inherited);
        next = e + 1;
      },
      progress, "elements");
  copy_elements(next, in_.elements().size(), first_piece);
  return first_out;
}

void Splitter::copy_elements(std::size_t from, std::size_t end, std::vector<std::size_t>* first_piece) {
  if (first_piece)
    for (std::size_t e = from; e < end; ++e) (*first_piece)[e] = out_.elements().size() + (e - from);
  if (adopt_)
    out_.add_elements_as_in(in_, from, end);
  else
    out_.add_elements_of(in_, from, end);
}

void Splitter::add_pieces(std::size_t element, const std::vector<std::vector<NodeId>>& pieces,
                          const std::vector<std::optional<JacobianBounds>>& bounds,
                          std::vector<InheritedBounds>* inherited) {
  for (std::size_t piece = 0; piece < pieces.size(); ++piece) {
    out_.add_element(in_.elements()[element].shape, pieces[piece], in_.elements()[element].region);
    if (!inherited || piece >= bounds.size() || !bounds[piece]) continue;
    inherited->push_back({out_.elements().size() - 1, 0, *bounds[piece]});  // fingerprinted at the end
  }
}

// The fingerprint of each piece as made, on all cores once the split is done (its nodes no longer
// move: the serial pass that makes the pieces had computed them one by one). Its shared nodes may
// come from a neighbour's evaluation of the same point (the same up to rounding, which kPieceMargin
// covers).
void Splitter::fingerprint_pieces(std::vector<InheritedBounds>& inherited) const {
  detail::parallel_for(inherited.size(), true, [&](std::size_t i) {
    inherited[i].fingerprint = element_fingerprint(out_, inherited[i].element);
  });
}

// Boundary faces: split with the element whose face they are when its split cuts them (each
// piece lying on the face gives one), copied otherwise.
void Splitter::add_boundary_faces(const std::vector<LayerSplit>& split, const std::vector<int>& position,
                                  const std::vector<std::size_t>& first_out) {
  // (input face id, split element) of every cut face, sorted by face (stable: of a face cut by two
  // elements, the later in `split` comes last and owns it). The split's peak memory is reached
  // here: a list of the cut faces, not an entry for every face of the mesh.
  std::vector<std::pair<std::uint32_t, std::size_t>> cut_faces;
  for (const LayerSplit& s : split) {
    const mesh::Element& el = in_.elements()[s.element];
    for (std::size_t f = 0; f < faces(el.shape).size(); ++f)
      if (!cuts(s.element, el.faces[f]).empty()) cut_faces.emplace_back(el.faces[f], s.element);
  }
  std::stable_sort(cut_faces.begin(), cut_faces.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t b = 0; b < in_.boundary_faces().size(); ++b) {
    const mesh::BoundaryFace& bf = in_.boundary_faces()[b];
    const std::string& group = in_.group_names()[bf.group];
    const auto after = std::upper_bound(cut_faces.begin(), cut_faces.end(), bf.face,
                                        [](std::uint32_t face, const auto& c) { return face < c.first; });
    if (after == cut_faces.begin() || std::prev(after)->first != bf.face) {
      out_.add_boundary_face(group, bf.shape, in_.boundary_face_nodes(b));
      continue;
    }
    const std::size_t e = std::prev(after)->second;
    const mesh::Element& el = in_.elements()[e];
    std::vector<int> local(num_vertices(bf.shape));
    for (std::size_t j = 0; j < local.size(); ++j)
      local[j] =
          static_cast<int>(std::find(el.vertices.begin(), el.vertices.end(), bf.vertices[j]) - el.vertices.begin());
    const std::size_t count = static_cast<std::size_t>(layers(e, 0)) * layers(e, 1);
    std::vector<NodeId> nodes;
    for (std::size_t piece = 0; piece < count; ++piece)
      if (piece_on_face(e, piece, local)) {
        out_.element_nodes(first_out[position[e]] + piece, nodes);
        out_.add_boundary_face(group, bf.shape, detail::face_nodes_of_element(el.shape, in_.order(), nodes, local));
      }
  }
}

// A piece lies on the face unless the face is at one end of a split direction and the piece is
// not the one at that end.
bool Splitter::piece_on_face(std::size_t element, std::size_t piece, const std::vector<int>& local) const {
  const ShapeData& data = data_of(element);
  const Plan& plan = plans_[element];
  const int na = layers(element, 0);
  const std::array<int, 2> k{static_cast<int>(piece) % na, static_cast<int>(piece) / na};
  bool on_face = true;
  for (int s = 0; s < (plan.two() ? 2 : 1) && on_face; ++s) {
    const int d = plan.direction[s];
    const bool all_low = std::all_of(local.begin(), local.end(), [&](int v) { return data.lattice[v][d] == 0; });
    const bool all_high = std::all_of(local.begin(), local.end(), [&](int v) { return data.lattice[v][d] != 0; });
    if (all_low) on_face = k[s] == 0;
    if (all_high) on_face = k[s] == layers(element, s) - 1;
  }
  return on_face;
}

std::vector<SplitStats> Splitter::split_stats() const {
  std::vector<SplitStats> stats(families_.size());
  for (std::size_t f = 0; f < families_.size(); ++f) {
    SplitStats& s = stats[f];
    const Figures& figures = stats_[f];
    s.elements_in = static_cast<int>(in_.elements().size());
    s.elements_out = static_cast<int>(out_.elements().size());
    s.first_cell_height_min = figures.vertical_edges ? figures.height_min : 0.0;
    s.first_cell_height_max = figures.height_max;
    s.achieved_ratio = figures.vertical_edges ? figures.ratio_sum / figures.vertical_edges : 1.0;
  }
  return stats;
}

}  // namespace

mesh::Mesh split_layers(const mesh::Mesh& mesh, const std::vector<LayerSplit>& split,
                        const std::vector<SplitFamily>& families, std::vector<SplitStats>* stats,
                        std::vector<std::size_t>* first_piece, const ProgressCallback& progress,
                        std::vector<InheritedBounds>* inherited) {
  return Splitter(mesh, families, "split_layers").run(split, stats, first_piece, progress, inherited);
}

mesh::Mesh split_layers(mesh::Mesh&& mesh, const std::vector<LayerSplit>& split,
                        const std::vector<SplitFamily>& families, std::vector<SplitStats>* stats,
                        std::vector<std::size_t>* first_piece, const ProgressCallback& progress,
                        std::vector<InheritedBounds>* inherited, SplitEntities entities,
                        const PieceBoundsAhead* ahead) {
  Splitter splitter(mesh, families, "split_layers", &mesh, entities);
  splitter.take_bounds_from(ahead);
  return splitter.run(split, stats, first_piece, progress, inherited);
}

PieceBoundsAhead::PieceBoundsAhead(std::vector<Entry> entries) : entries_(std::move(entries)) {
  for (std::size_t i = 1; i < entries_.size(); ++i)
    if (entries_[i].element <= entries_[i - 1].element)
      throw std::invalid_argument("PieceBoundsAhead: entries not in ascending element order at element " +
                                  std::to_string(entries_[i].element));
}

const std::vector<std::optional<JacobianBounds>>* PieceBoundsAhead::find(std::size_t element,
                                                                        std::uint64_t fingerprint) const {
  const auto it = std::lower_bound(entries_.begin(), entries_.end(), element,
                                   [](const Entry& entry, std::size_t e) { return entry.element < e; });
  return it != entries_.end() && it->element == element && it->fingerprint == fingerprint ? &it->bounds : nullptr;
}

PieceBoundsAhead piece_bounds_ahead(const mesh::Mesh& mesh, const std::vector<LayerSplit>& split,
                                    const std::vector<SplitFamily>& families, const std::atomic<bool>& stop) {
  return PieceBoundsAhead(Splitter(mesh, families, "piece_bounds_ahead").bounds_ahead(split, stop));
}

namespace detail {

mesh::Mesh split_layers_by_keys(const mesh::Mesh& mesh, const std::vector<LayerSplit>& split,
                                const std::vector<SplitFamily>& families, std::vector<InheritedBounds>* inherited) {
  Splitter splitter(mesh, families, "split_layers");
  splitter.name_nodes_by_keys();
  return splitter.run(split, nullptr, nullptr, {}, inherited);
}

}  // namespace detail

mesh::Mesh split_layers(const mesh::Mesh& mesh, const std::vector<std::size_t>& layer_elements,
                        const LayerDistribution& distribution, const RatioField& ratio, SplitStats* stats) {
  std::vector<LayerSplit> split;
  split.reserve(layer_elements.size());
  for (std::size_t e : layer_elements) split.push_back({e, {2, -1}, {0, 0}});
  std::vector<SplitStats> per_family;
  mesh::Mesh out = Splitter(mesh, {{distribution, ratio}}, "split_layers").run(split, &per_family, nullptr);
  if (stats) *stats = per_family.front();
  return out;
}

mesh::Mesh split_hex_direction(const mesh::Mesh& mesh, const std::vector<std::size_t>& hexes, int direction,
                               const LayerDistribution& distribution, SplitStats* stats) {
  if (direction < 0 || direction > 2)
    throw std::invalid_argument("split_hex_direction: direction " + std::to_string(direction) +
                                " must be 0 (xi), 1 (eta) or 2 (zeta)");
  std::vector<LayerSplit> split;
  for (std::size_t e : hexes) split.push_back({e, {direction, -1}, {0, 0}});
  std::vector<SplitStats> per_family;
  mesh::Mesh out = Splitter(mesh, {{distribution, {}}}, "split_hex_direction").run(split, &per_family, nullptr);
  if (stats) *stats = per_family.front();
  return out;
}

}  // namespace semimesh::ho
