#include "semimesh/io/equispaced.hpp"

#include "semimesh/ho/basis.hpp"
#include "semimesh/mesh/node_layout.hpp"

#include <algorithm>
#include <atomic>
#include <map>
#include <future>
#include <numeric>
#include <thread>

namespace semimesh::io {
namespace {

Eigen::MatrixXd resampling(ho::Shape shape, int order, ho::NodeSet from, ho::NodeSet to) {
  return ho::interpolation_matrix(ho::LagrangeBasis(shape, order, from), ho::LagrangeBasis(shape, order, to));
}

/// The rows of the resampling matrix for the nodes an entity owns, and which canonical positions
/// they are: a face's or an element's positions of kind `owned` in its node layout.
struct OwnedRows {
  std::vector<int> positions;
  Eigen::MatrixXd rows;  // (positions, num_nodes)
};

OwnedRows owned_rows(ho::Shape shape, int order, ho::NodeSet from, ho::NodeSet to, mesh::NodeSlot::Kind owned) {
  const Eigen::MatrixXd m = resampling(shape, order, from, to);
  OwnedRows r;
  const auto& slots = mesh::node_layout(shape, order).slots;
  for (std::size_t i = 0; i < slots.size(); ++i)
    if (slots[i].kind == owned) r.positions.push_back(static_cast<int>(i));
  r.rows.resize(r.positions.size(), m.cols());
  for (std::size_t k = 0; k < r.positions.size(); ++k) r.rows.row(k) = m.row(r.positions[k]);
  return r;
}

/// Edges: Mesh::edge_nodes lists the nodes by position along the edge, the canonical segment
/// order does not; so the matrix is re-indexed by the nodes' order along the reference segment.
Eigen::MatrixXd edge_resampling(int order, ho::NodeSet from, ho::NodeSet to) {
  const Eigen::MatrixXd m = resampling(ho::Shape::Segment, order, from, to);
  const Eigen::MatrixX3d ref = ho::reference_nodes(ho::Shape::Segment, order, ho::NodeSet::Equispaced);
  std::vector<int> along(ref.rows());
  std::iota(along.begin(), along.end(), 0);
  std::sort(along.begin(), along.end(), [&](int a, int b) { return ref(a, 0) < ref(b, 0); });
  Eigen::MatrixXd out(order - 1, order + 1);  // interior nodes from every node, both along the edge
  for (int i = 1; i < order; ++i)
    for (int j = 0; j <= order; ++j) out(i - 1, j) = m(along[i], along[j]);
  return out;
}

/// Resamples the nodes an entity owns from all its nodes `ids`, in `x` itself: x[ids[positions[k]]]
/// = sum_i rows(k, i) x[ids[i]], every sum taken before any is stored. A plain loop down the
/// (column-major) matrix: the matrices are tiny (at most 27 x 125), where a general matrix product
/// costs more in set-up than in arithmetic. The buffers are reused between calls (one per thread).
struct Resampler {
  std::vector<Eigen::Vector3d>& x;
  std::vector<Eigen::Vector3d> sum;
  std::vector<mesh::NodeId> ids;

