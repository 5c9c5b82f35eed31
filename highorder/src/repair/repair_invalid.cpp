#include "semimesh/ho/repair.hpp"

#include "semimesh/cad/labels.hpp"

#include "semimesh/ho/basis.hpp"
#include "semimesh/ho/quality.hpp"
#include "semimesh/ho/validity.hpp"
#include "semimesh/mesh/node_layout.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>

namespace semimesh::ho {
namespace {

using mesh::NodeId;

// Bisection steps on t: the kept t is within 2^-20 of the largest valid one found.
constexpr int kBisections = 20;

/// Nodes that move together, with both ends of their blend.
struct Blend {
  std::vector<NodeId> nodes;
  std::vector<Eigen::Vector3d> straight, curved;  // [nodes]
};

void apply(mesh::Mesh& m, const Blend& b, double t) {
  for (std::size_t i = 0; i < b.nodes.size(); ++i) m.place_node(b.nodes[i], b.straight[i] + t * (b.curved[i] - b.straight[i]));
}

bool all_valid(const mesh::Mesh& m, const std::vector<std::size_t>& elements, double floor) {
  return std::all_of(elements.begin(), elements.end(), [&](std::size_t e) {
    return acceptable(certify_jacobian(m.elements()[e].shape, m.order(), m.node_set(), m.element_coordinates(e), 8, floor),
                      floor);
  });
}

/// Largest t in [0, 1] found by bisection for which every element of `check` is valid, with the
/// nodes left there; -1 (nodes back at t = 1) when t = 0 is not valid.
double largest_valid_blend(mesh::Mesh& m, const Blend& b, const std::vector<std::size_t>& check, double floor) {
  apply(m, b, 0.0);
  if (!all_valid(m, check, floor)) {
    apply(m, b, 1.0);
    return -1.0;
  }
  double lo = 0.0, hi = 1.0;  // valid at lo, invalid at hi
  for (int k = 0; k < kBisections; ++k) {
    const double mid = 0.5 * (lo + hi);
    apply(m, b, mid);
    (all_valid(m, check, floor) ? lo : hi) = mid;
  }
  apply(m, b, lo);
  return lo;
}

/// The first t of 1, 3/4, 1/2, 1/4 for which every element of `check` is acceptable, with the nodes
/// left there; -1 (nodes back at t = 0) when none is. Not a bisection: t = 0 is the invalid state.
double first_valid_step(mesh::Mesh& m, const Blend& b, const std::vector<std::size_t>& check, double floor) {
  for (double t : {1.0, 0.75, 0.5, 0.25}) {
    apply(m, b, t);
    if (all_valid(m, check, floor)) return t;
  }
  apply(m, b, 0.0);
  return -1.0;
}

class Repairer {
 public:
  Repairer(mesh::Mesh& m, const cad::Model& model, double floor) : m_(m), model_(model), floor_(floor) {}
  void repair(std::size_t e, RepairStats& stats);

 private:
  Blend blend_of(std::size_t e, bool free_boundary_nodes) const;
  Blend follow_body_face(std::size_t e) const;
  /// Elements other than e that use a node of `nodes` and are valid now.
  std::vector<std::size_t> valid_neighbours(std::size_t e, const std::vector<NodeId>& nodes);
  RepairFailure failure(std::size_t e) const;

