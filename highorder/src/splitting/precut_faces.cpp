#include "semimesh/ho/splitting/precut_faces.hpp"

#include "semimesh/ho/basis.hpp"
#include "semimesh/ho/curving/extend_inward.hpp"
#include "semimesh/mesh/node_layout.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

namespace semimesh::ho {
namespace {

using mesh::NodeId;
// Node id -> how far it moves; zero for a strip node that stays (within tolerance), so nothing
// recomputes it.
using Displacements = std::map<NodeId, Eigen::Vector3d>;

std::string nodes_label(const std::vector<NodeId>& nodes) {
  std::string s;
  for (NodeId v : nodes) s += (s.empty() ? "" : " ") + std::to_string(v);
  return s;
}

std::size_t quad_face(const mesh::Mesh& m, const std::vector<NodeId>& corners, const char* what) {
  const long f = m.find_face(corners);
  if (f < 0 || m.faces()[f].num_vertices != 4)
    throw std::invalid_argument(std::string("follow_precut_faces: the ") + what + " with corners " +
                                nodes_label(corners) + " is not a quad face of the mesh");
  return static_cast<std::size_t>(f);
}

// Row k of the reference vertices of the quad whose stored vertex k is v.
Eigen::Vector3d corner_reference(const mesh::Mesh& m, std::size_t face, NodeId v) {
  const mesh::Face& f = m.faces()[face];
  const int k = static_cast<int>(std::find(f.vertices.begin(), f.vertices.begin() + 4, v) - f.vertices.begin());
  return reference_vertices(Shape::Quadrilateral).row(k).transpose();
}

// The precut face's map F(s, t): s from a0 towards a1, t from a0 towards b0, both in [0, 1].
class FaceMap {
 public:
  FaceMap(const mesh::Mesh& m, const PrecutFace& p)
      : basis_(Shape::Quadrilateral, m.order(), m.node_set()) {
    const std::size_t f = quad_face(m, {p.low.front(), p.low.back(), p.high.back(), p.high.front()}, "precut face");
    const std::vector<NodeId> ids = m.face_nodes(f);
    x_.resize(static_cast<Eigen::Index>(ids.size()), 3);
    for (std::size_t k = 0; k < ids.size(); ++k) x_.row(static_cast<Eigen::Index>(k)) = m.node(ids[k]).transpose();
    origin_ = corner_reference(m, f, p.low.front());
    ds_ = corner_reference(m, f, p.low.back()) - origin_;
    dt_ = corner_reference(m, f, p.high.front()) - origin_;
  }

  /// Points (rows) of F at the rows (s, t) of st.
  Eigen::MatrixXd at(const Eigen::MatrixX2d& st) const {
    Eigen::MatrixX3d xi(st.rows(), 3);
    for (Eigen::Index r = 0; r < st.rows(); ++r)
      xi.row(r) = (origin_ + st(r, 0) * ds_ + st(r, 1) * dt_).transpose();
    return basis_.values(xi) * x_;
  }

