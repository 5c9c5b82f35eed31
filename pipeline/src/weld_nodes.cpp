#include "semimesh/pipeline/weld_nodes.hpp"

#include "semimesh/ho/curving/extend_inward.hpp"
#include "semimesh/mesh/node_layout.hpp"
#include "semimesh/mesh/open_faces.hpp"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <stdexcept>
#include <string>
#include <system_error>
#include <unordered_map>
#include <utility>
#include <vector>

namespace semimesh::pipeline {
namespace {

// Points hashed by cells of 2.5 x the tolerance: the points within tolerance of x lie in x's cell
// and, per axis, the neighbour on the side of the cell's half x is in (a margin of a quarter of the
// tolerance beyond rounding), so 8 cells are probed, not 27. A cell keeps a chain of its points'
// entries (no list allocated per cell); the cells sit in an open-addressing table (a node-based
// map's allocation and pointer chase per cell were most of the weld's search).
class PointIndex {
 public:
  PointIndex(const mesh::Mesh& mesh, double tolerance, std::size_t expected)
      : mesh_(mesh), tolerance_(tolerance), cell_size_(2.5 * tolerance) {
    std::size_t capacity = 16;
    while (capacity < 2 * expected) capacity *= 2;
    cells_.assign(capacity, CellSlot{});
    entries_.reserve(expected);
  }

