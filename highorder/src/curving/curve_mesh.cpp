#include "semimesh/ho/curving/curve_mesh.hpp"

#include "curving/cad_classification.hpp"
#include "curving/harmonic_extension.hpp"
#include "curving/kinked_parameters.hpp"
#include "curving/pole_chart.hpp"
#include "curving/spring_optimisation.hpp"
#include "parallel_for.hpp"
#include "semimesh/ho/basis.hpp"
#include "semimesh/mesh/node_layout.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

namespace semimesh::ho {
namespace {

using detail::CadPlace;
using mesh::CadAttachment;
using mesh::NodeId;

// Edges, faces or elements placed in parallel before their nodes are made (bounds the memory of
// the placed positions; large enough that the threads rarely wait at a block's end).
constexpr std::size_t kBlock = 4096;

// A curve edge whose parameter midpoint lies farther than this fraction of the edge from its arc
// length midpoint takes its nodes by arc length.
constexpr double kUnevenParameter = 0.1;

// (num_nodes(shape, order), corners): the linear face's map at the face's reference nodes of
// `set`. Kept per thread and shape: building a basis (a Vandermonde solve) for every face on the
// CAD was a tenth of the curving.
const Eigen::MatrixXd& linear_face_map(Shape shape, int order, NodeSet set) {
  struct Cached {
    int order = -1;
    NodeSet set = NodeSet::Equispaced;
    Eigen::MatrixXd values;
  };
  thread_local std::array<Cached, 2> cache;  // triangle, quadrilateral
  Cached& c = cache[shape == Shape::Triangle ? 0 : 1];
  if (c.order != order || c.set != set)
    c = {order, set, LagrangeBasis(shape, 1, NodeSet::Equispaced).values(reference_nodes(shape, order, set))};
  return c.values;
}

// Nodes inside a volume element of this shape and order (none on its edges or faces).
std::size_t interior_node_count(Shape shape, int order) {
  const mesh::NodeLayout& layout = mesh::node_layout(shape, order);
  return static_cast<std::size_t>(std::count_if(layout.slots.begin(), layout.slots.end(), [](const mesh::NodeSlot& s) {
    return s.kind == mesh::NodeSlot::Interior;
  }));
}

// Thrown by the curving ahead when told to stop.
struct StoppedAhead {};

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

bool same_attachment(const CadAttachment& a, const CadAttachment& b) {
  return a.kind == b.kind && a.entity == b.entity && same_bits(a.u, b.u) && same_bits(a.v, b.v);
}

class Curver {
 public:
  /// `ahead`: placements to take (curve_mesh's); `record`: filled with this curving's placements
  /// (curve_ahead's); `stop`: when set, the next edge, face or element throws StoppedAhead.
  Curver(const mesh::Mesh& linear, const cad::Model& model, const CurvingParams& params, ProgressCallback progress,
         const CurvedAhead* ahead = nullptr, CurvedAhead* record = nullptr, const std::atomic<bool>* stop = nullptr)
      : in_(linear), model_(model), params_(params), out_(params.order, params.node_set), progress_(std::move(progress)),
        ahead_(ahead), record_(record), stop_(stop) {}
  mesh::Mesh run(CurvingStats* stats);
  std::size_t taken() const { return taken_; }

 private:
  /// New nodes of one edge or face, computed independently of the others (in parallel) and added
  /// to the mesh afterwards in a fixed order.
  struct PlacedNodes {
    CadPlace::Kind place = CadPlace::None;
    bool fallback = false;  // the spring optimisation kept its start positions
    double moved = 0.0;     // largest distance from a straight-sided position to the placed one
  };
  struct EdgeNodes : PlacedNodes {  // in place (no allocation per edge): [0, P-1) used
    std::array<Eigen::Vector3d, kMaxOrder - 1> x;  // from edge vertices[0] to vertices[1]
    std::array<CadAttachment, kMaxOrder - 1> att;
  };
  struct FaceNodes : PlacedNodes {
    Eigen::MatrixXd x;               // (face nodes, 3) canonical order of the stored face
    std::vector<CadAttachment> att;  // [face nodes], or empty: none attached
  };