 private:
  LagrangeBasis basis_;
  Eigen::MatrixXd x_;
  Eigen::Vector3d origin_, ds_, dt_;
};

// Where every node of strip k (low[k] low[k+1] high[k+1] high[k]) goes on F, by node id: each
// node's (s, t) bilinear in its strip's corners (the strip is a rectangle of (s, t)).
void strip_targets(const mesh::Mesh& m, const PrecutFace& p, const FaceMap& map, std::size_t k,
                   std::map<NodeId, Eigen::Vector3d>& out) {
  const std::size_t f = quad_face(m, {p.low[k], p.low[k + 1], p.high[k + 1], p.high[k]}, "strip");
  Eigen::Matrix<double, 4, 2> corners;
  for (int v = 0; v < 4; ++v) {
    const NodeId w = m.faces()[f].vertices[v];
    const bool next = w == p.low[k + 1] || w == p.high[k + 1], high = w == p.high[k] || w == p.high[k + 1];
    corners.row(v) << p.fractions[next ? k + 1 : k], high ? 1.0 : 0.0;
  }
  const Eigen::MatrixX3d ref = reference_nodes(Shape::Quadrilateral, m.order(), m.node_set());
  const Eigen::MatrixX2d st = LagrangeBasis(Shape::Quadrilateral, 1).values(ref) * corners;
  const Eigen::MatrixXd x = map.at(st);
  const std::vector<NodeId> ids = m.face_nodes(f);
  for (std::size_t j = 0; j < ids.size(); ++j) out.emplace(ids[j], x.row(static_cast<Eigen::Index>(j)).transpose());
}

void check_lists(const PrecutFace& p) {
  if (p.low.size() < 2 || p.low.size() != p.high.size() || p.low.size() != p.fractions.size())
    throw std::invalid_argument("follow_precut_faces: the precut face with low nodes " + nodes_label(p.low) +
                                " and high nodes " + nodes_label(p.high) + " has " +
                                std::to_string(p.fractions.size()) + " fractions (one per cut, ends included)");
}

Eigen::Vector3d displacement(const Displacements& d, NodeId v) {
  const auto it = d.find(v);
  return it == d.end() ? Eigen::Vector3d::Zero() : it->second;
}

// Fills the displacements of element e's nodes `d` lacks: its edges' inner nodes linearly between
// their ends, then its faces' and its own inner nodes by the harmonic extension (extend_inward).
void extend_into(const mesh::Mesh& m, std::size_t e, Displacements& d) {
  const mesh::Element& el = m.elements()[e];
  const int P = m.order();
  const std::vector<NodeId> ids = m.element_nodes(e);
  const mesh::NodeLayout& layout = mesh::node_layout(el.shape, P);
  const Eigen::MatrixX3d ref = reference_nodes(el.shape, P, m.node_set());
  for (std::size_t j = 0; j < ids.size(); ++j) {
    const mesh::NodeSlot& s = layout.slots[j];
    if (s.kind != mesh::NodeSlot::Edge || d.count(ids[j])) continue;
    const auto [a, b] = edges(el.shape)[s.local];
    const double f = (ref.row(static_cast<Eigen::Index>(j)) - ref.row(a)).norm() / (ref.row(b) - ref.row(a)).norm();
    d[ids[j]] = (1.0 - f) * displacement(d, ids[a]) + f * displacement(d, ids[b]);
  }
  for (std::size_t lf = 0; lf < faces(el.shape).size(); ++lf) {
    const std::size_t face = el.faces[lf];
    const Shape shape = m.faces()[face].num_vertices == 3 ? Shape::Triangle : Shape::Quadrilateral;
    const std::vector<NodeId> fids = m.face_nodes(face);
    const mesh::NodeLayout& face_layout = mesh::node_layout(shape, P);
    Eigen::MatrixXd x(static_cast<Eigen::Index>(fids.size()), 3);
    for (std::size_t r = 0; r < fids.size(); ++r) x.row(static_cast<Eigen::Index>(r)) = displacement(d, fids[r]).transpose();
    extend_inward(shape, P, m.node_set(), x);
    for (std::size_t r = 0; r < fids.size(); ++r)
      if (face_layout.slots[r].kind == mesh::NodeSlot::Face) d.emplace(fids[r], x.row(static_cast<Eigen::Index>(r)).transpose());
  }
  Eigen::MatrixXd x(static_cast<Eigen::Index>(ids.size()), 3);
  for (std::size_t j = 0; j < ids.size(); ++j) x.row(static_cast<Eigen::Index>(j)) = displacement(d, ids[j]).transpose();
  extend_inward(el.shape, P, m.node_set(), x);
  for (std::size_t j = 0; j < ids.size(); ++j)
    if (layout.slots[j].kind == mesh::NodeSlot::Interior) d.emplace(ids[j], x.row(static_cast<Eigen::Index>(j)).transpose());
}

// The elements using a node that moves.
std::vector<std::size_t> elements_moved(const mesh::Mesh& m, const Displacements& d) {
  std::vector<char> moves(m.num_nodes(), 0);
  for (const auto& [v, dv] : d) moves[v] = dv.squaredNorm() > 0.0;
  std::vector<std::size_t> out;
  std::vector<NodeId> ids;
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    m.element_nodes(e, ids);
    if (std::any_of(ids.begin(), ids.end(), [&](NodeId v) { return moves[v] != 0; })) out.push_back(e);
  }
  return out;
}

}  // namespace

PrecutStats follow_precut_faces(mesh::Mesh& mesh, const std::vector<PrecutFace>& faces, double tolerance) {
  PrecutStats stats;
  Displacements d;
  for (const PrecutFace& p : faces) {
    check_lists(p);
    const FaceMap map(mesh, p);
    std::map<NodeId, Eigen::Vector3d> target;
    for (std::size_t k = 0; k + 1 < p.low.size(); ++k) strip_targets(mesh, p, map, k, target);
    // The face's own corners are the hex's vertices: they stay.
    for (NodeId v : {p.low.front(), p.low.back(), p.high.front(), p.high.back()}) target.erase(v);
    double largest = 0.0;
    for (const auto& [v, x] : target) largest = std::max(largest, (x - mesh.node(v)).norm());
    if (largest <= tolerance) continue;
    ++stats.faces_moved;
    stats.largest_move = std::max(stats.largest_move, largest);
    for (const auto& [v, x] : target) {
      const Eigen::Vector3d dv = x - mesh.node(v);
      d.emplace(v, dv.norm() > tolerance ? dv : Eigen::Vector3d::Zero());
    }
  }
  if (stats.faces_moved == 0) return stats;
  for (std::size_t e : elements_moved(mesh, d)) extend_into(mesh, e, d);
  for (const auto& [v, dv] : d) {
    if (dv.squaredNorm() == 0.0) continue;
    ++stats.nodes_moved;
    const Eigen::Vector3d x = mesh.node(v) + dv;
    if (mesh.cad_attachment(v).kind == mesh::CadAttachment::None)
      mesh.place_node(v, x);
    else
      mesh.place_node_on_cad(v, x, {});
  }
  return stats;
}

}  // namespace semimesh::ho
