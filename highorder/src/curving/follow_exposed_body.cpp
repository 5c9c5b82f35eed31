#include "semimesh/ho/curving/follow_exposed_body.hpp"

#include "semimesh/ho/basis.hpp"
#include "semimesh/ho/closest_point.hpp"
#include "semimesh/ho/element_type.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <vector>

namespace semimesh::ho {
namespace {

using mesh::NodeId;

// A bulge below this share of the face's size is round-off: a planar face (the blunt base, a flat
// tip) leaves the far field bit for bit as curving made it.
constexpr double kLeastBulge = 1e-12;

// A curved body triangle the far field stands on: its vertices and its map's bulge over the chord.
struct ExposedFace {
  std::array<Eigen::Vector3d, 3> corner;
  Eigen::MatrixX3d nodes;  // canonical, order P
  double size = 0.0;       // longest edge: the reach of its bulge into the far field
};

// Which face entities the region's elements use, a flag per face: a std::set of them (every face of
// the far field's tetrahedra) took ~0.4 s of one core per call on the paper's case, twice a run.
std::vector<char> faces_of_region(const mesh::Mesh& m, int region) {
  std::vector<char> used(m.faces().size(), 0);
  for (const mesh::Element& el : m.elements())
    if (el.region == region)
      for (std::size_t k = 0; k < faces(el.shape).size(); ++k) used[el.faces[k]] = 1;
  return used;
}

std::vector<ExposedFace> curved_exposed_faces(const mesh::Mesh& m, int group, int region) {
  const std::vector<char> used = faces_of_region(m, region);
  const LagrangeBasis linear(Shape::Triangle, 1, NodeSet::Equispaced);
  const Eigen::MatrixX3d reference = reference_nodes(Shape::Triangle, m.order(), m.node_set());
  const Eigen::MatrixXd straight = linear.values(reference);
  std::vector<ExposedFace> out;
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b) {
    const mesh::BoundaryFace& bf = m.boundary_faces()[b];
    if (bf.group != group || bf.shape != Shape::Triangle || !used[bf.face]) continue;
    ExposedFace f;
    const std::vector<NodeId> ids = m.boundary_face_nodes(b);
    f.nodes.resize(static_cast<Eigen::Index>(ids.size()), 3);
    for (std::size_t i = 0; i < ids.size(); ++i) f.nodes.row(static_cast<Eigen::Index>(i)) = m.node(ids[i]).transpose();
    for (int k = 0; k < 3; ++k) f.corner[k] = f.nodes.row(k).transpose();
    for (int k = 0; k < 3; ++k) f.size = std::max(f.size, (f.corner[(k + 1) % 3] - f.corner[k]).norm());
    const double bulge = (f.nodes - straight * f.nodes.topRows(3)).rowwise().norm().maxCoeff();
    if (bulge > kLeastBulge * f.size) out.push_back(std::move(f));
  }
  return out;
}

// Nodes the far field must not move: on the CAD or a boundary face, shared with another region's
// elements, or a pyramid's base vertex (a pre-cut rim node, matched by position in the weld).
std::vector<char> fixed_nodes(const mesh::Mesh& m, int region) {
  std::vector<char> fixed(m.num_nodes(), 0);
  for (NodeId id = 0; id < m.num_nodes(); ++id) fixed[id] = m.cad_attachment(id).kind != mesh::CadAttachment::None;
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b)
    for (NodeId id : m.boundary_face_nodes(b)) fixed[id] = 1;
  std::vector<NodeId> ids;
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    const mesh::Element& el = m.elements()[e];
    if (el.region == region) {
      if (el.shape == Shape::Pyramid)
        for (int k = 0; k < 4; ++k) fixed[el.vertices[k]] = 1;
      continue;
    }
    m.element_nodes(e, ids);
    for (NodeId id : ids) fixed[id] = 1;
  }
  return fixed;
}