  /// The node indexed first among those within tolerance of v's point (v itself if none), then
  /// indexes v.
  mesh::NodeId find_or_add(mesh::NodeId v) {
    const Eigen::Vector3d& x = mesh_.node(v);
    Cell c{};
    std::array<long long, 3> side{};
    for (int k = 0; k < 3; ++k) {
      const double scaled = x[k] / cell_size_, cell = std::floor(scaled);
      c[k] = static_cast<long long>(cell);
      side[k] = scaled - cell < 0.5 ? -1 : 1;
    }
    std::uint32_t first = kNone;  // the earliest matching entry: entries are in insertion order
    for (int corner = 0; corner < 8; ++corner) {
      const Cell probe{c[0] + (corner & 1 ? side[0] : 0), c[1] + (corner & 2 ? side[1] : 0),
                       c[2] + (corner & 4 ? side[2] : 0)};
      const CellSlot& slot = cells_[place_of(probe)];
      if (slot.head == kNone) continue;
      for (std::uint32_t e = slot.head; e != kNone; e = entries_[e].next) {
        const mesh::NodeId w = entries_[e].node;
        if (e < first && (w == v || (mesh_.node(w) - x).norm() <= tolerance_)) first = e;
      }
    }
    if (first != kNone) return entries_[first].node;
    const auto entry = static_cast<std::uint32_t>(entries_.size());
    CellSlot* slot = &cells_[place_of(c)];
    if (slot->head == kNone) {  // a new cell: keep the table at most half full
      if (2 * (++used_cells_) > cells_.size()) {
        grow();
        slot = &cells_[place_of(c)];
      }
      slot->cell = c;
    }
    entries_.push_back({v, slot->head});
    slot->head = entry;
    return v;
  }

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu;
  using Cell = std::array<long long, 3>;
  struct CellSlot {
    Cell cell{};
    std::uint32_t head = kNone;  // the cell's last entry; kNone: a free slot
  };
  struct Entry {
    mesh::NodeId node;
    std::uint32_t next;  // the cell's previous entry, kNone at its first
  };
  static std::uint64_t hash(const Cell& c) {
    return mesh::IdTable::mix(static_cast<std::uint64_t>(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL));
  }
  // The slot holding cell c, or the free slot where it would go (linear probing).
  std::size_t place_of(const Cell& c) const {
    const std::size_t mask = cells_.size() - 1;
    std::size_t i = hash(c) & mask;
    while (cells_[i].head != kNone && cells_[i].cell != c) i = (i + 1) & mask;
    return i;
  }
  void grow() {
    std::vector<CellSlot> old(2 * cells_.size(), CellSlot{});
    old.swap(cells_);
    for (const CellSlot& s : old)
      if (s.head != kNone) cells_[place_of(s.cell)] = s;
  }
  const mesh::Mesh& mesh_;
  double tolerance_, cell_size_;
  std::vector<CellSlot> cells_;  // a power of two of slots
  std::size_t used_cells_ = 0;
  std::vector<Entry> entries_;
};

// Where the far field's entities meet the split's: an edge or face whose vertices were welded onto
// those of another (`theirs`, the entity of the element seen first) takes its inner nodes, each
// matched by its place in the entity (order along the edge, slot in the face under the
// orientation relating the two), never by distance: the far field's pre-cut skin quads are
// straight, the split's pieces of a curved rear interface are not, and the bulge can exceed the
// spacing of the nodes (order 3 on an 8-layer split at the sharp trailing edge's tip).
struct Snapped {
  std::vector<char> edge_moved, face_moved;  ///< [edges], [faces]: inner nodes now at other points
  double largest_move = 0.0;
};

std::vector<mesh::NodeId> pool_part(const std::vector<mesh::NodeId>& pool, std::size_t first, std::size_t count) {
  return std::vector<mesh::NodeId>(pool.begin() + first, pool.begin() + first + count);
}

// to[mine[k]] = to[theirs[k]] for every k; whether a node then sits elsewhere (beyond tolerance).
bool take_nodes(const mesh::Mesh& mesh, const std::vector<mesh::NodeId>& mine, const std::vector<mesh::NodeId>& theirs,
                double tolerance, std::vector<mesh::NodeId>& to, double& largest_move) {
  bool moved = false;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    to[mine[k]] = to[theirs[k]];
    const double d = (mesh.node(to[mine[k]]) - mesh.node(mine[k])).norm();
    largest_move = std::max(largest_move, d);
    moved = moved || d > tolerance;
  }
  return moved;
}

// The faces' part of snap_welded_entities: each face whose welded vertices are another's takes its inner nodes.
void snap_faces(const mesh::Mesh& mesh, double tolerance, std::vector<mesh::NodeId>& to, std::vector<char>& face_moved,
                double& largest_move) {
  const int P = mesh.order();
  std::vector<mesh::NodeId> welded;  // one face's vertices after the weld, reused: most faces do not move
  for (std::size_t f = 0; f < mesh.faces().size(); ++f) {
    const mesh::Face& face = mesh.faces()[f];
    const int n = face.num_vertices;
    welded.assign(face.vertices.begin(), face.vertices.begin() + n);
    bool moved = false;
    for (mesh::NodeId& v : welded) moved = moved || to[v] != v, v = to[v];
    if (!moved) continue;
    const long other = mesh.find_face(welded);
    if (other < 0 || static_cast<std::size_t>(other) == f) continue;
    const mesh::Face& their_face = mesh.faces()[other];
    const int code = mesh::face_orientation_code(welded.data(), their_face.vertices.data(), n);
    if (code < 0)
      throw std::logic_error("weld: face " + std::to_string(f) + " welds onto face " + std::to_string(other) +
                             " but no rotation or reflection relates their vertices");
    // Face f seen with its welded vertices is face `other` seen with orientation `code`.
    const mesh::NodeLayout& layout = mesh::node_layout(n == 3 ? ho::Shape::Triangle : ho::Shape::Quadrilateral, P);
    std::vector<mesh::NodeId> mine, theirs;
    for (const mesh::NodeSlot& slot : layout.slots)
      if (slot.kind == mesh::NodeSlot::Face) {
        mine.push_back(mesh.face_pool()[face.first_node + slot.slot[0]]);
        theirs.push_back(mesh.face_pool()[their_face.first_node + slot.slot[code]]);
      }
    face_moved[f] = take_nodes(mesh, mine, theirs, tolerance, to, largest_move);
  }
}

// The edges' inner nodes and the faces' on two threads: each side writes `to` only at its own
// entities' inner nodes and reads it there and at vertices, which neither writes.
Snapped snap_welded_entities(const mesh::Mesh& mesh, double tolerance, std::vector<mesh::NodeId>& to) {
  const int P = mesh.order();
  Snapped out{std::vector<char>(mesh.edges().size(), 0), std::vector<char>(mesh.faces().size(), 0), 0.0};
  if (P < 2) return out;
  double largest_face_move = 0.0;
  std::future<void> faces;  // std::async's: waits in its destructor, also when the edges' side throws
  try {
    faces = std::async(std::launch::async, [&] { snap_faces(mesh, tolerance, to, out.face_moved, largest_face_move); });
  } catch (const std::system_error&) {  // no thread to be had: after the edges, on this one
  }
  for (std::size_t e = 0; e < mesh.edges().size(); ++e) {
    const mesh::Edge& edge = mesh.edges()[e];
    const mesh::NodeId a = to[edge.vertices[0]], b = to[edge.vertices[1]];
    if (a == edge.vertices[0] && b == edge.vertices[1]) continue;
    const long other = mesh.find_edge(a, b);
    if (other < 0 || static_cast<std::size_t>(other) == e) continue;
    std::vector<mesh::NodeId> theirs = pool_part(mesh.edge_pool(), mesh.edges()[other].first_node, P - 1);
    if (mesh.edges()[other].vertices[0] != a) std::reverse(theirs.begin(), theirs.end());
    out.edge_moved[e] = take_nodes(mesh, pool_part(mesh.edge_pool(), edge.first_node, P - 1), theirs, tolerance, to,
                                   out.largest_move);
  }
  if (faces.valid())
    faces.get();
  else
    snap_faces(mesh, tolerance, to, out.face_moved, largest_face_move);
  out.largest_move = std::max(out.largest_move, largest_face_move);
  return out;
}


// The points after the weld: node v at to[v]'s, or where `moved` puts it.
Eigen::MatrixXd welded_points(const mesh::Mesh& mesh, const std::vector<mesh::NodeId>& ids,
                              const std::vector<mesh::NodeId>& to,
                              const std::unordered_map<mesh::NodeId, Eigen::Vector3d>& moved) {
  Eigen::MatrixXd x(ids.size(), 3);
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const mesh::NodeId v = to[ids[k]];
    const auto it = moved.find(v);
    x.row(k) = (it == moved.end() ? mesh.node(v) : it->second).transpose();
  }
  return x;
}