  mesh::Mesh& m_;
  const cad::Model& model_;
  double floor_;  // min scaled Jacobian an element must reach
  std::vector<std::vector<std::size_t>> elements_of_node_;  // built on first need
};

Blend Repairer::blend_of(std::size_t e, bool free_boundary_nodes) const {
  const Shape shape = m_.elements()[e].shape;
  const int P = m_.order(), nv = num_vertices(shape);
  const std::vector<NodeId> ids = m_.element_nodes(e);
  const Eigen::MatrixX3d X = m_.element_coordinates(e);
  const Eigen::MatrixXd straight =
      LagrangeBasis(shape, 1, NodeSet::Equispaced).values(reference_nodes(shape, P, m_.node_set())) * X.topRows(nv);
  const mesh::NodeLayout& layout = mesh::node_layout(shape, P);
  Blend b;
  for (std::size_t i = nv; i < ids.size(); ++i) {
    const bool interior = layout.slots[i].kind == mesh::NodeSlot::Interior;
    const bool on_cad = m_.cad_attachment(ids[i]).kind != mesh::CadAttachment::None;
    if (on_cad || !(interior || free_boundary_nodes)) continue;
    b.nodes.push_back(ids[i]);
    b.straight.push_back(straight.row(i).transpose());
    b.curved.push_back(X.row(i).transpose());
  }
  return b;
}

// A prism of the shell: its face 0-1-2 lies on the body, curved onto the CAD; its outer face is
// straight. Every node off the CAD moves from where it is (t = 0) to its straight position plus the
// body face's displacement below it (t = 1): the whole column follows the curved body, as when the
// paper curves the single-layer element as a whole. The outer face's nodes are shared with the far
// field, so the far-field elements there get curved too (and are checked).
Blend Repairer::follow_body_face(std::size_t e) const {
  const Shape shape = m_.elements()[e].shape;
  Blend b;
  if (shape != Shape::Prism) return b;
  const int P = m_.order();
  const std::vector<NodeId> ids = m_.element_nodes(e);
  const Eigen::MatrixX3d X = m_.element_coordinates(e);
  Eigen::MatrixX3d reference = reference_nodes(shape, P, m_.node_set());
  Eigen::MatrixX3d below = reference;
  below.col(2).setConstant(-1.0);  // Gmsh's prism: face 0-1-2 at zeta = -1
  const LagrangeBasis curved(shape, P, m_.node_set());
  const LagrangeBasis linear(shape, 1, NodeSet::Equispaced);
  const Eigen::MatrixX3d straight = linear.values(reference) * X.topRows(6);
  const Eigen::MatrixX3d bulge = curved.values(below) * X - linear.values(below) * X.topRows(6);
  for (std::size_t i = 6; i < ids.size(); ++i) {
    if (m_.cad_attachment(ids[i]).kind != mesh::CadAttachment::None) continue;
    b.nodes.push_back(ids[i]);
    b.straight.push_back(X.row(i).transpose());
    b.curved.push_back((straight.row(i) + bulge.row(i)).transpose());
  }
  return b;
}

std::vector<std::size_t> Repairer::valid_neighbours(std::size_t e, const std::vector<NodeId>& nodes) {
  if (elements_of_node_.empty()) {
    elements_of_node_.resize(m_.num_nodes());
    std::vector<NodeId> ids;
    for (std::size_t k = 0; k < m_.elements().size(); ++k) {
      m_.element_nodes(k, ids);
      for (NodeId id : ids) elements_of_node_[id].push_back(k);
    }
  }
  std::vector<std::size_t> out;
  for (NodeId id : nodes)
    for (std::size_t k : elements_of_node_[id])
      if (k != e) out.push_back(k);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  out.erase(std::remove_if(out.begin(), out.end(), [&](std::size_t k) { return !all_valid(m_, {k}, floor_); }), out.end());
  return out;
}

RepairFailure Repairer::failure(std::size_t e) const {
  const mesh::Element& el = m_.elements()[e];
  RepairFailure f;
  f.element = e;
  const int nv = num_vertices(el.shape);
  for (int v = 0; v < nv; ++v) f.centroid += m_.node(el.vertices[v]);
  f.centroid /= nv;
  std::string surfaces;
  for (NodeId id : m_.element_nodes(e)) {
    const mesh::CadAttachment& a = m_.cad_attachment(id);
    if (a.kind != mesh::CadAttachment::Surface) continue;
    const std::string name = cad::surface_label(model_, a.entity);
    if (surfaces.find(name) == std::string::npos) surfaces += (surfaces.empty() ? "" : ", ") + name;
  }
  std::ostringstream msg;
  msg << "element " << e << " at (" << f.centroid.x() << ", " << f.centroid.y() << ", " << f.centroid.z()
      << ") stays invalid with every node off the CAD straightened, and with its column following the curved "
         "body face: its nodes on the CAD"
      << (surfaces.empty() ? std::string() : " (" + surfaces + ")")
      << " fold it; refine the surface mesh there (a smaller sizing.min_size) or change the near-field thickness";
  f.reason = msg.str();
  return f;
}

void Repairer::repair(std::size_t e, RepairStats& stats) {
  ++stats.checked;
  if (all_valid(m_, {e}, floor_)) {
    ++stats.already_valid;
    return;
  }
  const Blend interior = blend_of(e, false);
  if (!interior.nodes.empty()) {
    const double t = largest_valid_blend(m_, interior, {e}, floor_);
    if (t >= 0.0) {
      ++stats.repaired_interior;
      stats.min_blend = std::min(stats.min_blend, t);
      return;
    }
  }
  const Blend free = blend_of(e, true);
  if (free.nodes.size() > interior.nodes.size()) {
    std::vector<std::size_t> check = valid_neighbours(e, free.nodes);
    check.push_back(e);
    const double t = largest_valid_blend(m_, free, check, floor_);
    if (t >= 0.0) {
      ++stats.repaired_free_nodes;
      stats.min_blend = std::min(stats.min_blend, t);
      return;
    }
  }
  const Blend column = follow_body_face(e);
  if (!column.nodes.empty()) {
    std::vector<std::size_t> check = valid_neighbours(e, column.nodes);
    check.push_back(e);
    if (first_valid_step(m_, column, check, floor_) > 0.0) {
      ++stats.repaired_body_following;
      return;
    }
  }
  stats.failures.push_back(failure(e));
}

}  // namespace

Repaired repair_invalid(const mesh::Mesh& mesh, const cad::Model& model, const std::vector<std::size_t>& elements,
                        double min_scaled_jacobian) {
  for (std::size_t e : elements) {
    if (e >= mesh.elements().size())
      throw std::invalid_argument("repair_invalid: element index " + std::to_string(e) + " out of range (mesh has " +
                                  std::to_string(mesh.elements().size()) + " elements)");
    if (dimension(mesh.elements()[e].shape) != 3)
      throw std::invalid_argument("repair_invalid: element " + std::to_string(e) + " is a " +
                                  to_string(mesh.elements()[e].shape) + "; only 3D elements can be repaired");
  }
  Repaired out{mesh, {}};
  Repairer repairer(out.mesh, model, min_scaled_jacobian);
  for (std::size_t e : elements) repairer.repair(e, out.stats);
  return out;
}

}  // namespace semimesh::ho
