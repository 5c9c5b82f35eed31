// Mesh::replace_nodes without rebuilding the entities: the old edges, faces and pools renamed
// through the node map, the few whose welded vertices make them another's merged into it, and all
// of them renumbered and reframed as the rebuild (add_element, element by element) would have
// made them. Linear passes over arrays: the rebuild's hash lookup per element edge and face was
// most of the weld's time.
#include "semimesh/mesh/mesh.hpp"

#include "semimesh/mesh/node_layout.hpp"

#include "entity_keys.hpp"

#include <algorithm>
#include <array>
#include <future>
#include <system_error>
#include <map>
#include <unordered_map>

namespace semimesh::mesh {
namespace {

constexpr std::uint32_t kNone = IdTable::kNone;

// For a triangle (n = 3) or quadrilateral at `order` and each orientation code: pairs (k, j), the
// face's k-th interior node in the frame `code` makes of the stored one is the stored node j (the
// face layout's k-th face slot: slot[0], slot[code]).
using FrameSlots = std::array<std::vector<std::pair<int, int>>, 8>;

FrameSlots frame_slots(int n, int order) {
  const NodeLayout& layout = node_layout(n == 3 ? ho::Shape::Triangle : ho::Shape::Quadrilateral, order);
  FrameSlots slots;
  for (std::size_t code = 0; code < face_permutations(n).size(); ++code)
    for (const NodeSlot& s : layout.slots)
      if (s.kind == NodeSlot::Face) slots[code].emplace_back(s.slot[0], s.slot[code]);
  return slots;
}

// The face's interior nodes, from a pool at `first`, renamed by `to`, in the frame `code` makes of
// the stored one, into out[0, count).
void face_nodes_in_frame(const std::vector<NodeId>& pool, std::uint32_t first, const FrameSlots& slots, int code,
                         const std::vector<NodeId>& to, NodeId* out) {
  for (const auto& [k, j] : slots[code]) out[k] = to[pool[first + j]];
}

// Whether two ids of one element or face are equal (the rebuild refuses such an element).
bool repeats(const NodeId* v, int n) {
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      if (v[a] == v[b]) return true;
  return false;
}

}  // namespace

Mesh::EntityMerges Mesh::entity_merges(const std::vector<NodeId>& to) const {
  EntityMerges merges;
  // Entities whose vertices all stay keep distinct keys; one with a moved vertex takes the entity
  // that holds its new key and keeps it (its vertices stay: the weld's targets), else the first
  // other moved one with that key. (An entity holding that key whose own vertices move has
  // another key afterwards: a map that chains, v onto w and w elsewhere.)
  const auto stays = [&](const NodeId* v, int n) {
    for (int k = 0; k < n; ++k)
      if (to[v[k]] != v[k]) return false;
    return true;
  };
  std::unordered_map<std::uint64_t, std::uint32_t> moved_edges;
  for (std::uint32_t e = 0; e < edges_.size(); ++e) {
    const NodeId a = to[edges_[e].vertices[0]], b = to[edges_[e].vertices[1]];
    if (a == edges_[e].vertices[0] && b == edges_[e].vertices[1]) continue;
    if (a == b) {
      merges.collapsed = true;
      continue;
    }
    const long other = find_edge(a, b);
    if (other >= 0 && stays(edges_[other].vertices.data(), 2)) {
      merges.edges.emplace(e, static_cast<std::uint32_t>(other));
    } else {
      const auto [it, fresh] = moved_edges.try_emplace(detail::edge_key(a, b), e);
      if (!fresh) merges.edges.emplace(e, it->second);
    }
  }
  std::map<std::array<NodeId, 4>, std::uint32_t> moved_faces;
  std::vector<NodeId> mapped;
  for (std::uint32_t f = 0; f < faces_.size(); ++f) {
    const Face& face = faces_[f];
    mapped.assign(face.vertices.begin(), face.vertices.begin() + face.num_vertices);
    bool moved = false;
    for (NodeId& v : mapped) moved = moved || to[v] != v, v = to[v];
    if (!moved) continue;
    if (repeats(mapped.data(), face.num_vertices)) {
      merges.collapsed = true;
      continue;
    }
    const long other = find_face(mapped);
    if (other >= 0 && stays(faces_[other].vertices.data(), faces_[other].num_vertices)) {
      merges.faces.emplace(f, static_cast<std::uint32_t>(other));
    } else {
      const auto [it, fresh] = moved_faces.try_emplace(detail::face_key(mapped.data(), face.num_vertices), f);
      if (!fresh) merges.faces.emplace(f, it->second);
    }
  }
  return merges;
}

Mesh::EntityOrder Mesh::entity_order(const EntityMerges& merges) const {
  EntityOrder order;
  order.edge_target.resize(edges_.size());
  order.face_target.resize(faces_.size());
  for (std::uint32_t e = 0; e < order.edge_target.size(); ++e) order.edge_target[e] = e;
  for (std::uint32_t f = 0; f < order.face_target.size(); ++f) order.face_target[f] = f;
  for (const auto& [from, into] : merges.edges) order.edge_target[from] = into;
  for (const auto& [from, into] : merges.faces) order.face_target[from] = into;
  // New ids in the order the rebuild meets the entities: elements, then boundary faces; each face's
  // first user gives its frame (its vertex order), as a new face takes its first element's.
  order.new_edge.assign(edges_.size(), kNone);
  order.new_face.assign(faces_.size(), kNone);
  order.edge_order.reserve(edges_.size());
  order.face_order.reserve(faces_.size());
  order.first_user.reserve(faces_.size());
  const auto meet_edge = [&](std::uint32_t e) {
    const std::uint32_t t = order.edge_target[e];
    if (order.new_edge[t] == kNone)
      order.new_edge[t] = static_cast<std::uint32_t>(order.edge_order.size()), order.edge_order.push_back(t);
  };
  const auto meet_face = [&](std::uint32_t f, EntityOrder::FirstUser user) {
    const std::uint32_t t = order.face_target[f];
    if (order.new_face[t] == kNone)
      order.new_face[t] = static_cast<std::uint32_t>(order.face_order.size()), order.face_order.push_back(t),
      order.first_user.push_back(user);
  };
  for (std::uint32_t e = 0; e < elements_.size(); ++e) {
    const Element& el = elements_[e];
    for (std::size_t k = 0; k < ho::edges(el.shape).size(); ++k) meet_edge(el.edges[k]);
    for (std::size_t f = 0; f < ho::faces(el.shape).size(); ++f)
      meet_face(el.faces[f], {e, static_cast<std::uint8_t>(f), false});
  }
  for (std::uint32_t b = 0; b < boundary_.size(); ++b) {
    const BoundaryFace& bf = boundary_[b];
    for (std::size_t k = 0; k < ho::edges(bf.shape).size(); ++k) meet_edge(bf.edges[k]);
    meet_face(bf.face, {b, 0, true});
  }
  return order;
}

bool Mesh::remap_entities(const Mesh& old, const std::vector<NodeId>& to, const EntityMerges& merges,
                          const EntityOrder& order) {
  if (merges.collapsed) return false;  // the rebuild's error names the element
  const int P = order_;
  const std::size_t per_edge = static_cast<std::size_t>(edge_interior_count(P));
  const std::vector<std::uint32_t>& edge_target = order.edge_target;
  const std::vector<std::uint32_t>& face_target = order.face_target;
  const std::vector<std::uint32_t>& new_edge = order.new_edge;
  const std::vector<std::uint32_t>& new_face = order.new_face;
  const std::vector<std::uint32_t>& edge_order = order.edge_order;
  const std::vector<std::uint32_t>& face_order = order.face_order;
  const std::vector<EntityOrder::FirstUser>& first_user = order.first_user;

  const std::array<FrameSlots, 2> frames{frame_slots(3, P), frame_slots(4, P)};
  // Merged entities must give the nodes of the one they join, as the rebuild's later users must.
  std::vector<NodeId> mine, theirs;
  for (const auto& [from, into] : merges.edges) {
    const Edge &a = old.edges_[from], &b = old.edges_[into];
    const bool same_way = to[a.vertices[0]] == to[b.vertices[0]];
    for (std::size_t k = 0; k < per_edge; ++k)
      if (to[old.edge_pool_[a.first_node + k]] != to[old.edge_pool_[b.first_node + (same_way ? k : per_edge - 1 - k)]])
        return false;
  }
  for (const auto& [from, into] : merges.faces) {
    const Face &a = old.faces_[from], &b = old.faces_[into];
    std::array<NodeId, 4> va{}, vb{};
    for (int k = 0; k < a.num_vertices; ++k) va[k] = to[a.vertices[k]], vb[k] = to[b.vertices[k]];
    const int code = face_orientation_code(va.data(), vb.data(), a.num_vertices);
    if (code < 0) return false;
    const auto count = static_cast<std::size_t>(face_interior_count(a.num_vertices, P));
    mine.resize(count), theirs.resize(count);
    face_nodes_in_frame(old.face_pool_, a.first_node, frames[a.num_vertices - 3], 0, to, mine.data());
    face_nodes_in_frame(old.face_pool_, b.first_node, frames[b.num_vertices - 3], code, to, theirs.data());
    if (mine != theirs) return false;
  }
  // An element or boundary face whose renamed vertices repeat: the rebuild refuses it.
  std::array<NodeId, 8> v{};
  for (const Element& el : elements_) {
    const int nv = ho::num_vertices(el.shape);
    for (int k = 0; k < nv; ++k) v[k] = to[el.vertices[k]];
    if (repeats(v.data(), nv)) return false;
  }
  for (const BoundaryFace& bf : old.boundary_) {
    const int nv = ho::num_vertices(bf.shape);
    for (int k = 0; k < nv; ++k) v[k] = to[bf.vertices[k]];
    if (repeats(v.data(), nv)) return false;
  }

  // The first user's vertices of a face, in its own order, renamed.
  const auto user_vertices = [&](const EntityOrder::FirstUser& u, std::array<NodeId, 4>& out) {
    if (u.boundary) {
      const BoundaryFace& bf = old.boundary_[u.owner];
      for (int k = 0; k < ho::num_vertices(bf.shape); ++k) out[k] = to[bf.vertices[k]];
    } else {
      const Element& el = elements_[u.owner];
      const auto& local = ho::faces(el.shape)[u.local];
      for (std::size_t k = 0; k < local.size(); ++k) out[k] = to[el.vertices[local[k]]];
    }
  };

  // The new edges: sorted renamed vertices, the pool turned where the renaming turned them.
  std::vector<Edge> edges(edge_order.size());
  std::vector<NodeId> edge_pool(edge_order.size() * per_edge);
  for (std::size_t i = 0; i < edge_order.size(); ++i) {
    const Edge& was = old.edges_[edge_order[i]];
    NodeId a = to[was.vertices[0]], b = to[was.vertices[1]];
    const bool turned = a > b;
    if (turned) std::swap(a, b);
    edges[i].vertices = {a, b};
    edges[i].first_node = static_cast<std::uint32_t>(i * per_edge);
    for (std::size_t k = 0; k < per_edge; ++k)
      edge_pool[i * per_edge + k] = to[old.edge_pool_[was.first_node + (turned ? per_edge - 1 - k : k)]];
  }

  // The new faces in their first user's frame; `reframed`: an element's code must be found anew.
  // Two halves on two threads (each face's pool entries start after all those of the faces before
  // it: the second half starts where the first's sum ends).
  const std::array<std::size_t, 2> per_face{static_cast<std::size_t>(face_interior_count(3, P)),
                                            static_cast<std::size_t>(face_interior_count(4, P))};
  const std::size_t half = face_order.size() / 2;
  std::size_t face_pool_size = 0, second_half_first = 0;
  for (std::size_t i = 0; i < face_order.size(); ++i) {
    if (i == half) second_half_first = face_pool_size;
    face_pool_size += per_face[old.faces_[face_order[i]].num_vertices - 3];
  }
  std::vector<Face> faces(face_order.size());
  std::vector<NodeId> face_pool(face_pool_size);
  std::vector<char> reframed(face_order.size(), 0);
  for (const auto& [from, into] : merges.faces)  // users of `from` now see `into`: their codes change
    if (new_face[into] != kNone) reframed[new_face[into]] = 1;
  // Faces [begin, end), their pool entries from `pool_end` on; false at a twisted quadrilateral
  // (the rebuild's error names it).
  const auto make_faces = [&](std::size_t begin, std::size_t end, std::size_t pool_end) {
    for (std::size_t i = begin; i < end; ++i) {
      const Face& was = old.faces_[face_order[i]];
      const int n = was.num_vertices;
      std::array<NodeId, 4> stored{kNoNode, kNoNode, kNoNode, kNoNode}, frame{kNoNode, kNoNode, kNoNode, kNoNode};
      for (int k = 0; k < n; ++k) stored[k] = to[was.vertices[k]];
      user_vertices(first_user[i], frame);
      const int code = face_orientation_code(frame.data(), stored.data(), n);
      if (code < 0) return false;
      reframed[i] = reframed[i] || code != 0;
      Face& face = faces[i];
      face.vertices = frame;
      face.num_vertices = static_cast<std::uint8_t>(n);
      face.first_node = static_cast<std::uint32_t>(pool_end);
      face_nodes_in_frame(old.face_pool_, was.first_node, frames[n - 3], code, to, face_pool.data() + pool_end);
      pool_end += per_face[n - 3];
      const EntityOrder::FirstUser& u = first_user[i];
      const auto& own = ho::edges(n == 3 ? ho::Shape::Triangle : ho::Shape::Quadrilateral);
      for (std::size_t k = 0; k < own.size(); ++k) {
        const std::uint32_t e = u.boundary ? old.boundary_[u.owner].edges[k]
                                           : elements_[u.owner].edges[detail::face_edges_of(elements_[u.owner].shape)[u.local][k]];
        face.edges[k] = new_edge[edge_target[e]];
        if (frame[own[k][0]] > frame[own[k][1]]) face.edge_reversed |= static_cast<std::uint8_t>(1u << k);
      }
    }
    return true;
  };
  std::future<bool> second_half;
  try {
    second_half = std::async(std::launch::async, make_faces, half, face_order.size(), second_half_first);
  } catch (const std::system_error&) {  // no thread to be had: both halves on this one
  }
  const bool first_made = make_faces(0, half, 0);
  const bool second_made = second_half.valid() ? second_half.get() : make_faces(half, face_order.size(), second_half_first);
  if (!first_made || !second_made) return false;

  // The lookups of the new entities, on another thread while the elements are renamed: every key
  // is distinct, so each id goes to the first free slot of its hash.
  IdTable edge_index, face_index;
  const auto edge_hash_of = [&](std::uint32_t e) {
    return IdTable::mix(detail::edge_key(edges[e].vertices[0], edges[e].vertices[1]));
  };
  const auto face_hash_of = [&](std::uint32_t f) {
    return detail::face_key_hash(detail::face_key(faces[f].vertices.data(), faces[f].num_vertices));
  };
  const auto build_lookups = [&] {
    const auto distinct = [](std::uint32_t) { return false; };
    edge_index.reserve(edges.size(), edge_hash_of);
    face_index.reserve(faces.size(), face_hash_of);
    for (std::uint32_t e = 0; e < edges.size(); ++e) edge_index.find_or_insert(edge_hash_of(e), distinct, e, edge_hash_of);
    for (std::uint32_t f = 0; f < faces.size(); ++f) face_index.find_or_insert(face_hash_of(f), distinct, f, face_hash_of);
  };
  std::future<void> lookups;
  try {
    lookups = std::async(std::launch::async, build_lookups);
  } catch (const std::system_error&) {  // no thread to be had: built below, on this one
  }
  // Joined before leaving, also when an element is refused below.
  struct Join {
    std::future<void>& f;
    ~Join() {
      if (f.valid()) f.wait();
    }
  } join{lookups};

  // Every element's codes are checked before any element changes: a refusal leaves the mesh whole.
  const auto element_code = [&](const Element& el, std::size_t f, std::uint32_t face) {
    const auto& local = ho::faces(el.shape)[f];
    std::array<NodeId, 4> frame{};
    for (std::size_t k = 0; k < local.size(); ++k) frame[k] = to[el.vertices[local[k]]];
    return face_orientation_code(frame.data(), faces[face].vertices.data(), static_cast<int>(local.size()));
  };
  for (const Element& el : elements_)
    for (std::size_t f = 0; f < ho::faces(el.shape).size(); ++f) {
      const std::uint32_t face = new_face[face_target[el.faces[f]]];
      if (reframed[face] && element_code(el, f, face) < 0) return false;
    }

  // An element's or boundary face's vertices and edges renamed; the bits of its reversed edges.
  const auto rename = [&](ho::Shape shape, NodeId* vertices, std::uint32_t* edge_ids) {
    for (int k = 0; k < ho::num_vertices(shape); ++k) vertices[k] = to[vertices[k]];
    const auto& local_edges = ho::edges(shape);
    std::uint16_t reversed = 0;
    for (std::size_t k = 0; k < local_edges.size(); ++k) {
      edge_ids[k] = new_edge[edge_target[edge_ids[k]]];
      if (vertices[local_edges[k][0]] > vertices[local_edges[k][1]]) reversed |= static_cast<std::uint16_t>(1u << k);
    }
    return reversed;
  };
  std::vector<NodeId> interior_pool;
  interior_pool.reserve(old.interior_pool_.size());
  for (Element& el : elements_) {
    for (std::size_t f = 0; f < ho::faces(el.shape).size(); ++f) {  // before the vertices are renamed
      el.faces[f] = new_face[face_target[el.faces[f]]];
      if (reframed[el.faces[f]]) el.face_orientation[f] = static_cast<std::uint8_t>(element_code(el, f, el.faces[f]));
    }
    el.edge_reversed = rename(el.shape, el.vertices.data(), el.edges.data());
    const int count = node_layout(el.shape, P).num_interior;
    const auto first = static_cast<std::uint32_t>(interior_pool.size());
    for (int k = 0; k < count; ++k) interior_pool.push_back(to[old.interior_pool_[el.first_node + k]]);
    el.first_node = first;
  }
  boundary_ = old.boundary_;
  for (BoundaryFace& bf : boundary_) {
    bf.edge_reversed = static_cast<std::uint8_t>(rename(bf.shape, bf.vertices.data(), bf.edges.data()));
    bf.face = new_face[face_target[bf.face]];
    bf.face_orientation = static_cast<std::uint8_t>(
        face_orientation_code(bf.vertices.data(), faces[bf.face].vertices.data(), ho::num_vertices(bf.shape)));
  }
  if (lookups.valid())
    lookups.get();
  else
    build_lookups();
  edges_ = std::move(edges), faces_ = std::move(faces);
  edge_pool_ = std::move(edge_pool), face_pool_ = std::move(face_pool), interior_pool_ = std::move(interior_pool);
  edge_index_ = std::move(edge_index), face_index_ = std::move(face_index);
  return true;
}

}  // namespace semimesh::mesh
