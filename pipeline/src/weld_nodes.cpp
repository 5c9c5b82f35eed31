#include "semimesh/pipeline/weld_nodes.hpp"

#include "semimesh/mesh/compact.hpp"
#include "semimesh/mesh/node_layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace semimesh::pipeline {
namespace {

// Points hashed by cells of size `tolerance`: an equal point lies in the same or a neighbouring cell.
class PointIndex {
 public:
  PointIndex(const mesh::Mesh& mesh, double tolerance) : mesh_(mesh), tolerance_(tolerance) {}

  /// The node already indexed within tolerance of v's point (v itself if none), then indexes v.
  mesh::NodeId find_or_add(mesh::NodeId v) {
    const Eigen::Vector3d& x = mesh_.node(v);
    const Cell c = cell_of(x);
    for (long long i = -1; i <= 1; ++i)
      for (long long j = -1; j <= 1; ++j)
        for (long long k = -1; k <= 1; ++k) {
          const auto it = cells_.find({c[0] + i, c[1] + j, c[2] + k});
          if (it == cells_.end()) continue;
          for (mesh::NodeId w : it->second)
            if (w == v || (mesh_.node(w) - x).norm() <= tolerance_) return w;
        }
    cells_[c].push_back(v);
    return v;
  }

 private:
  using Cell = std::array<long long, 3>;
  struct CellHash {
    std::size_t operator()(const Cell& c) const {
      return static_cast<std::size_t>(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
    }
  };
  Cell cell_of(const Eigen::Vector3d& x) const {
    return {static_cast<long long>(std::floor(x.x() / tolerance_)), static_cast<long long>(std::floor(x.y() / tolerance_)),
            static_cast<long long>(std::floor(x.z() / tolerance_))};
  }
  const mesh::Mesh& mesh_;
  double tolerance_;
  std::unordered_map<Cell, std::vector<mesh::NodeId>, CellHash> cells_;
};

// An edge or face whose vertices were all welded onto another entity's takes that entity's inner
// nodes, slot for slot (the edge's direction, the face's orientation code relating the two vertex
// orders): the far field's straight skin quads place theirs between their vertices, the split
// places its own where the interfaces, interpolated between the vertices', fall on the element's
// curved map; they differ inside the entity by more than round-off where the ratio varies (the
// wake) or the layer element's body edge is curved (a sharp trailing edge's tip end, where the
// quads over the curved wing stand bare). Taken by nearest point before, the pairing failed where
// that difference reached half the node spacing (a first layer 2e-4 thick, a body edge's sagitta
// 7e-5: the mesh rebuild's internal error).
void snap_welded_entities(const mesh::Mesh& mesh, std::vector<mesh::NodeId>& to) {
  const int P = mesh.order();
  if (P < 2) return;
  auto take = [&](mesh::NodeId mine, mesh::NodeId theirs) {
    if (to[mine] == mine) to[mine] = to[theirs];
  };
  for (std::size_t e = 0; e < mesh.edges().size(); ++e) {
    const mesh::Edge& edge = mesh.edges()[e];
    const mesh::NodeId a = to[edge.vertices[0]], b = to[edge.vertices[1]];
    if (a == edge.vertices[0] && b == edge.vertices[1]) continue;
    const long other = mesh.find_edge(a, b);
    if (other < 0 || static_cast<std::size_t>(other) == e) continue;
    const mesh::Edge& theirs = mesh.edges()[other];
    const bool same_way = theirs.vertices[0] == a;
    for (int i = 0; i < P - 1; ++i)
      take(mesh.edge_pool()[edge.first_node + i], mesh.edge_pool()[theirs.first_node + (same_way ? i : P - 2 - i)]);
  }
  for (std::size_t f = 0; f < mesh.faces().size(); ++f) {
    const mesh::Face& face = mesh.faces()[f];
    std::vector<mesh::NodeId> welded;
    bool moved = false;
    for (int k = 0; k < face.num_vertices; ++k) {
      welded.push_back(to[face.vertices[k]]);
      moved = moved || welded.back() != face.vertices[k];
    }
    if (!moved) continue;
    const long other = mesh.find_face(welded);
    if (other < 0 || static_cast<std::size_t>(other) == f) continue;
    const mesh::Face& theirs = mesh.faces()[other];
    const int code = mesh::face_orientation_code(welded.data(), theirs.vertices.data(), face.num_vertices);
    if (code < 0) continue;
    // Seen from this face's own vertex order (code 0), a node at slot[0] of this face's list sits
    // at slot[code] of theirs.
    const mesh::NodeLayout& layout =
        mesh::node_layout(face.num_vertices == 4 ? ho::Shape::Quadrilateral : ho::Shape::Triangle, P);
    for (const mesh::NodeSlot& s : layout.slots)
      if (s.kind == mesh::NodeSlot::Face)
        take(mesh.face_pool()[face.first_node + s.slot[0]], mesh.face_pool()[theirs.first_node + s.slot[code]]);
  }
}

}  // namespace

Welded weld_coincident_nodes(const mesh::Mesh& mesh, double tolerance, const ProgressCallback& progress) {
  const auto report = [&](double fraction, const char* step) {
    if (progress) progress(fraction, step);
  };
  const std::size_t n = mesh.num_nodes();
  std::vector<mesh::NodeId> to(n);
  for (std::size_t v = 0; v < n; ++v) to[v] = static_cast<mesh::NodeId>(v);
  Welded out{mesh::Mesh(mesh.order(), mesh.node_set()), 0};

  report(0.0, "vertices");
  // Coincident vertices first (few nodes); then all nodes of the elements touching one of them.
  std::vector<char> seen(n, 0), merged_vertex(n, 0);
  PointIndex vertices(mesh, tolerance);
  for (const mesh::Element& e : mesh.elements())
    for (int k = 0; k < ho::num_vertices(e.shape); ++k) {
      const mesh::NodeId v = e.vertices[k];
      if (seen[v]) continue;
      seen[v] = 1;
      const mesh::NodeId w = vertices.find_or_add(v);
      if (w != v) merged_vertex[v] = merged_vertex[w] = 1;
    }
  report(0.05, "nodes");
  PointIndex nodes(mesh, tolerance);
  std::vector<mesh::NodeId> list;
  std::fill(seen.begin(), seen.end(), 0);
  for (std::size_t e = 0; e < mesh.elements().size(); ++e) {
    const mesh::Element& el = mesh.elements()[e];
    bool touches = false;
    for (int k = 0; k < ho::num_vertices(el.shape); ++k) touches = touches || merged_vertex[el.vertices[k]];
    if (!touches) continue;
    mesh.element_nodes(e, list);
    for (mesh::NodeId v : list)
      if (!seen[v]) {
        seen[v] = 1;
        to[v] = nodes.find_or_add(v);
        if (to[v] != v) ++out.merged;
      }
  }

  report(0.15, "edges and faces");
  snap_welded_entities(mesh, to);
  report(0.2, "mesh");

  out.mesh = mesh::with_nodes_replaced(mesh, to, [&](double done) { report(0.2 + 0.8 * done, "mesh"); });
  return out;
}

}  // namespace semimesh::pipeline