  template <typename Ids>
  void operator()(const Eigen::MatrixXd& rows, const std::vector<int>& positions, const Ids& entity_ids) {
    // Every node's position asked for before any is used: they are scattered over the array, and
    // the misses overlap instead of each stalling the sum in turn.
    for (std::size_t i = 0; i < entity_ids.size(); ++i) __builtin_prefetch(x[entity_ids[i]].data());
    sum.assign(positions.size(), Eigen::Vector3d::Zero());
    for (std::size_t i = 0; i < entity_ids.size(); ++i) {
      const Eigen::Vector3d& xi = x[entity_ids[i]];
      const double* column = rows.data() + i * positions.size();
      for (std::size_t k = 0; k < positions.size(); ++k) sum[k] += column[k] * xi;
    }
    for (std::size_t k = 0; k < positions.size(); ++k) x[entity_ids[positions[k]]] = sum[k];
  }
};

/// f(begin, end, resampler) over [0, n) in blocks that the hardware threads take in turn as they
/// finish one (the work is uneven: a mesh's elements with interior nodes come first, its
/// tetrahedra, which have none at order 3, last; halves by index left one thread idle): the
/// entities of one kind own disjoint nodes and read none another entity of that kind owns, so the
/// threads never touch an entry another writes, and the result does not depend on who took what.
template <typename F>
void parallel_ranges(std::size_t n, std::vector<Eigen::Vector3d>& x, F f) {
  constexpr std::size_t kBlock = 4096;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  const std::size_t threads = std::max<std::size_t>(1, std::min<std::size_t>(std::thread::hardware_concurrency(), blocks));
  std::atomic<std::size_t> next{0};
  std::vector<std::future<void>> workers;
  for (std::size_t t = 0; t < threads; ++t)
    workers.push_back(std::async(t == 0 ? std::launch::deferred : std::launch::async, [&] {
      Resampler r{x, {}, {}};
      for (std::size_t b = next++; b < blocks; b = next++) f(b * kBlock, std::min(n, (b + 1) * kBlock), r);
    }));
  for (auto& w : workers) w.get();  // the deferred one runs here; rethrows a worker's exception
}

/// The nodes element interiors own, moved from set `from` to set `to` of their element's map; reads
/// every node of each element, moves none another element reads.
void resample_interiors(const mesh::Mesh& m, std::vector<Eigen::Vector3d>& x, ho::NodeSet from, ho::NodeSet to) {
  std::map<ho::Shape, OwnedRows> interior;
  for (const mesh::Element& el : m.elements())
    if (!interior.count(el.shape)) interior.emplace(el.shape, owned_rows(el.shape, m.order(), from, to, mesh::NodeSlot::Interior));
  parallel_ranges(m.elements().size(), x, [&](std::size_t begin, std::size_t end, Resampler& r) {
    for (std::size_t e = begin; e < end; ++e) {
      const OwnedRows& owned = interior.at(m.elements()[e].shape);
      if (owned.positions.empty()) continue;
      m.element_nodes(e, r.ids);
      r(owned.rows, owned.positions, r.ids);
    }
  });
}

/// The nodes faces own, likewise; reads the faces' vertices and edge nodes, not element interiors.
void resample_faces(const mesh::Mesh& m, std::vector<Eigen::Vector3d>& x, ho::NodeSet from, ho::NodeSet to) {
  const OwnedRows tri = owned_rows(ho::Shape::Triangle, m.order(), from, to, mesh::NodeSlot::Face);
  const OwnedRows quad = owned_rows(ho::Shape::Quadrilateral, m.order(), from, to, mesh::NodeSlot::Face);
  parallel_ranges(m.faces().size(), x, [&](std::size_t begin, std::size_t end, Resampler& r) {
    for (std::size_t f = begin; f < end; ++f) {
      const OwnedRows& owned = m.faces()[f].num_vertices == 3 ? tri : quad;
      if (owned.positions.empty()) continue;
      m.face_nodes(f, r.ids);
      r(owned.rows, owned.positions, r.ids);
    }
  });
}

/// The nodes edges own, likewise; reads the edges' own nodes and vertices only.
void resample_edges(const mesh::Mesh& m, std::vector<Eigen::Vector3d>& x, ho::NodeSet from, ho::NodeSet to) {
  const int p = m.order();
  const Eigen::MatrixXd edge = edge_resampling(p, from, to);
  std::vector<int> edge_positions(p - 1);
  std::iota(edge_positions.begin(), edge_positions.end(), 1);
  parallel_ranges(m.edges().size(), x, [&](std::size_t begin, std::size_t end, Resampler& r) {
    r.ids.resize(p + 1);
    for (std::size_t e = begin; e < end; ++e) {
      const mesh::Edge& edge_entity = m.edges()[e];
      r.ids.front() = edge_entity.vertices[0], r.ids.back() = edge_entity.vertices[1];
      std::copy_n(m.edge_pool().begin() + edge_entity.first_node, p - 1, r.ids.begin() + 1);
      r(edge, edge_positions, r.ids);
    }
  });
}

/// x: [m.num_nodes()] positions at the nodes of set `from` of m's element maps, moved to those of
/// set `to`: element interiors, then faces, then edges, each reading only nodes not yet moved.
void resample_in_place(const mesh::Mesh& m, std::vector<Eigen::Vector3d>& x, ho::NodeSet from, ho::NodeSet to) {
  resample_interiors(m, x, from, to);
  resample_faces(m, x, from, to);
  resample_edges(m, x, from, to);
}

bool needs_resampling(const mesh::Mesh& m) { return m.node_set() != ho::NodeSet::Equispaced && m.order() >= 2; }

}  // namespace

EquispacedNodes::EquispacedNodes(const mesh::Mesh& m) : nodes_(&m.nodes()) {
  if (!needs_resampling(m)) return;
  resampled_ = m.nodes();  // vertices keep their place
  resample_in_place(m, resampled_, m.node_set(), ho::NodeSet::Equispaced);
  nodes_ = &resampled_;
}

EquispacedNodes::EquispacedNodes(mesh::Mesh& m, InPlace) : nodes_(&m.nodes()) {
  if (!needs_resampling(m)) return;
  std::vector<Eigen::Vector3d>& x = m.positions_for_resampling();
  kept_.reserve(m.interior_pool().size());
  for (mesh::NodeId id : m.interior_pool()) kept_.push_back(x[id]);
  resample_in_place(m, x, m.node_set(), ho::NodeSet::Equispaced);
  moved_ = &m;
}

EquispacedNodes::~EquispacedNodes() {
  if (!moved_) return;
  if (leave_resampled_) {
    moved_->relabel_node_set(ho::NodeSet::Equispaced);
    moved_->clear_cad_attachments();
    return;
  }
  // Faces, then edges, resampled back, each reading only nodes not yet moved back; the interiors,
  // which no face or edge reads, get their kept positions.
  std::vector<Eigen::Vector3d>& x = moved_->positions_for_resampling();
  resample_faces(*moved_, x, ho::NodeSet::Equispaced, moved_->node_set());
  resample_edges(*moved_, x, ho::NodeSet::Equispaced, moved_->node_set());
  std::size_t k = 0;
  for (mesh::NodeId id : moved_->interior_pool()) x[id] = kept_[k++];
}

mesh::Mesh to_equispaced(const mesh::Mesh& source) {
  mesh::Mesh out = source;
  if (source.node_set() == ho::NodeSet::Equispaced) return out;
  out.clear_cad_attachments();
  const int order = source.order();
  std::map<ho::Shape, Eigen::MatrixXd> resample;  // (n, n) per shape
  auto matrix = [&](ho::Shape shape) -> const Eigen::MatrixXd& {
    auto it = resample.find(shape);
    if (it == resample.end()) it = resample.emplace(shape, resampling(shape, order, source.node_set(), ho::NodeSet::Equispaced)).first;
    return it->second;
  };
  auto move_nodes = [&](ho::Shape shape, const std::vector<mesh::NodeId>& ids) {
    Eigen::MatrixX3d x(ids.size(), 3);
    for (std::size_t i = 0; i < ids.size(); ++i) x.row(i) = source.node(ids[i]).transpose();
    const Eigen::MatrixX3d y = matrix(shape) * x;
    for (std::size_t i = 0; i < ids.size(); ++i) out.place_node(ids[i], y.row(i).transpose());
  };
  std::vector<mesh::NodeId> ids;
  for (std::size_t b = 0; b < source.boundary_faces().size(); ++b)
    move_nodes(source.boundary_faces()[b].shape, source.boundary_face_nodes(b));
  for (std::size_t e = 0; e < source.elements().size(); ++e) {
    source.element_nodes(e, ids);
    move_nodes(source.elements()[e].shape, ids);
  }
  out.relabel_node_set(ho::NodeSet::Equispaced);
  return out;
}

}  // namespace semimesh::io
