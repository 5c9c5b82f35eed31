#include "semimesh/mesh/node_layout.hpp"

#include <Eigen/Dense>

#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace semimesh::mesh {
namespace {

constexpr double kTol = 1e-9;

/// Weights of a point of a face on the face's vertices: barycentric on triangles, bilinear on
/// (parallelogram) quads. Two nodes of a face are the same node iff their weights agree, whatever
/// the vertex order, which is what makes orientation matching purely combinatorial.
using FaceWeights = std::array<double, 4>;

bool close(const FaceWeights& a, const FaceWeights& b) {
  for (int k = 0; k < 4; ++k)
    if (std::abs(a[k] - b[k]) > 1e-7) return false;
  return true;
}

/// Parameter t in (0,1) of x on the open segment a-b, or -1.
double segment_parameter(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  const double t = (x - a).dot(d) / d.squaredNorm();
  if ((x - a - t * d).norm() > kTol || t <= kTol || t >= 1.0 - kTol) return -1.0;
  return t;
}

/// Face weights of x strictly inside the face with reference vertices `v` (3 or 4), or false.
bool face_weights(const Eigen::Vector3d& x, const std::vector<Eigen::Vector3d>& v, FaceWeights& w) {
  const bool quad = v.size() == 4;
  Eigen::Matrix<double, 3, 2> m;
  m.col(0) = v[1] - v[0];
  m.col(1) = (quad ? v[3] : v[2]) - v[0];
  const Eigen::Vector2d st = m.colPivHouseholderQr().solve(x - v[0]);
  if ((m * st - (x - v[0])).norm() > kTol) return false;
  const double s = st[0], t = st[1];
  if (s <= kTol || t <= kTol) return false;
  if (quad) {
    if (s >= 1.0 - kTol || t >= 1.0 - kTol) return false;
    w = {(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t};
  } else {
    if (s + t >= 1.0 - kTol) return false;
    w = {1 - s - t, s, t, 0.0};
  }
  return true;
}

std::vector<std::vector<int>> local_faces(ho::Shape shape) {
  if (ho::dimension(shape) == 2) {
    std::vector<int> all(ho::num_vertices(shape));
    for (int k = 0; k < static_cast<int>(all.size()); ++k) all[k] = k;
    return {all};
  }
  return ho::faces(shape);
}

/// Weights of the interior nodes of a face element (tri/quad of order P) in its canonical order,
/// relative to its own vertices 0..n-1.
std::vector<FaceWeights> face_entity_weights(int num_face_vertices, int order) {
  const ho::Shape face_shape = num_face_vertices == 3 ? ho::Shape::Triangle : ho::Shape::Quadrilateral;
  const Eigen::MatrixX3d ref = ho::reference_nodes(face_shape, order, ho::NodeSet::Equispaced);
  std::vector<Eigen::Vector3d> corners;
  for (int k = 0; k < num_face_vertices; ++k) corners.push_back(ref.row(k).transpose());
  const int first = num_face_vertices + num_face_vertices * edge_interior_count(order);
  std::vector<FaceWeights> out;
  for (int i = first; i < ref.rows(); ++i) {
    FaceWeights w{};
    if (!face_weights(ref.row(i).transpose(), corners, w))
      throw std::logic_error("node_layout: face node " + std::to_string(i) + " of " + ho::to_string(face_shape) +
                             " order " + std::to_string(order) + " is not inside the face");
    out.push_back(w);
  }
  return out;
}

// Whether the layout's slots come in the blocks NodeLayout::slots describes.
bool slots_in_blocks(const NodeLayout& layout) {
  const ho::Shape shape = layout.shape;
  const int P = layout.order, nv = ho::num_vertices(shape);
  std::size_t at = 0;
  const auto next = [&](NodeSlot::Kind kind, int local, int forward, int backward) {
    if (at >= layout.slots.size()) return false;
    const NodeSlot& s = layout.slots[at++];
    return s.kind == kind && s.local == local && s.slot[0] == forward && (backward < 0 || s.slot[1] == backward);
  };
  for (int v = 0; v < nv; ++v)
    if (!next(NodeSlot::Vertex, v, 0, -1)) return false;
  for (int e = 0; e < static_cast<int>(ho::edges(shape).size()); ++e)
    for (int j = 0; j < P - 1; ++j)
      if (!next(NodeSlot::Edge, e, j, P - 2 - j)) return false;
  const bool volume = ho::dimension(shape) == 3;
  for (int f = 0; f < (volume ? static_cast<int>(ho::faces(shape).size()) : 1); ++f) {
    const int n = volume ? static_cast<int>(ho::faces(shape)[f].size()) : nv;
    for (int j = 0; j < face_interior_count(n, P); ++j)
      if (!next(NodeSlot::Face, f, j, -1)) return false;
  }
  for (int j = 0; j < layout.num_interior; ++j)
    if (!next(NodeSlot::Interior, 0, j, -1)) return false;
  return at == layout.slots.size();
}

std::unique_ptr<NodeLayout> build_layout(ho::Shape shape, int order) {
  auto layout = std::make_unique<NodeLayout>();
  layout->shape = shape;
  layout->order = order;
  const Eigen::MatrixX3d ref = ho::reference_nodes(shape, order, ho::NodeSet::Equispaced);
  const int nv = ho::num_vertices(shape);
  std::vector<Eigen::Vector3d> vert(nv);
  for (int k = 0; k < nv; ++k) vert[k] = ref.row(k).transpose();

  const Eigen::MatrixX3d seg = ho::reference_nodes(ho::Shape::Segment, order, ho::NodeSet::Equispaced);
  std::vector<double> edge_t;  // parameters of the stored edge slots, shape (P-1)
  for (int i = 2; i < seg.rows(); ++i) edge_t.push_back(0.5 * (seg(i, 0) + 1.0));
  auto edge_slot = [&](double t) {
    for (std::size_t k = 0; k < edge_t.size(); ++k)
      if (std::abs(edge_t[k] - t) < 1e-7) return static_cast<std::uint16_t>(k);
    throw std::logic_error("node_layout: edge parameter " + std::to_string(t) + " matches no segment node");
  };

  const auto faces = local_faces(shape);
  const std::vector<FaceWeights> tri_w = face_entity_weights(3, order);
  const std::vector<FaceWeights> quad_w = face_entity_weights(4, order);

  for (int i = 0; i < ref.rows(); ++i) {
    const Eigen::Vector3d x = ref.row(i).transpose();
    NodeSlot slot;
    bool found = false;
    for (int k = 0; k < nv && !found; ++k)
      if ((x - vert[k]).norm() < kTol) {
        slot.kind = NodeSlot::Vertex;
        slot.local = static_cast<std::uint8_t>(k);
        found = true;
      }
    const auto& edges = ho::edges(shape);
    for (std::size_t e = 0; e < edges.size() && !found; ++e) {
      const double t = segment_parameter(x, vert[edges[e][0]], vert[edges[e][1]]);
      if (t < 0) continue;
      slot.kind = NodeSlot::Edge;
      slot.local = static_cast<std::uint8_t>(e);
      slot.slot[0] = edge_slot(t);
      slot.slot[1] = edge_slot(1.0 - t);
      found = true;
    }
    for (std::size_t f = 0; f < faces.size() && !found; ++f) {
      std::vector<Eigen::Vector3d> corners;
      for (int v : faces[f]) corners.push_back(vert[v]);
      FaceWeights local_w{};
      if (!face_weights(x, corners, local_w)) continue;
      const int n = static_cast<int>(corners.size());
      const auto& stored_w = n == 3 ? tri_w : quad_w;
      const auto& perms = face_permutations(n);
      for (std::size_t code = 0; code < perms.size(); ++code) {
        FaceWeights w{};
        for (int k = 0; k < n; ++k) w[perms[code][k]] = local_w[k];
        std::size_t j = 0;
        while (j < stored_w.size() && !close(stored_w[j], w)) ++j;
        if (j == stored_w.size())
          throw std::logic_error("node_layout: face node " + std::to_string(i) + " of " + ho::to_string(shape) +
                                 " matches no node of the face element");
        slot.slot[code] = static_cast<std::uint16_t>(j);
      }
      slot.kind = NodeSlot::Face;
      slot.local = static_cast<std::uint8_t>(f);
      found = true;
    }
    if (!found) {
      if (ho::dimension(shape) == 2)
        throw std::logic_error("node_layout: node " + std::to_string(i) + " of " + ho::to_string(shape) +
                               " lies on no vertex, edge or face");
      slot.kind = NodeSlot::Interior;
      slot.slot[0] = static_cast<std::uint16_t>(layout->num_interior++);
    }
    layout->slots.push_back(slot);
  }
  if (!slots_in_blocks(*layout))
    throw std::logic_error("node_layout: the nodes of the order-" + std::to_string(order) + " " + ho::to_string(shape) +
                           " are not in Gmsh's blocks (vertices, edges, faces, interior), which Mesh relies on");
  return layout;
}

}  // namespace

const std::vector<std::array<int, 4>>& face_permutations(int num_face_vertices) {
  static const std::vector<std::array<int, 4>> tri = {{0, 1, 2, -1}, {1, 2, 0, -1}, {2, 0, 1, -1},
                                                      {0, 2, 1, -1}, {2, 1, 0, -1}, {1, 0, 2, -1}};
  static const std::vector<std::array<int, 4>> quad = {{0, 1, 2, 3}, {1, 2, 3, 0}, {2, 3, 0, 1}, {3, 0, 1, 2},
                                                       {0, 3, 2, 1}, {3, 2, 1, 0}, {2, 1, 0, 3}, {1, 0, 3, 2}};
  if (num_face_vertices != 3 && num_face_vertices != 4)
    throw std::invalid_argument("face_permutations: a face has 3 or 4 vertices, got " +
                                std::to_string(num_face_vertices));
  return num_face_vertices == 3 ? tri : quad;
}

int face_orientation_code(const std::uint32_t* local, const std::uint32_t* stored, int n) {
  const auto& perms = face_permutations(n);
  for (std::size_t code = 0; code < perms.size(); ++code) {
    bool same = true;
    for (int k = 0; k < n && same; ++k) same = stored[perms[code][k]] == local[k];
    if (same) return static_cast<int>(code);
  }
  return -1;
}

int edge_interior_count(int order) { return order - 1; }

int face_interior_count(int num_face_vertices, int order) {
  return num_face_vertices == 3 ? (order - 1) * (order - 2) / 2 : (order - 1) * (order - 1);
}

const NodeLayout& node_layout(ho::Shape shape, int order) {
  if (shape == ho::Shape::Segment) throw std::invalid_argument("node_layout: segments are not mesh elements");
  if (order < 1 || order > ho::kMaxOrder)
    throw std::invalid_argument("node_layout: order " + std::to_string(order) + " outside [1, " +
                                std::to_string(ho::kMaxOrder) + "]");
  // Read on every element_nodes call, by several threads at once: a lock-free slot per (shape,
  // order), filled once under the mutex (layouts are never freed, so a pointer once seen stays valid).
  constexpr int kShapes = static_cast<int>(ho::Shape::Hexahedron) + 1;
  static std::array<std::atomic<const NodeLayout*>, kShapes*(ho::kMaxOrder + 1)> table{};
  std::atomic<const NodeLayout*>& slot = table[static_cast<int>(shape) * (ho::kMaxOrder + 1) + order];
  if (const NodeLayout* layout = slot.load(std::memory_order_acquire)) return *layout;
  static std::mutex mutex;
  static std::vector<std::unique_ptr<NodeLayout>> owned;
  const std::lock_guard<std::mutex> lock(mutex);
  if (const NodeLayout* layout = slot.load(std::memory_order_relaxed)) return *layout;
  owned.push_back(build_layout(shape, order));
  slot.store(owned.back().get(), std::memory_order_release);
  return *owned.back();
}

}  // namespace semimesh::mesh