// The far field's faces and elements around the snapped entities take the inner nodes curving
// would have given them had their edges been curved then (their harmonic extension, as
// ho::curve_mesh): a face off the CAD with a snapped edge, then every element with a moved edge or
// face. Returns the new points by node id.
std::unordered_map<mesh::NodeId, Eigen::Vector3d> carry_inwards(const mesh::Mesh& mesh, const Snapped& snapped,
                                                                const std::vector<mesh::NodeId>& to) {
  const int P = mesh.order();
  std::unordered_map<mesh::NodeId, Eigen::Vector3d> moved;
  if (std::none_of(snapped.edge_moved.begin(), snapped.edge_moved.end(), [](char c) { return c != 0; })) return moved;
  std::vector<char> face_moved = snapped.face_moved, on_cad(mesh.faces().size(), 0);
  for (const mesh::BoundaryFace& b : mesh.boundary_faces()) on_cad[b.face] = 1;
  std::vector<char> ends(mesh.num_nodes(), 0);  // the vertices of moved edges: few, a cheap filter
  for (std::size_t e = 0; e < mesh.edges().size(); ++e)
    if (snapped.edge_moved[e]) ends[mesh.edges()[e].vertices[0]] = ends[mesh.edges()[e].vertices[1]] = 1;
  for (std::size_t f = 0; f < mesh.faces().size(); ++f) {
    const mesh::Face& face = mesh.faces()[f];
    const int n = face.num_vertices;
    if (face_moved[f] || on_cad[f]) continue;
    if (std::count_if(face.vertices.begin(), face.vertices.begin() + n, [&](mesh::NodeId v) { return ends[v]; }) < 2)
      continue;
    bool touched = false;
    for (int k = 0; k < n; ++k) {
      const long e = mesh.find_edge(face.vertices[k], face.vertices[(k + 1) % n]);
      touched = touched || (e >= 0 && snapped.edge_moved[e]);
    }
    if (!touched) continue;
    const ho::Shape shape = n == 3 ? ho::Shape::Triangle : ho::Shape::Quadrilateral;
    const std::vector<mesh::NodeId> ids = mesh.face_nodes(f);
    Eigen::MatrixXd x = welded_points(mesh, ids, to, moved);
    ho::extend_inward(shape, P, mesh.node_set(), x);
    const mesh::NodeLayout& layout = mesh::node_layout(shape, P);
    for (std::size_t k = 0; k < ids.size(); ++k)
      if (layout.slots[k].kind == mesh::NodeSlot::Face) moved[ids[k]] = x.row(k).transpose();
    face_moved[f] = 1;
  }
  for (std::size_t e = 0; e < mesh.elements().size(); ++e) {
    const mesh::Element& el = mesh.elements()[e];
    bool touched = false;
    for (std::size_t k = 0; k < ho::edges(el.shape).size(); ++k) touched = touched || snapped.edge_moved[el.edges[k]];
    for (std::size_t k = 0; k < ho::faces(el.shape).size(); ++k) touched = touched || face_moved[el.faces[k]];
    if (!touched) continue;
    const std::vector<mesh::NodeId> ids = mesh.element_nodes(e);
    Eigen::MatrixXd x = welded_points(mesh, ids, to, moved);
    ho::extend_inward(el.shape, P, mesh.node_set(), x);
    const mesh::NodeLayout& layout = mesh::node_layout(el.shape, P);
    for (std::size_t k = 0; k < ids.size(); ++k)
      if (layout.slots[k].kind == mesh::NodeSlot::Interior) moved[ids[k]] = x.row(k).transpose();
  }
  return moved;
}