  EdgeNodes place_edge(std::size_t e, const std::vector<double>& fraction, bool on_boundary) const;
  FaceNodes place_face(std::size_t f, bool on_boundary) const;
  /// Which edges, faces and elements take their nodes from ahead_ (the rules in curve_mesh.hpp).
  void choose_taken(const std::vector<char>& edge_on_boundary, const std::vector<char>& face_on_boundary);
  /// place_edge's and place_face's results as the curving ahead placed them.
  EdgeNodes taken_edge(std::size_t e) const;
  FaceNodes taken_face(std::size_t f) const;
  void check_stop() const {
    if (stop_ && stop_->load(std::memory_order_relaxed)) throw StoppedAhead{};
  }
  void note(const PlacedNodes& placed);
  void curve_edges(const std::vector<char>& on_boundary);
  void curve_faces(const std::vector<char>& on_boundary);
  /// Canonical node ids of element e with kNoNode for its volume-interior nodes.
  std::vector<NodeId> element_node_ids(std::size_t e) const;
  /// Canonical node ids of a 2D shape with these vertices and edges (the input's ids, in the order
  /// of the shape's edges, as a mesh::Face or BoundaryFace stores them), from the edge nodes
  /// already made and, when `face` >= 0, that face's interior nodes seen with orientation `code`;
  /// into `ids` (a buffer of the caller's: this runs for every face).
  void planar_nodes(Shape shape, const NodeId* vertices, const std::uint32_t* edge_ids, long face, int code,
                    std::vector<NodeId>& ids) const;