// The displacement that carries a far-field point at `x` (straight) along with the nearest face.
std::optional<Eigen::Vector3d> follow(const Eigen::Vector3d& x, const std::vector<ExposedFace>& faces, int order,
                                      NodeSet set) {
  double nearest = std::numeric_limits<double>::infinity();
  const ExposedFace* face = nullptr;
  Eigen::Vector3d foot_barycentric = Eigen::Vector3d::Zero();
  for (const ExposedFace& f : faces) {
    const TriangleFoot foot = closest_point_on_triangle(x, f.corner[0], f.corner[1], f.corner[2]);
    const double d = (x - foot.point).norm();
    if (d < nearest) nearest = d, face = &f, foot_barycentric = foot.barycentric;
  }
  if (!face || nearest >= face->size) return std::nullopt;
  Eigen::MatrixX3d foot(1, 3);
  foot << foot_barycentric[1], foot_barycentric[2], 0.0;  // Gmsh's triangle: vertices (0,0) (1,0) (0,1)
  const Eigen::RowVector3d curved = LagrangeBasis(Shape::Triangle, order, set).values(foot) * face->nodes;
  const Eigen::RowVector3d chord = LagrangeBasis(Shape::Triangle, 1, NodeSet::Equispaced).values(foot) * face->nodes.topRows(3);
  const double fade = 1.0 - nearest / face->size;
  return Eigen::Vector3d(fade * fade * (curved - chord).transpose());
}

// The straight place o of a far-field vertex that a first pass moved to x = o + F(o): F's slope is
// a face's bulge over its size, below 1, so the iteration o <- x - F(o) contracts to it.
Eigen::Vector3d unfollowed(const Eigen::Vector3d& x, const std::vector<ExposedFace>& faces, const mesh::Mesh& m) {
  constexpr int kMostSteps = 200;
  constexpr double kRoundOff = 1e-15;
  Eigen::Vector3d o = x;
  for (int k = 0; k < kMostSteps; ++k) {
    const Eigen::Vector3d next = x - follow(o, faces, m.order(), m.node_set()).value_or(Eigen::Vector3d::Zero());
    const double step = (next - o).norm();
    o = next;
    if (step <= kRoundOff * (1.0 + x.norm())) break;
  }
  return o;
}

}  // namespace

ExposedBodyStats follow_exposed_body(mesh::Mesh& curved, const std::string& body_group, const std::string& region,
                                     bool moved_before) {
  ExposedBodyStats stats;
  const auto& groups = curved.group_names();
  const auto& regions = curved.region_names();
  const auto group_it = std::find(groups.begin(), groups.end(), body_group);
  const auto region_it = std::find(regions.begin(), regions.end(), region);
  if (curved.order() < 2 || group_it == groups.end() || region_it == regions.end()) return stats;
  const int group = static_cast<int>(group_it - groups.begin()), region_id = static_cast<int>(region_it - regions.begin());
  const std::vector<ExposedFace> faces = curved_exposed_faces(curved, group, region_id);
  stats.faces = faces.size();
  if (faces.empty()) return stats;

  double reach = 0.0;
  Eigen::AlignedBox3d near_faces;
  for (const ExposedFace& f : faces) {
    reach = std::max(reach, f.size);
    for (const Eigen::Vector3d& c : f.corner) near_faces.extend(c);
  }
  near_faces.min().array() -= reach;
  near_faces.max().array() += reach;

  const std::vector<char> fixed = fixed_nodes(curved, region_id);
  std::vector<char> done(curved.num_nodes(), 0);
  std::vector<std::pair<NodeId, Eigen::Vector3d>> moves;
  std::vector<NodeId> ids;
  for (std::size_t e = 0; e < curved.elements().size(); ++e) {
    const mesh::Element& el = curved.elements()[e];
    if (el.region != region_id) continue;
    const int nv = num_vertices(el.shape);
    Eigen::MatrixX3d corners(nv, 3);
    bool near = false;
    for (int k = 0; k < nv; ++k) {
      const Eigen::Vector3d& x = curved.node(el.vertices[k]);
      corners.row(k) = (moved_before && !fixed[el.vertices[k]] ? unfollowed(x, faces, curved) : x).transpose();
      near = near || near_faces.contains(x);
    }
    if (!near) continue;
    curved.element_nodes(e, ids);
    // Straight positions from the element's vertices: one place per node, whichever element asks.
    const Eigen::MatrixX3d straight = LagrangeBasis(el.shape, 1, NodeSet::Equispaced)
                                          .values(reference_nodes(el.shape, curved.order(), curved.node_set())) *
                                      corners;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (fixed[ids[i]] || done[ids[i]]) continue;
      done[ids[i]] = 1;
      const Eigen::Vector3d x = straight.row(static_cast<Eigen::Index>(i)).transpose();
      if (const auto move = follow(x, faces, curved.order(), curved.node_set())) moves.emplace_back(ids[i], x + *move);
    }
  }
  for (const auto& [id, x] : moves) curved.place_node(id, x);
  stats.nodes = moves.size();
  return stats;
}

}  // namespace semimesh::ho