// [num_nodes()]: 1 at the vertices of the open faces. Two copies of one face are both open until
// welded, so only these vertices can weld; the rest of the mesh is closed (its vertices need no
// search, and no thin element there is collapsed).
std::vector<char> open_face_vertices(const mesh::Mesh& mesh) {
  std::vector<char> open(mesh.num_nodes(), 0);
  for (const mesh::OpenFace& f : mesh::open_faces(mesh))
    for (int k = 0; k < mesh.faces()[f.face].num_vertices; ++k) open[mesh.faces()[f.face].vertices[k]] = 1;
  return open;
}

// to[v]: for a vertex of an open face, the open-face vertex seen first (in element order) within
// tolerance of its point; else v.
std::vector<mesh::NodeId> coincident_vertices(const mesh::Mesh& mesh, double tolerance) {
  const std::size_t n = mesh.num_nodes();
  std::vector<mesh::NodeId> to(n);
  for (std::size_t v = 0; v < n; ++v) to[v] = static_cast<mesh::NodeId>(v);
  std::vector<char> candidate = open_face_vertices(mesh);
  PointIndex vertices(mesh, tolerance,
                      static_cast<std::size_t>(std::count(candidate.begin(), candidate.end(), 1)) + 16);
  for (const mesh::Element& e : mesh.elements())
    for (int k = 0; k < ho::num_vertices(e.shape); ++k) {
      const mesh::NodeId v = e.vertices[k];
      if (!candidate[v]) continue;
      candidate[v] = 0;  // indexed once, at its first element
      to[v] = vertices.find_or_add(v);
    }
  return to;
}

// Runs `beside` on a thread of its own at the lowest priority (Linux: a thread's own nice value)
// while it lives; the destructor tells it to stop and waits for it.
class BesideThread {
 public:
  BesideThread(const BesideRebuild& beside, const mesh::Mesh& mesh) {
    if (!beside) return;
    try {
      run_ = std::async(std::launch::async, [&beside, &mesh, this] {
        ::setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 19);
        try {
          beside(mesh, rebuilt_, stop_);
        } catch (...) {  // speculative: the stages after do what it did not
        }
      });
    } catch (const std::system_error&) {  // no thread to be had: the weld alone
    }
  }
  ~BesideThread() {
    stop_.store(true);
    if (run_.valid()) run_.wait();
  }
  BesideThread(const BesideThread&) = delete;
  BesideThread& operator=(const BesideThread&) = delete;
  std::atomic<std::size_t>* rebuilt() { return &rebuilt_; }

 private:
  std::atomic<std::size_t> rebuilt_{0};
  std::atomic<bool> stop_{false};
  std::future<void> run_;
};

}  // namespace

Welded weld_coincident_nodes(mesh::Mesh mesh, double tolerance, const ProgressCallback& progress,
                             const BesideRebuild& beside) {
  const auto report = [&](double fraction, const char* step) {
    if (progress) progress(fraction, step);
  };
  Welded out;
  report(0.0, "vertices");
  // Coincident vertices by their points; the nodes inside edges and faces by topology (above).
  std::vector<mesh::NodeId> to = coincident_vertices(mesh, tolerance);
  report(0.1, "edges and faces");
  const Snapped snapped = snap_welded_entities(mesh, tolerance, to);
  out.largest_move = snapped.largest_move;
  for (std::size_t v = 0; v < to.size(); ++v) out.merged += to[v] != v;
  report(0.15, "inwards");
  const auto moved = carry_inwards(mesh, snapped, to);
  out.carried = moved.size();
  report(0.2, "mesh");
  {
    BesideThread beside_rebuild(beside, mesh);
    out.entities = mesh.replace_nodes(std::move(to), moved, [&](double done) { report(0.2 + 0.8 * done, "mesh"); },
                                      beside_rebuild.rebuilt());
  }
  out.mesh = std::move(mesh);
  return out;
}

}  // namespace semimesh::pipeline