  const mesh::Mesh& in_;
  const cad::Model& model_;
  CurvingParams params_;
  mesh::Mesh out_;
  CurvingStats stats_;
  ProgressCallback progress_;
  // The parts of progress_ for the edges, faces and volumes, in proportion to their counts.
  ProgressCallback edge_progress_, face_progress_, volume_progress_;
  std::vector<std::vector<cad::Vec3>> poles_;       // [surfaces] detail::surface_poles
  std::vector<std::array<detail::KinkChart, 2>> surface_charts_;  // [surfaces] u and v
  std::vector<detail::KinkChart> curve_charts_;                   // [curves]
  // The nodes made inside the input's edges and faces, each entity's in a fixed stride of one array
  // (millions of small lists cost an allocation and a free each): edge e's P - 1 from its
  // vertices[0] to vertices[1]; face f's in the canonical order of the stored face, in a stride of a
  // quadrilateral's count (a triangle's are fewer).
  std::vector<NodeId> edge_interior_;  // [edges * (P - 1)]
  std::vector<NodeId> face_interior_;  // [faces * face_stride_]
  // The CAD attachments of the edges' nodes that have one: place_face reads them while the faces'
  // nodes are being added (out_'s own table of attachments is then being written).
  std::unordered_map<NodeId, CadAttachment> edge_node_cad_;
  const CadAttachment& edge_node_cad(NodeId id) const {
    static const CadAttachment none{};
    const auto found = edge_node_cad_.find(id);
    return found == edge_node_cad_.end() ? none : found->second;
  }
  std::size_t face_stride_ = 0;
  NodeId edge_node(std::size_t edge, int slot) const {
    return edge_interior_[edge * static_cast<std::size_t>(params_.order - 1) + static_cast<std::size_t>(slot)];
  }
  NodeId face_node(std::size_t face, int slot) const {
    return face_interior_[face * face_stride_ + static_cast<std::size_t>(slot)];
  }
  const CurvedAhead* ahead_;
  CurvedAhead* record_;
  const std::atomic<bool>* stop_;
  // [edges], [faces], [elements] of in_: 1 where the nodes are taken from ahead_ (empty: none).
  std::vector<char> edge_taken_, face_taken_, element_taken_;
  std::size_t taken_ = 0;
};

void Curver::choose_taken(const std::vector<char>& edge_on_boundary, const std::vector<char>& face_on_boundary) {
  if (!ahead_ || ahead_->empty()) return;
  const mesh::Mesh& m = ahead_->curved;
  if (m.order() != params_.order || m.node_set() != params_.node_set || ahead_->linear_nodes > in_.num_nodes() ||
      ahead_->linear_nodes > m.num_nodes() || ahead_->edges.size() != m.edges().size() ||
      ahead_->faces.size() != m.faces().size() || ahead_->edge_on_boundary.size() != m.edges().size() ||
      ahead_->face_on_boundary.size() != m.faces().size())
    return;
  // The linear nodes it was curved on: the same bits and attachments, or nothing is taken.
  for (NodeId id = 0; id < ahead_->linear_nodes; ++id) {
    const Eigen::Vector3d &a = in_.node(id), &b = m.node(id);
    if (!same_bits(a.x(), b.x()) || !same_bits(a.y(), b.y()) || !same_bits(a.z(), b.z()) ||
        !same_attachment(in_.cad_attachment(id), m.cad_attachment(id)))
      return;
  }
  edge_taken_.assign(in_.edges().size(), 0);
  face_taken_.assign(in_.faces().size(), 0);
  element_taken_.assign(in_.elements().size(), 0);
  for (std::size_t e = 0; e < std::min(in_.edges().size(), m.edges().size()); ++e)
    edge_taken_[e] = in_.edges()[e].vertices == m.edges()[e].vertices &&
                     (edge_on_boundary[e] != 0) == (ahead_->edge_on_boundary[e] != 0);
  const auto edges_taken = [&](const std::uint32_t* ids, int n) {
    return std::all_of(ids, ids + n, [&](std::uint32_t id) { return edge_taken_[id] != 0; });
  };
  for (std::size_t f = 0; f < std::min(in_.faces().size(), m.faces().size()); ++f) {
    const mesh::Face &a = in_.faces()[f], &b = m.faces()[f];
    face_taken_[f] = a.vertices == b.vertices && a.num_vertices == b.num_vertices && a.edges == b.edges &&
                     a.edge_reversed == b.edge_reversed &&
                     (face_on_boundary[f] != 0) == (ahead_->face_on_boundary[f] != 0) &&
                     edges_taken(a.edges.data(), a.num_vertices);
  }
  for (std::size_t e = 0; e < std::min(in_.elements().size(), m.elements().size()); ++e) {
    const mesh::Element &a = in_.elements()[e], &b = m.elements()[e];
    const int faces = static_cast<int>(ho::faces(a.shape).size());
    element_taken_[e] = a.shape == b.shape && a.vertices == b.vertices && a.edges == b.edges &&
                        a.edge_reversed == b.edge_reversed && a.faces == b.faces &&
                        a.face_orientation == b.face_orientation && edges_taken(a.edges.data(), static_cast<int>(edges(a.shape).size())) &&
                        std::all_of(a.faces.begin(), a.faces.begin() + faces,
                                    [&](std::uint32_t f) { return face_taken_[f] != 0; });
  }
  for (const std::vector<char>* taken : {&edge_taken_, &face_taken_, &element_taken_})
    taken_ += static_cast<std::size_t>(std::count(taken->begin(), taken->end(), 1));
}

Curver::EdgeNodes Curver::taken_edge(std::size_t e) const {
  const mesh::Mesh& m = ahead_->curved;
  const CurvedAhead::Placed& placed = ahead_->edges[e];
  EdgeNodes out;
  out.place = static_cast<CadPlace::Kind>(placed.place);
  out.fallback = placed.fallback;
  out.moved = placed.moved;
  thread_local std::vector<NodeId> ids;  // this thread's: no allocation per edge
  m.edge_nodes(e, ids);                   // vertices[0], the interior, vertices[1]
  for (std::size_t i = 1; i + 1 < ids.size(); ++i) {
    out.x[i - 1] = m.node(ids[i]);
    out.att[i - 1] = m.cad_attachment(ids[i]);
  }
  return out;
}

Curver::FaceNodes Curver::taken_face(std::size_t f) const {
  const Shape shape = in_.faces()[f].num_vertices == 3 ? Shape::Triangle : Shape::Quadrilateral;
  FaceNodes out;
  if (detail::harmonic_extension(shape, params_.order, params_.node_set).interior.empty()) return out;
  const mesh::Mesh& m = ahead_->curved;
  const CurvedAhead::Placed& placed = ahead_->faces[f];
  out.place = static_cast<CadPlace::Kind>(placed.place);
  out.fallback = placed.fallback;
  out.moved = placed.moved;
  thread_local std::vector<NodeId> ids;  // this thread's: no allocation per face
  m.face_nodes(f, ids);                   // canonical order of the stored face
  out.x.resize(static_cast<Eigen::Index>(ids.size()), 3);
  out.att.resize(ids.size());
  for (std::size_t j = 0; j < ids.size(); ++j) {
    out.x.row(static_cast<Eigen::Index>(j)) = m.node(ids[j]).transpose();
    out.att[j] = m.cad_attachment(ids[j]);
  }
  return out;
}

void Curver::planar_nodes(Shape shape, const NodeId* vertices, const std::uint32_t* edge_ids, long face, int code,
                          std::vector<NodeId>& ids) const {
  const mesh::NodeLayout& layout = mesh::node_layout(shape, params_.order);
  ids.assign(layout.slots.size(), mesh::kNoNode);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const mesh::NodeSlot& s = layout.slots[i];
    if (s.kind == mesh::NodeSlot::Vertex) {
      ids[i] = vertices[s.local];
    } else if (s.kind == mesh::NodeSlot::Edge) {
      const auto& e = edges(shape)[s.local];
      ids[i] = edge_node(edge_ids[s.local], s.slot[vertices[e[0]] > vertices[e[1]] ? 1 : 0]);
    } else if (face >= 0) {
      ids[i] = face_node(static_cast<std::size_t>(face), s.slot[code]);
    }
  }
}

Curver::EdgeNodes Curver::place_edge(std::size_t e, const std::vector<double>& fraction, bool on_boundary) const {
  const int P = params_.order;
  const NodeId a = in_.edges()[e].vertices[0], b = in_.edges()[e].vertices[1];
  const Eigen::Vector3d xa = in_.node(a), xb = in_.node(b);
  EdgeNodes out;
  for (int i = 0; i < P - 1; ++i) out.x[i] = xa + fraction[i] * (xb - xa);
  const CadPlace place =
      on_boundary ? detail::classify(model_, {in_.cad_attachment(a), in_.cad_attachment(b)}, true, 0.5 * (xa + xb))
                  : CadPlace{};
  out.place = place.kind;
  const bool springs = params_.placement == NodePlacement::Springs;
  if (place.kind == CadPlace::Curve) {
    // The node set's fractions of the parameter interval (of its kink chart's when kinked), or of
    // the arc length (the spring chain's optimum on a curve).
    const cad::Curve& c = model_.curve(place.id);
    // b's parameter first on its own, then each end next to the other: a closed curve's vertex
    // takes the end nearer the edge's other node (only a vertex needs b's second look).
    const CadAttachment& att_b = in_.cad_attachment(b);
    const double tb0 = detail::curve_parameter(model_, place.id, att_b, xb, std::nullopt);
    const double ta = detail::curve_parameter(model_, place.id, in_.cad_attachment(a), xa, tb0);
    const double tb = att_b.kind == CadAttachment::Vertex ? detail::curve_parameter(model_, place.id, att_b, xb, ta) : tb0;
    const detail::KinkChart& chart = curve_charts_[place.id];
    const double sa = chart.to_chart(ta), sb = chart.to_chart(tb);
    const auto by_parameter = [&](double f) { return chart.from_chart(sa + f * (sb - sa)); };
    // A parameter running very unevenly inside the edge (an intersection curve of OCCT's Booleans:
    // at a wing's root on a fuselage a mid-edge node a tenth of the way along folded the junction
    // hex there) gives way to the arc length on this edge. A smooth parameter passes the test
    // once the mesh is fine, so the placement keeps its convergence rate.
    const double length = c.arc_length(ta, tb);
    const bool by_length =
        springs || (c.point(by_parameter(0.5)) - c.point(c.parameter_at_length(ta, 0.5 * length))).norm() >
                       kUnevenParameter * (xb - xa).norm();
    for (int i = 0; i < P - 1; ++i) {
      const double t = by_length ? c.parameter_at_length(ta, fraction[i] * length) : by_parameter(fraction[i]);
      const Eigen::Vector3d p = c.point(t);
      out.moved = std::max(out.moved, (p - out.x[i]).norm());
      out.x[i] = p;
      out.att[i] = {CadAttachment::Curve, place.id, t, 0.0};
    }
  } else if (place.kind == CadPlace::Surface) {
    const cad::Surface& s = model_.surface(place.id);
    const cad::Vec2 start = detail::surface_parameter(model_, place.id, in_.cad_attachment(a), xa);
    Eigen::MatrixXd ends(2, 2);
    ends.row(0) = start.transpose();
    ends.row(1) = detail::surface_parameter(model_, place.id, in_.cad_attachment(b), xb, &start).transpose();
    detail::continuous_parameters(s, ends, 2, 2);
    const cad::Vec2 uva = ends.row(0).transpose(), uvb = ends.row(1).transpose();
    Eigen::MatrixX2d uv(P + 1, 2);
    Eigen::MatrixX3d pts(P + 1, 3);
    uv.row(0) = uva.transpose();
    uv.row(1) = uvb.transpose();
    pts.row(0) = xa.transpose();
    pts.row(1) = xb.transpose();
    const std::array<detail::KinkChart, 2>& chart = surface_charts_[place.id];
    for (int i = 0; i < P - 1; ++i)
      for (int d = 0; d < 2; ++d) {
        const double a = chart[d].to_chart(uva[d]), b = chart[d].to_chart(uvb[d]);
        uv(i + 2, d) = chart[d].from_chart(a + fraction[i] * (b - a));
      }
    if (detail::near_pole(poles_[place.id], xa, xb, params_.pole_reach))
      for (int i = 0; i < P - 1; ++i) detail::place_by_projection(s, out.x[i], uv, pts, i + 2);
    else if (springs)
      out.fallback = !detail::optimise_on_surface(s, Shape::Segment, P, params_.node_set, uv, pts,
                                                  params_.spring_iterations, params_.tolerance * (xb - xa).norm());
    else
      for (int i = 0; i < P - 1; ++i) pts.row(i + 2) = s.point(uv.row(i + 2).transpose()).transpose();
    for (int i = 0; i < P - 1; ++i) {
      out.moved = std::max(out.moved, (pts.row(i + 2).transpose() - out.x[i]).norm());
      out.x[i] = pts.row(i + 2).transpose();
      out.att[i] = {CadAttachment::Surface, place.id, uv(i + 2, 0), uv(i + 2, 1)};
    }
  }
  return out;
}

void Curver::note(const PlacedNodes& placed) {
  stats_.max_projection_distance = std::max(stats_.max_projection_distance, placed.moved);
  stats_.optimisation_fallbacks += placed.fallback ? 1 : 0;
}

void Curver::curve_edges(const std::vector<char>& on_boundary) {
  const int P = params_.order;
  const Eigen::MatrixX3d seg = reference_nodes(Shape::Segment, P, params_.node_set);
  std::vector<double> fraction(P - 1);  // of the interior nodes, from vertex 0 to vertex 1
  for (int i = 0; i < P - 1; ++i) fraction[i] = 0.5 * (seg(i + 2, 0) + 1.0);

  // Positions in parallel, then the nodes in edge order (ids independent of the thread count); a
  // block's nodes are made while the next block is placed (place_edge reads the input mesh and the
  // CAD only).
  edge_interior_.assign(in_.edges().size() * static_cast<std::size_t>(P - 1), mesh::kNoNode);
  detail::overlapped_blocks(
      in_.edges().size(), model_.thread_safe(), kBlock, [](std::size_t, std::size_t) {},
      [&](std::size_t e) {
        check_stop();
        return !edge_taken_.empty() && edge_taken_[e] ? taken_edge(e) : place_edge(e, fraction, on_boundary[e] != 0);
      },
      [&](std::size_t e, const EdgeNodes& placed) {
        if (record_) record_->edges[e] = {static_cast<std::int8_t>(placed.place), placed.fallback, placed.moved};
        note(placed);
        stats_.edges_on_curves += placed.place == CadPlace::Curve ? 1 : 0;
        stats_.edges_on_surfaces += placed.place == CadPlace::Surface ? 1 : 0;
        for (int i = 0; i < P - 1; ++i) {
          const NodeId id = out_.add_node(placed.x[i], placed.att[i]);
          edge_interior_[e * static_cast<std::size_t>(P - 1) + static_cast<std::size_t>(i)] = id;
          if (placed.att[i].kind != CadAttachment::None) edge_node_cad_.emplace(id, placed.att[i]);
        }
      },
      edge_progress_, "edges");
}

Curver::FaceNodes Curver::place_face(std::size_t f, bool on_boundary) const {
  const int P = params_.order;
  const mesh::Face& face = in_.faces()[f];
  const Shape shape = face.num_vertices == 3 ? Shape::Triangle : Shape::Quadrilateral;
  const detail::HarmonicExtension& ext = detail::harmonic_extension(shape, P, params_.node_set);
  FaceNodes out;
  if (ext.interior.empty()) return out;
  thread_local std::vector<NodeId> ids;  // this thread's: no allocation per face
  planar_nodes(shape, face.vertices.data(), face.edges.data(), -1, 0, ids);
  const int n = static_cast<int>(ids.size());
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(n, 3);
  for (int j : ext.boundary) X.row(j) = out_.node(ids[j]).transpose();
  extend_harmonically(detail::inner_extension(shape, P, params_.node_set), X);

  if (!on_boundary) {  // off the CAD (most faces): its corners' attachments are not read
    out.x = std::move(X);
    return out;
  }
  std::vector<CadAttachment> corner_att;
  for (int v = 0; v < face.num_vertices; ++v) corner_att.push_back(in_.cad_attachment(face.vertices[v]));
  const CadPlace place = detail::classify(model_, corner_att, false, X.colwise().mean().transpose());
  out.place = place.kind;
  if (place.kind == CadPlace::Surface) {
    out.att.resize(n);  // (off the CAD: none, every node unattached)
    // The straight-sided face (its linear map), to measure how far curving moves the nodes.
    Eigen::MatrixX3d corners(face.num_vertices, 3);
    for (int v = 0; v < face.num_vertices; ++v) corners.row(v) = in_.node(face.vertices[v]).transpose();
    const Eigen::MatrixXd straight = linear_face_map(shape, P, params_.node_set) * corners;
    const cad::Surface& s = model_.surface(place.id);
    Eigen::MatrixXd uv = Eigen::MatrixXd::Zero(n, 2);
    for (int v = 0; v < face.num_vertices; ++v)
      uv.row(v) = detail::surface_parameter(model_, place.id, corner_att[v], X.row(v).transpose()).transpose();
    detail::continuous_parameters(s, uv, face.num_vertices, face.num_vertices);
    const cad::Vec2 guess = uv.topRows(face.num_vertices).colwise().mean().transpose();
    for (int j : ext.boundary)
      if (j >= face.num_vertices)
        uv.row(j) =
            detail::surface_parameter(model_, place.id, edge_node_cad(ids[j]), X.row(j).transpose(), &guess)
                .transpose();
    detail::continuous_parameters(s, uv, static_cast<int>(uv.rows()), face.num_vertices);
    // The harmonic extension in the kink chart's parameters (the identity on most surfaces).
    const std::array<detail::KinkChart, 2>& chart = surface_charts_[place.id];
    for (int j : ext.boundary)
      for (int d = 0; d < 2; ++d) uv(j, d) = chart[d].to_chart(uv(j, d));
    extend_harmonically(ext, uv);
    for (int j = 0; j < n; ++j)
      for (int d = 0; d < 2; ++d) uv(j, d) = chart[d].from_chart(uv(j, d));
    Eigen::MatrixX2d uv2 = uv;
    Eigen::MatrixX3d pts = X;
    double size = 0.0;
    for (int v = 1; v < face.num_vertices; ++v) size = std::max(size, (X.row(v) - X.row(0)).norm());
    std::vector<cad::Vec3> vertices;
    for (int v = 0; v < face.num_vertices; ++v) vertices.push_back(X.row(v).transpose());
    if (detail::face_near_pole(poles_[place.id], vertices, params_.pole_reach))
      for (int j : ext.interior) detail::place_by_projection(s, straight.row(j).transpose(), uv2, pts, j);
    else if (params_.placement == NodePlacement::Springs)
      out.fallback = !detail::optimise_on_surface(s, shape, P, params_.node_set, uv2, pts, params_.spring_iterations,
                                                  params_.tolerance * size);
    else
      for (int j : ext.interior) pts.row(j) = s.point(uv2.row(j).transpose()).transpose();
    for (int j : ext.interior) {
      X.row(j) = pts.row(j);
      out.att[j] = {CadAttachment::Surface, place.id, uv2(j, 0), uv2(j, 1)};
      out.moved = std::max(out.moved, (straight.row(j) - X.row(j)).norm());
    }
  }
  out.x = std::move(X);
  return out;
}

void Curver::curve_faces(const std::vector<char>& on_boundary) {
  const int P = params_.order;
  face_stride_ = static_cast<std::size_t>(mesh::face_interior_count(4, P));
  face_interior_.assign(in_.faces().size() * face_stride_, mesh::kNoNode);
  // A block's nodes are made while the next block is placed: place_face reads the input mesh, the
  // CAD, the edges' nodes (their room reserved in run: adding nodes never moves them) and
  // edge_node_cad_, nothing the adding writes.
  detail::overlapped_blocks(
      in_.faces().size(), model_.thread_safe(), kBlock, [](std::size_t, std::size_t) {},
      [&](std::size_t f) {
        check_stop();
        return !face_taken_.empty() && face_taken_[f] ? taken_face(f) : place_face(f, on_boundary[f] != 0);
      },
      [&](std::size_t f, const FaceNodes& placed) {
        const Shape shape = in_.faces()[f].num_vertices == 3 ? Shape::Triangle : Shape::Quadrilateral;
        const detail::HarmonicExtension& ext = detail::harmonic_extension(shape, P, params_.node_set);
        if (record_) record_->faces[f] = {static_cast<std::int8_t>(placed.place), placed.fallback, placed.moved};
        if (ext.interior.empty()) return;
        note(placed);
        stats_.faces_on_surfaces += placed.place == CadPlace::Surface ? 1 : 0;
        // Interior nodes in the face's own canonical order (interior slot, orientation code 0).
        const mesh::NodeLayout& layout = mesh::node_layout(shape, P);
        if (out_.num_nodes() + ext.interior.size() > out_.nodes().capacity())
          throw std::logic_error("curve_mesh: no room left for the nodes of face " + std::to_string(f));
        for (int j : ext.interior)
          face_interior_[f * face_stride_ + static_cast<std::size_t>(layout.slots[j].slot[0])] =
              out_.add_node(placed.x.row(j).transpose(), placed.att.empty() ? CadAttachment{} : placed.att[j]);
      },
      face_progress_, "faces");
}

std::vector<NodeId> Curver::element_node_ids(std::size_t e) const {
  const mesh::Element& el = in_.elements()[e];
  const mesh::NodeLayout& layout = mesh::node_layout(el.shape, params_.order);
  std::vector<NodeId> ids(layout.slots.size(), mesh::kNoNode);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const mesh::NodeSlot& s = layout.slots[i];
    switch (s.kind) {
      case mesh::NodeSlot::Vertex: ids[i] = el.vertices[s.local]; break;
      case mesh::NodeSlot::Edge: ids[i] = edge_node(el.edges[s.local], s.slot[(el.edge_reversed >> s.local) & 1]); break;
      case mesh::NodeSlot::Face: ids[i] = face_node(el.faces[s.local], s.slot[el.face_orientation[s.local]]); break;
      case mesh::NodeSlot::Interior: break;
    }
  }
  return ids;
}

