#include "semimesh/io/equispaced.hpp"

#include "semimesh/ho/basis.hpp"
#include "semimesh/mesh/node_layout.hpp"

#include <algorithm>
#include <map>
#include <numeric>

namespace semimesh::io {
namespace {

Eigen::MatrixXd resampling(ho::Shape shape, int order, ho::NodeSet from) {
  return ho::interpolation_matrix(ho::LagrangeBasis(shape, order, from),
                                  ho::LagrangeBasis(shape, order, ho::NodeSet::Equispaced));
}

/// The rows of the resampling matrix for the nodes an entity owns, and which canonical positions
/// they are: a face's or an element's positions of kind `owned` in its node layout.
struct OwnedRows {
  std::vector<int> positions;
  Eigen::MatrixXd rows;  // (positions, num_nodes)
};

OwnedRows owned_rows(ho::Shape shape, int order, ho::NodeSet from, mesh::NodeSlot::Kind owned) {
  const Eigen::MatrixXd m = resampling(shape, order, from);
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
Eigen::MatrixXd edge_resampling(int order, ho::NodeSet from) {
  const Eigen::MatrixXd m = resampling(ho::Shape::Segment, order, from);
  const Eigen::MatrixX3d ref = ho::reference_nodes(ho::Shape::Segment, order, ho::NodeSet::Equispaced);
  std::vector<int> along(ref.rows());
  std::iota(along.begin(), along.end(), 0);
  std::sort(along.begin(), along.end(), [&](int a, int b) { return ref(a, 0) < ref(b, 0); });
  Eigen::MatrixXd out(order - 1, order + 1);  // interior nodes from every node, both along the edge
  for (int i = 1; i < order; ++i)
    for (int j = 0; j <= order; ++j) out(i - 1, j) = m(along[i], along[j]);
  return out;
}

template <typename Ids>
void resample(const Eigen::MatrixXd& rows, const std::vector<int>& positions, const Ids& ids,
              const std::vector<Eigen::Vector3d>& from, std::vector<Eigen::Vector3d>& to) {
  Eigen::MatrixX3d x(ids.size(), 3);
  for (std::size_t i = 0; i < ids.size(); ++i) x.row(i) = from[ids[i]].transpose();
  const Eigen::MatrixX3d y = rows * x;
  for (std::size_t k = 0; k < positions.size(); ++k) to[ids[positions[k]]] = y.row(k).transpose();
}

}  // namespace

EquispacedNodes::EquispacedNodes(const mesh::Mesh& m) : nodes_(&m.nodes()) {
  const int p = m.order();
  if (m.node_set() == ho::NodeSet::Equispaced || p < 2) return;
  const ho::NodeSet set = m.node_set();
  resampled_ = m.nodes();  // vertices keep their place
  const auto& from = m.nodes();

  const Eigen::MatrixXd edge = edge_resampling(p, set);
  std::vector<int> edge_positions(p - 1);
  std::iota(edge_positions.begin(), edge_positions.end(), 1);
  for (std::size_t e = 0; e < m.edges().size(); ++e) resample(edge, edge_positions, m.edge_nodes(e), from, resampled_);

  const OwnedRows tri = owned_rows(ho::Shape::Triangle, p, set, mesh::NodeSlot::Face);
  const OwnedRows quad = owned_rows(ho::Shape::Quadrilateral, p, set, mesh::NodeSlot::Face);
  for (std::size_t f = 0; f < m.faces().size(); ++f) {
    const OwnedRows& r = m.faces()[f].num_vertices == 3 ? tri : quad;
    if (!r.positions.empty()) resample(r.rows, r.positions, m.face_nodes(f), from, resampled_);
  }

  std::map<ho::Shape, OwnedRows> interior;
  std::vector<mesh::NodeId> ids;
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    const ho::Shape shape = m.elements()[e].shape;
    if (mesh::node_layout(shape, p).num_interior == 0) continue;
    auto it = interior.find(shape);
    if (it == interior.end()) it = interior.emplace(shape, owned_rows(shape, p, set, mesh::NodeSlot::Interior)).first;
    m.element_nodes(e, ids);
    resample(it->second.rows, it->second.positions, ids, from, resampled_);
  }
  nodes_ = &resampled_;
}

mesh::Mesh to_equispaced(const mesh::Mesh& source) {
  mesh::Mesh out = source;
  if (source.node_set() == ho::NodeSet::Equispaced) return out;
  out.clear_cad_attachments();
  const int order = source.order();
  std::map<ho::Shape, Eigen::MatrixXd> resample;  // (n, n) per shape
  auto matrix = [&](ho::Shape shape) -> const Eigen::MatrixXd& {
    auto it = resample.find(shape);
    if (it == resample.end()) it = resample.emplace(shape, resampling(shape, order, source.node_set())).first;
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