mesh::Mesh Curver::run(CurvingStats* stats) {
  if (in_.order() != 1)
    throw std::invalid_argument("curve_mesh: the input mesh must be linear (order 1), it has order " +
                                std::to_string(in_.order()));
  if (const auto bad = params::violation(params_, curving_keys(), "highorder"))
    throw std::invalid_argument("curve_mesh: " + *bad);
  if (!(params_.pole_reach >= 0.0))
    throw std::invalid_argument("curve_mesh: CurvingParams::pole_reach = " + std::to_string(params_.pole_reach) +
                                " must be >= 0");
  if (!(params_.tolerance > 0.0))
    throw std::invalid_argument("curve_mesh: CurvingParams::tolerance = " + std::to_string(params_.tolerance) +
                                " must be > 0");

  for (int s = 0; s < model_.num_surfaces(); ++s) {
    poles_.push_back(detail::surface_poles(model_, s));
    surface_charts_.push_back({detail::kink_chart(model_.surface(s), 0), detail::kink_chart(model_.surface(s), 1)});
    stats_.kinked_surfaces += surface_charts_.back()[0].identity() && surface_charts_.back()[1].identity() ? 0 : 1;
  }
  for (int c = 0; c < model_.num_curves(); ++c) {
    curve_charts_.push_back(detail::kink_chart(model_.curve(c)));
    stats_.kinked_curves += curve_charts_.back().identity() ? 0 : 1;
  }
  // Room for every node the curving makes, reserved once: the faces' and the volumes' nodes are
  // placed from nodes made before while later ones are added, which must never move them.
  // (Counted from the node layouts, not the harmonic extensions: those are built on first use
  // inside the parallel loops, where Eigen's products run on one thread; built here, outside them,
  // they would take Eigen's multi-threaded blocking and differ in the last bits.)
  std::size_t all_nodes = in_.num_nodes() + in_.edges().size() * static_cast<std::size_t>(params_.order - 1);
  for (const mesh::Face& face : in_.faces())
    all_nodes += static_cast<std::size_t>(mesh::face_interior_count(face.num_vertices, params_.order));
  std::size_t interior_nodes = 0;
  for (const mesh::Element& el : in_.elements()) interior_nodes += interior_node_count(el.shape, params_.order);
  out_.reserve_nodes(all_nodes + interior_nodes);
  out_.reserve_elements(in_.elements().size(), interior_nodes);
  out_.copy_nodes(in_);
  for (const std::string& g : in_.group_names()) out_.group_index(g);
  out_.copy_regions_from(in_);
  std::vector<char> edge_on_boundary(in_.edges().size(), 0), face_on_boundary(in_.faces().size(), 0);
  for (const mesh::BoundaryFace& bf : in_.boundary_faces()) {
    face_on_boundary[bf.face] = 1;
    for (int k = 0; k < num_vertices(bf.shape); ++k) edge_on_boundary[bf.edges[k]] = 1;
  }
  const double edges = static_cast<double>(in_.edges().size()), faces = static_cast<double>(in_.faces().size());
  const double all = std::max(1.0, edges + faces + static_cast<double>(in_.elements().size()));
  edge_progress_ = progress_part(progress_, 0.0, edges / all);
  face_progress_ = progress_part(progress_, edges / all, (edges + faces) / all);
  volume_progress_ = progress_part(progress_, (edges + faces) / all, 1.0);
  if (record_) {
    record_->edges.assign(in_.edges().size(), {});
    record_->faces.assign(in_.faces().size(), {});
    record_->edge_on_boundary = edge_on_boundary;
    record_->face_on_boundary = face_on_boundary;
  }
  choose_taken(edge_on_boundary, face_on_boundary);
  curve_edges(edge_on_boundary);
  curve_faces(face_on_boundary);
  // The same elements in the same order: the input's edges and faces, now owning these nodes.
  out_.adopt_entities(in_, edge_interior_, face_interior_, face_stride_);

  // Volume interiors: harmonic extensions in parallel (no CAD), then the nodes in element order; a
  // block's nodes and elements are made while the next block is extended, which reads the edges'
  // and faces' nodes only: their room was reserved up front, so that adding them never moves those.
  const int P = params_.order;
  const std::size_t num_elements = in_.elements().size();
  struct VolumeNodes {
    std::vector<NodeId> ids;  // canonical, kNoNode for the interior until made
    Eigen::MatrixXd x;        // (nodes, 3), interior rows filled
  };
  detail::overlapped_blocks(
      num_elements, true, kBlock, [](std::size_t, std::size_t) {},
      [&](std::size_t e) {
        check_stop();
        const detail::HarmonicExtension& ext = detail::inner_extension(in_.elements()[e].shape, P, params_.node_set);
        if (ext.interior.empty()) return VolumeNodes{};  // all its nodes are its entities'
        VolumeNodes v{element_node_ids(e), {}};
        v.x = Eigen::MatrixXd::Zero(v.ids.size(), 3);
        if (!element_taken_.empty() && element_taken_[e]) {  // the interior rows, as placed ahead
          const std::vector<NodeId> ids = ahead_->curved.element_nodes(e);
          for (int j : ext.interior) v.x.row(j) = ahead_->curved.node(ids[j]).transpose();
          return v;
        }
        for (int j : ext.boundary) v.x.row(j) = out_.node(v.ids[j]).transpose();
        extend_harmonically(ext, v.x);
        return v;
      },
      [&](std::size_t e, VolumeNodes& v) {
        const Shape shape = in_.elements()[e].shape;
        const std::vector<int>& interior = detail::inner_extension(shape, P, params_.node_set).interior;
        // Never reallocate under the threads reading the nodes (the room was counted above).
        if (out_.num_nodes() + interior.size() > out_.nodes().capacity())
          throw std::logic_error("curve_mesh: no room left for the inner nodes of element " + std::to_string(e));
        thread_local std::vector<NodeId> inner;  // the interior nodes in canonical order
        inner.clear();
        for (int j : interior) inner.push_back(out_.add_node(v.x.row(j).transpose()));
        out_.add_element_adopted(in_, e, inner);
      },
      volume_progress_, "volumes");
  std::vector<NodeId> ids;
  for (std::size_t b = 0; b < in_.boundary_faces().size(); ++b) {
    const mesh::BoundaryFace& bf = in_.boundary_faces()[b];
    planar_nodes(bf.shape, bf.vertices.data(), bf.edges.data(), bf.face, bf.face_orientation, ids);
    out_.add_boundary_face(in_.group_names()[bf.group], bf.shape, ids);
  }
  if (stats) *stats = stats_;
  return std::move(out_);
}

}  // namespace

const params::Table<CurvingParams>& curving_keys() {
  static const params::Table<CurvingParams> table = {
      params::integer("order", &CurvingParams::order, "[1, 8]",
                      "polynomial order P; above 1 the boundary nodes are placed on the CAD"),
      params::choice("node_set", &CurvingParams::node_set,
                     {{"gll", NodeSet::GLL}, {"equispaced", NodeSet::Equispaced}}, "node placement inside elements"),
      params::choice("node_placement", &CurvingParams::placement,
                     {{"parameter", NodePlacement::Parameter}, {"springs", NodePlacement::Springs}},
                     "how the nodes of boundary edges and faces are placed on the CAD"),
      params::integer("spring_iterations", &CurvingParams::spring_iterations, "[1, 10000]",
                      "springs: Gauss-Newton iterations per edge or face before it falls back"),
  };
  return table;
}

mesh::Mesh curve_mesh(const mesh::Mesh& linear, const cad::Model& model, const CurvingParams& params,
                      CurvingStats* stats, const ProgressCallback& progress, const CurvedAhead* ahead,
                      std::size_t* taken) {
  Curver curver(linear, model, params, progress, ahead);
  mesh::Mesh curved = curver.run(stats);
  if (taken) *taken = curver.taken();
  return curved;
}

CurvedAhead curve_ahead(const mesh::Mesh& so_far, const cad::Model& model, const CurvingParams& params,
                        const std::atomic<bool>& stop) {
  const detail::OneThreadScope one_thread;  // beside TetGen's process, not over both cores
  CurvedAhead ahead;
  try {
    Curver curver(so_far, model, params, {}, nullptr, &ahead, &stop);
    ahead.curved = curver.run(nullptr);
  } catch (...) {  // stopped, or the curving fails: the later curving says why
    return CurvedAhead();
  }
  ahead.linear_nodes = so_far.num_nodes();
  return ahead;
}

}  // namespace semimesh::ho
