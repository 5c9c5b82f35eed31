#include "semimesh/mesh/mesh.hpp"

#include "semimesh/mesh/node_layout.hpp"

#include "entity_keys.hpp"

#include <algorithm>
#include <exception>
#include <future>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace semimesh::mesh {
namespace {

// Runs `mine` on this thread and `theirs` on another (here too when no thread is to be had): two
// halves of a copy that write different members. Both are done when it returns or throws (this
// thread's error first).
template <class Mine, class Theirs>
void both_sides(const Mine& mine, const Theirs& theirs) {
  std::future<void> other;
  try {
    other = std::async(std::launch::async, theirs);
  } catch (const std::system_error&) {
  }
  std::exception_ptr error;
  try {
    mine();
  } catch (...) {
    error = std::current_exception();
  }
  if (other.valid()) {
    other.wait();
    if (!error) other.get();
  } else if (!error) {
    theirs();
  }
  if (error) std::rethrow_exception(error);
}

using detail::edge_key;
using detail::face_edges_of;
using detail::face_key;
using detail::face_key_hash;
using detail::FaceEdges;
using detail::same_edge;
using detail::same_face;

// Elements whose old node lists replace_nodes holds at once, per block (two blocks: ~8 MB at order 4).
constexpr std::size_t kRebuildBlock = 8192;

// link(i, nodes) for i in [0, count) in order on this thread, the node lists made by
// node_lists(first, lists) (a block's, from index `first`) a block ahead on another thread (a third
// of a rebuild's time): node_lists must not read what link writes. An error of link's leaves after
// the block ahead is made.
template <typename NodeLists, typename Link>
void link_in_blocks(std::size_t count, const NodeLists& node_lists, const Link& link) {
  std::vector<std::vector<NodeId>> current, next;
  const auto make = [&](std::size_t first, std::vector<std::vector<NodeId>>& lists) {
    lists.resize(std::min(kRebuildBlock, count - first));
    node_lists(first, lists);
  };
  if (count > 0) make(0, current);
  for (std::size_t first = 0; first < count; first += kRebuildBlock) {
    std::future<void> ahead;  // joined before leaving, also when link throws
    if (first + kRebuildBlock < count)
      ahead = std::async(std::launch::async, [&, next_first = first + kRebuildBlock] { make(next_first, next); });
    for (std::size_t k = 0; k < current.size(); ++k) link(first + k, current[k]);
    if (ahead.valid()) ahead.get();
    std::swap(current, next);
  }
}

std::string point_text(const Eigen::Vector3d& x) {
  std::ostringstream out;
  out << "(" << x.x() << ", " << x.y() << ", " << x.z() << ")";
  return out.str();
}

std::string element_name(ho::Shape shape, std::size_t index) {
  return ho::to_string(shape) + " " + std::to_string(index);
}

}  // namespace

std::uint64_t Mesh::edge_hash(std::uint32_t edge) const {
  return IdTable::mix(edge_key(edges_[edge].vertices[0], edges_[edge].vertices[1]));
}

std::uint64_t Mesh::face_hash(std::uint32_t face) const {
  return face_key_hash(face_key(faces_[face].vertices.data(), faces_[face].num_vertices));
}

Mesh::Mesh(int order, ho::NodeSet node_set) : order_(order), node_set_(node_set) {
  if (order < 1 || order > ho::kMaxOrder)
    throw std::invalid_argument("Mesh: order " + std::to_string(order) + " outside [1, " +
                                std::to_string(ho::kMaxOrder) + "]");
}

NodeId Mesh::add_node(const Eigen::Vector3d& x, const CadAttachment& cad) {
  if (nodes_.size() >= kNoNode) throw std::length_error("Mesh: too many nodes for 32-bit node ids");
  const auto id = static_cast<NodeId>(nodes_.size());
  nodes_.push_back(x);
  if (cad.kind != CadAttachment::None) cad_.set(id, cad);
  return id;
}

void Mesh::take_nodes(Mesh& other) {
  if (!nodes_.empty()) throw std::logic_error("Mesh::take_nodes: this mesh has nodes already");
  nodes_ = std::move(other.nodes_), other.nodes_ = {};
  cad_ = std::move(other.cad_), other.cad_ = {};
}

void Mesh::copy_nodes(const Mesh& other) {
  if (!nodes_.empty()) throw std::logic_error("Mesh::copy_nodes: this mesh has nodes already");
  if (&other == this) return;
  nodes_.insert(nodes_.end(), other.nodes_.begin(), other.nodes_.end());  // keeps the reserved room
  cad_ = other.cad_;
}

const CadAttachment& Mesh::cad_attachment(NodeId id) const {
  static const CadAttachment none{};
  const CadAttachment* attachment = cad_.find(id);
  return attachment ? *attachment : none;
}

void Mesh::place_node(NodeId id, const Eigen::Vector3d& x) {
  if (id >= nodes_.size()) throw std::out_of_range("Mesh::place_node: no node " + std::to_string(id));
  if (cad_.contains(id))
    throw std::logic_error("Mesh::place_node: node " + std::to_string(id) +
                           " is attached to CAD; move it with place_node_on_cad so its parameters follow");
  nodes_[id] = x;
}

void Mesh::place_node_on_cad(NodeId id, const Eigen::Vector3d& x, const CadAttachment& cad) {
  if (id >= nodes_.size()) throw std::out_of_range("Mesh::place_node_on_cad: no node " + std::to_string(id));
  nodes_[id] = x;
  if (cad.kind == CadAttachment::None)
    cad_.erase(id);
  else
    cad_.set(id, cad);
}

int Mesh::region_index(const std::string& name) {
  const auto it = std::find(regions_.begin(), regions_.end(), name);
  if (it != regions_.end()) return static_cast<int>(it - regions_.begin());
  regions_.push_back(name);
  return static_cast<int>(regions_.size()) - 1;
}

void Mesh::copy_regions_from(const Mesh& other) {
  const auto& theirs = other.regions_;
  if (regions_.size() > theirs.size() || !std::equal(regions_.begin(), regions_.end(), theirs.begin()))
    throw std::logic_error("Mesh::copy_regions_from: this mesh already has other regions");
  regions_ = theirs;
}

int Mesh::group_index(const std::string& name) {
  const auto it = std::find(groups_.begin(), groups_.end(), name);
  if (it != groups_.end()) return static_cast<int>(it - groups_.begin());
  groups_.push_back(name);
  return static_cast<int>(groups_.size()) - 1;
}

void Mesh::set_boundary_group(std::size_t face, const std::string& group) {
  if (face >= boundary_.size())
    throw std::out_of_range("Mesh::set_boundary_group: boundary face " + std::to_string(face) + " does not exist (" +
                            std::to_string(boundary_.size()) + " faces)");
  boundary_[face].group = static_cast<std::uint16_t>(group_index(group));
}

void Mesh::reserve(ho::Shape typical_shape, std::size_t num_elements) {
  elements_.reserve(num_elements);
  // Each edge and interior face is shared by several elements; these are upper bounds.
  const std::size_t ne = ho::edges(typical_shape).size() * num_elements / 2;
  const std::size_t nf = ho::faces(typical_shape).size() * num_elements / 2 + num_elements;
  // The vectors' unused room is never touched, so never resident; the lookups grow as they fill
  // (sized by these bounds they would be resident in full: twice too large on hexahedra).
  edges_.reserve(ne);
  faces_.reserve(nf);
  edge_pool_.reserve(ne * (order_ - 1));
  face_pool_.reserve(nf * face_interior_count(4, order_));  // quadrilaterals own the most
  interior_pool_.reserve(num_elements * node_layout(typical_shape, order_).num_interior);
}

void Mesh::reserve_lookups(std::size_t num_edges, std::size_t num_faces) {
  // Two tables, each rehashing what it holds: one on each side.
  both_sides([&] { edge_index_.reserve(num_edges, [&](std::uint32_t e) { return edge_hash(e); }); },
             [&] { face_index_.reserve(num_faces, [&](std::uint32_t f) { return face_hash(f); }); });
}

std::string Mesh::Named::text() const {
  return group ? "boundary " + element_name(shape, index) + " of group '" + *group + "'" : element_name(shape, index);
}

void Mesh::check_same_node(NodeId stored, NodeId given, const Named& who) const {
  if (stored == given) return;
  const Eigen::Vector3d& a = nodes_[stored];
  const Eigen::Vector3d& b = nodes_[given];
  const double scale = std::max({1.0, a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()});
  if ((a - b).norm() > 1e-9 * scale)
    throw std::invalid_argument(who.text() + ": node " + std::to_string(given) + " at " + point_text(b) +
                                " is not at the place of node " + std::to_string(stored) + " at " + point_text(a) +
                                " that the shared entity already owns (non-conforming elements or a wrong node order)");
}

void Mesh::link_entities(ho::Shape shape, const std::vector<NodeId>& canonical, const NodeId* vertices,
                         std::uint32_t* edge_ids, std::uint16_t& reversed, std::uint32_t* face_ids,
                         std::uint8_t* codes, const Named& who) {
  const NodeLayout& layout = node_layout(shape, order_);
  if (canonical.size() != layout.slots.size())
    throw std::invalid_argument(who.text() + ": expected " + std::to_string(layout.slots.size()) + " nodes for order " +
                                std::to_string(order_) + ", got " + std::to_string(canonical.size()));
  for (NodeId id : canonical)
    if (id >= nodes_.size()) throw std::invalid_argument(who.text() + ": unknown node id " + std::to_string(id));
  const int nv = ho::num_vertices(shape);
  for (int a = 0; a < nv; ++a)
    for (int b = a + 1; b < nv; ++b)
      if (vertices[a] == vertices[b])
        throw std::invalid_argument(who.text() + ": vertex " + std::to_string(vertices[a]) + " appears twice");

  // Every lookup's hash first, its slot's load started: the tables are far larger than the caches,
  // and the loads of an element's 18 lookups then overlap instead of waiting on each other.
  const auto& local_edges = ho::edges(shape);
  std::array<std::uint64_t, 12> edge_hashes;
  for (std::size_t e = 0; e < local_edges.size(); ++e) {
    edge_hashes[e] = IdTable::mix(edge_key(vertices[local_edges[e][0]], vertices[local_edges[e][1]]));
    edge_index_.prefetch(edge_hashes[e]);
  }
  const bool volume = ho::dimension(shape) == 3;
  const std::size_t num_faces = volume ? ho::faces(shape).size() : 1;
  std::array<std::array<NodeId, 4>, 6> face_vertices{};
  std::array<std::array<NodeId, 4>, 6> face_keys;
  for (std::size_t f = 0; f < num_faces; ++f) {
    const int n = volume ? static_cast<int>(ho::faces(shape)[f].size()) : nv;
    for (int k = 0; k < n; ++k) face_vertices[f][k] = volume ? vertices[ho::faces(shape)[f][k]] : vertices[k];
    face_keys[f] = face_key(face_vertices[f].data(), n);
    face_index_.prefetch(face_key_hash(face_keys[f]));
  }
  reversed = 0;
  for (std::size_t e = 0; e < local_edges.size(); ++e) {
    const NodeId a = vertices[local_edges[e][0]], b = vertices[local_edges[e][1]];
    edge_ids[e] = find_or_add_edge(a, b, edge_hashes[e]);
    if (a > b) reversed |= static_cast<std::uint16_t>(1u << e);
  }
  if (!volume) {
    face_ids[0] = find_or_add_face(face_vertices[0].data(), nv, face_keys[0], edge_ids, codes[0], who);
  } else {
    const FaceEdges& local_face_edges = face_edges_of(shape);
    for (std::size_t f = 0; f < num_faces; ++f) {
      std::array<std::uint32_t, 4> fe{};
      const int n = static_cast<int>(ho::faces(shape)[f].size());
      for (int k = 0; k < n; ++k) fe[k] = edge_ids[local_face_edges[f][k]];
      face_ids[f] = find_or_add_face(face_vertices[f].data(), n, face_keys[f], fe.data(), codes[f], who);
    }
  }
  // New entities hold kNoNode placeholders: the first element to see a node stores it, later
  // ones must give the same node (or one at the same place).
  for (std::size_t i = 0; i < layout.slots.size(); ++i) {
    const NodeSlot& s = layout.slots[i];
    NodeId* stored = nullptr;
    if (s.kind == NodeSlot::Edge)
      stored = &edge_pool_[edges_[edge_ids[s.local]].first_node + s.slot[(reversed >> s.local) & 1u]];
    else if (s.kind == NodeSlot::Face)
      stored = &face_pool_[faces_[face_ids[s.local]].first_node + s.slot[codes[s.local]]];
    else
      continue;
    if (*stored == kNoNode)
      *stored = canonical[i];
    else
      check_same_node(*stored, canonical[i], who);
  }
}

std::size_t Mesh::add_element(ho::Shape shape, const std::vector<NodeId>& canonical_nodes, int region) {
  if (ho::dimension(shape) != 3)
    throw std::invalid_argument("Mesh::add_element: " + ho::to_string(shape) +
                                " is not a volume element (use add_boundary_face)");
  if (region < 0 || static_cast<std::size_t>(region) >= regions_.size())
    throw std::invalid_argument("Mesh::add_element: region " + std::to_string(region) + " does not exist (" +
                                std::to_string(regions_.size()) + " regions)");
  const std::size_t index = elements_.size();
  elements_.push_back(linked_element(shape, canonical_nodes, region, index));
  return index;
}

void Mesh::add_elements_of(const Mesh& other, std::size_t first, std::size_t end) {
  if (&other == this) throw std::invalid_argument("Mesh::add_elements_of: the other mesh is this one");
  if (first > end || end > other.elements_.size())
    throw std::out_of_range("Mesh::add_elements_of: elements [" + std::to_string(first) + ", " + std::to_string(end) +
                            ") of a mesh of " + std::to_string(other.elements_.size()));
  link_in_blocks(
      end - first,
      [&](std::size_t from, std::vector<std::vector<NodeId>>& lists) {
        for (std::size_t k = 0; k < lists.size(); ++k) other.element_nodes(first + from + k, lists[k]);
      },
      [&](std::size_t i, const std::vector<NodeId>& ids) {
        const Element& el = other.elements_[first + i];
        add_element(el.shape, ids, el.region);
      });
}

void Mesh::adopt_entities(const Mesh& linear, const std::vector<NodeId>& edge_nodes,
                          const std::vector<NodeId>& face_nodes, std::size_t face_stride) {
  if (!elements_.empty() || !edges_.empty() || !faces_.empty() || !boundary_.empty())
    throw std::logic_error("Mesh::adopt_entities: the mesh already has elements or entities");
  const auto per_edge = static_cast<std::size_t>(edge_interior_count(order_));
  if (edge_nodes.size() != linear.edges_.size() * per_edge || face_nodes.size() != linear.faces_.size() * face_stride ||
      face_stride < static_cast<std::size_t>(face_interior_count(4, order_)))
    throw std::invalid_argument("Mesh::adopt_entities: node lists of " + std::to_string(edge_nodes.size()) + " and " +
                                std::to_string(face_nodes.size()) + " ids for " + std::to_string(linear.edges_.size()) +
                                " edges and " + std::to_string(linear.faces_.size()) + " faces at order " +
                                std::to_string(order_));
  both_sides(
      [&] {
        edges_ = linear.edges_;
        for (std::size_t e = 0; e < edges_.size(); ++e) edges_[e].first_node = static_cast<std::uint32_t>(e * per_edge);
        edge_pool_ = edge_nodes;
        edge_index_ = linear.edge_index_;
      },
      [&] {
        faces_ = linear.faces_;
        face_pool_.clear();
        std::size_t pool_size = 0;
        for (const Face& face : faces_) pool_size += static_cast<std::size_t>(face_interior_count(face.num_vertices, order_));
        face_pool_.reserve(pool_size);
        for (std::size_t f = 0; f < faces_.size(); ++f) {
          const auto count = static_cast<std::size_t>(face_interior_count(faces_[f].num_vertices, order_));
          faces_[f].first_node = static_cast<std::uint32_t>(face_pool_.size());
          face_pool_.insert(face_pool_.end(), face_nodes.begin() + static_cast<long>(f * face_stride),
                            face_nodes.begin() + static_cast<long>(f * face_stride + count));
        }
        face_index_ = linear.face_index_;
      });
}

void Mesh::adopt_all_entities(const Mesh& other, Mesh* lookups_from) {
  if (!elements_.empty() || !edges_.empty() || !faces_.empty() || !boundary_.empty())
    throw std::logic_error("Mesh::adopt_all_entities: the mesh already has elements or entities");
  if (other.order_ != order_)
    throw std::invalid_argument("Mesh::adopt_all_entities: a mesh of order " + std::to_string(other.order_) +
                                " into one of order " + std::to_string(order_));
  if (lookups_from && lookups_from != &other)
    throw std::invalid_argument("Mesh::adopt_all_entities: the lookups must come from the mesh adopted");
  both_sides(
      [&] {
        edges_ = other.edges_, edge_pool_ = other.edge_pool_;
        if (!lookups_from) return void(edge_index_ = other.edge_index_);
        edge_index_ = std::move(lookups_from->edge_index_);
        lookups_from->edge_index_ = IdTable();
      },
      [&] {
        faces_ = other.faces_, face_pool_ = other.face_pool_;
        if (!lookups_from) return void(face_index_ = other.face_index_);
        face_index_ = std::move(lookups_from->face_index_);
        lookups_from->face_index_ = IdTable();
      });
}

void Mesh::add_elements_as_in(const Mesh& other, std::size_t first, std::size_t end) {
  if (first > end || end > other.elements_.size())
    throw std::out_of_range("Mesh::add_elements_as_in: elements [" + std::to_string(first) + ", " +
                            std::to_string(end) + ") of a mesh of " + std::to_string(other.elements_.size()));
  if (first == end) return;
  // The ids must name the same entities here: checked on the range's first element (a mesh that
  // took other entities differs there).
  const Element& probe = other.elements_[first];
  bool same = edges_.size() >= other.edges_.size() && faces_.size() >= other.faces_.size() && order_ == other.order_;
  for (std::size_t k = 0; same && k < ho::edges(probe.shape).size(); ++k)
    same = edges_[probe.edges[k]].vertices == other.edges_[probe.edges[k]].vertices;
  for (std::size_t k = 0; same && k < ho::faces(probe.shape).size(); ++k)
    same = faces_[probe.faces[k]].vertices == other.faces_[probe.faces[k]].vertices;
  if (!same)
    throw std::logic_error("Mesh::add_elements_as_in: " + element_name(probe.shape, first) +
                           " names entities this mesh did not take (adopt_all_entities)");
  for (std::size_t e = first; e < end; ++e) {
    Element el = other.elements_[e];
    if (el.region >= regions_.size())
      throw std::invalid_argument(element_name(el.shape, e) + ": region " + std::to_string(el.region) +
                                  " does not exist (copy_regions_from first)");
    const int interior = node_layout(el.shape, order_).num_interior;
    const auto from = other.interior_pool_.begin() + el.first_node;
    el.first_node = static_cast<std::uint32_t>(interior_pool_.size());
    interior_pool_.insert(interior_pool_.end(), from, from + interior);
    elements_.push_back(el);
  }
}

std::size_t Mesh::add_element_as(const Mesh& linear, std::size_t element, const std::vector<NodeId>& canonical_nodes) {
  const Element& was = linear.elements_.at(element);
  const NodeLayout& layout = node_layout(was.shape, order_);
  const Named who{was.shape, element, nullptr};
  if (canonical_nodes.size() != layout.slots.size())
    throw std::invalid_argument(who.text() + ": expected " + std::to_string(layout.slots.size()) + " nodes for order " +
                                std::to_string(order_) + ", got " + std::to_string(canonical_nodes.size()));
  for (NodeId id : canonical_nodes)
    if (id >= nodes_.size()) throw std::invalid_argument(who.text() + ": unknown node id " + std::to_string(id));
  thread_local std::vector<NodeId> interior;
  interior.clear();
  for (std::size_t i = 0; i < layout.slots.size(); ++i)
    if (layout.slots[i].kind == NodeSlot::Interior) interior.push_back(canonical_nodes[i]);
  add_element_adopted(linear, element, interior);
  // Every other node must be the one the vertex or adopted entity already names: the same mesh
  // add_element would build (it would find these entities and compare the same nodes).
  const Element el = elements_.back();
  thread_local std::vector<NodeId> stored;
  assemble(el.shape, el.vertices.data(), el.edges.data(), el.edge_reversed, el.faces.data(), el.face_orientation.data(),
           el.first_node, stored);
  const auto differs = std::mismatch(stored.begin(), stored.end(), canonical_nodes.begin());
  if (differs.first != stored.end()) {
    elements_.pop_back();
    interior_pool_.resize(el.first_node);
    throw std::logic_error(who.text() + ": node " + std::to_string(*differs.second) + " at canonical position " +
                           std::to_string(differs.first - stored.begin()) + " is not the adopted entity's node " +
                           std::to_string(*differs.first));
  }
  return element;
}

std::size_t Mesh::add_element_adopted(const Mesh& linear, std::size_t element,
                                      const std::vector<NodeId>& interior_nodes) {
  const Element& was = linear.elements_.at(element);
  const NodeLayout& layout = node_layout(was.shape, order_);
  const Named who{was.shape, element, nullptr};
  if (element != elements_.size() || edges_.size() != linear.edges_.size() || faces_.size() != linear.faces_.size())
    throw std::logic_error(who.text() + ": add_element_adopted needs the adopted entities and the elements in order");
  if (interior_nodes.size() != static_cast<std::size_t>(layout.num_interior))
    throw std::invalid_argument(who.text() + ": expected " + std::to_string(layout.num_interior) +
                                " interior nodes for order " + std::to_string(order_) + ", got " +
                                std::to_string(interior_nodes.size()));
  if (was.region >= regions_.size())
    throw std::invalid_argument(who.text() + ": region " + std::to_string(was.region) + " does not exist (" +
                                std::to_string(regions_.size()) + " regions: copy_regions_from first)");
  Element el = was;
  el.first_node = static_cast<std::uint32_t>(interior_pool_.size());
  interior_pool_.resize(interior_pool_.size() + interior_nodes.size());
  std::size_t k = 0;
  for (const NodeSlot& s : layout.slots) {
    if (s.kind != NodeSlot::Interior) continue;
    const NodeId id = interior_nodes[k++];
    if (id >= nodes_.size()) {
      interior_pool_.resize(el.first_node);
      throw std::invalid_argument(who.text() + ": unknown node id " + std::to_string(id));
    }
    interior_pool_[el.first_node + s.slot[0]] = id;
  }
  elements_.push_back(el);
  return element;
}

Element Mesh::linked_element(ho::Shape shape, const std::vector<NodeId>& canonical_nodes, int region,
                             std::size_t index) {
  const Named who{shape, index, nullptr};
  const int nv = ho::num_vertices(shape);
  if (canonical_nodes.size() < static_cast<std::size_t>(nv))
    throw std::invalid_argument(who.text() + ": fewer nodes than vertices");
  Element el;
  el.shape = shape;
  el.region = static_cast<std::uint16_t>(region);
  std::copy(canonical_nodes.begin(), canonical_nodes.begin() + nv, el.vertices.begin());
  link_entities(shape, canonical_nodes, el.vertices.data(), el.edges.data(), el.edge_reversed, el.faces.data(),
                el.face_orientation.data(), who);
  el.first_node = append_interior(node_layout(shape, order_), canonical_nodes);
  return el;
}

std::uint32_t Mesh::append_interior(const NodeLayout& layout, const std::vector<NodeId>& canonical_nodes) {
  const auto first = static_cast<std::uint32_t>(interior_pool_.size());
  interior_pool_.resize(interior_pool_.size() + layout.num_interior);
  for (std::size_t i = 0; i < layout.slots.size(); ++i)
    if (layout.slots[i].kind == NodeSlot::Interior) interior_pool_[first + layout.slots[i].slot[0]] = canonical_nodes[i];
  return first;
}

std::size_t Mesh::add_boundary_face(const std::string& group, ho::Shape shape,
                                    const std::vector<NodeId>& canonical_nodes) {
  if (shape != ho::Shape::Triangle && shape != ho::Shape::Quadrilateral)
    throw std::invalid_argument("Mesh::add_boundary_face: group '" + group + "': " + ho::to_string(shape) +
                                " is not a triangle or quadrilateral");
  const std::size_t index = boundary_.size();
  const Named who{shape, index, &group};
  const int nv = ho::num_vertices(shape);
  if (canonical_nodes.size() < static_cast<std::size_t>(nv))
    throw std::invalid_argument(who.text() + ": fewer nodes than vertices");
  BoundaryFace bf;
  bf.shape = shape;
  std::copy(canonical_nodes.begin(), canonical_nodes.begin() + nv, bf.vertices.begin());
  std::uint16_t reversed = 0;
  link_entities(shape, canonical_nodes, bf.vertices.data(), bf.edges.data(), reversed, &bf.face,
                &bf.face_orientation, who);
  bf.edge_reversed = static_cast<std::uint8_t>(reversed);
  bf.group = static_cast<std::uint16_t>(group_index(group));
  boundary_.push_back(bf);
  return index;
}

std::uint32_t Mesh::find_or_add_edge(NodeId a, NodeId b, std::uint64_t hash) {
  const std::array<NodeId, 2> key{std::min(a, b), std::max(a, b)};
  const auto id = static_cast<std::uint32_t>(edges_.size());
  const std::uint32_t found = edge_index_.find_or_insert(
      hash, [&](std::uint32_t e) { return same_edge(edges_[e].vertices, key); }, id,
      [&](std::uint32_t e) { return edge_hash(e); });
  if (found != IdTable::kNone) return found;
  Edge edge;
  edge.vertices = key;
  edge.first_node = static_cast<std::uint32_t>(edge_pool_.size());
  edge_pool_.resize(edge_pool_.size() + edge_interior_count(order_), kNoNode);
  edges_.push_back(edge);
  return id;
}

std::uint32_t Mesh::find_or_add_face(const NodeId* local_vertices, int n, const std::array<NodeId, 4>& key,
                                     const std::uint32_t* edge_ids, std::uint8_t& code, const Named& who) {
  const auto id = static_cast<std::uint32_t>(faces_.size());
  const std::uint32_t found = face_index_.find_or_insert(
      face_key_hash(key), [&](std::uint32_t f) { return has_face_key(f, key); }, id,
      [&](std::uint32_t f) { return face_hash(f); });
  if (found == IdTable::kNone) {
    Face face;
    std::copy(local_vertices, local_vertices + n, face.vertices.begin());
    face.num_vertices = static_cast<std::uint8_t>(n);
    // The face's edges (link_entities found them first); kept so that face_nodes needs no lookup.
    const auto& local_edges = ho::edges(n == 3 ? ho::Shape::Triangle : ho::Shape::Quadrilateral);
    for (std::size_t e = 0; e < local_edges.size(); ++e) {
      const NodeId a = local_vertices[local_edges[e][0]], b = local_vertices[local_edges[e][1]];
      face.edges[e] = edge_ids[e];
      if (a > b) face.edge_reversed |= static_cast<std::uint8_t>(1u << e);
    }
    face.first_node = static_cast<std::uint32_t>(face_pool_.size());
    face_pool_.resize(face_pool_.size() + face_interior_count(n, order_), kNoNode);
    faces_.push_back(face);
    code = 0;
    return id;
  }
  const int c = face_orientation_code(local_vertices, faces_[found].vertices.data(), n);
  if (c < 0)
    throw std::invalid_argument(who.text() + ": face " + std::to_string(found) +
                                " has the same vertices in a different cycle (twisted quadrilateral)");
  code = static_cast<std::uint8_t>(c);
  return found;
}

bool Mesh::has_face_key(std::uint32_t face, const std::array<NodeId, 4>& key) const {
  return same_face(face_key(faces_[face].vertices.data(), faces_[face].num_vertices), key);
}

long Mesh::find_edge(NodeId a, NodeId b) const {
  const std::array<NodeId, 2> key{std::min(a, b), std::max(a, b)};
  const std::uint32_t found =
      edge_index_.find(IdTable::mix(edge_key(a, b)), [&](std::uint32_t e) { return same_edge(edges_[e].vertices, key); });
  return found == IdTable::kNone ? -1 : static_cast<long>(found);
}

long Mesh::find_face(const std::vector<NodeId>& vertices) const {
  if (vertices.size() != 3 && vertices.size() != 4) return -1;
  const std::array<NodeId, 4> key = face_key(vertices.data(), static_cast<int>(vertices.size()));
  const std::uint32_t found = face_index_.find(face_key_hash(key), [&](std::uint32_t f) { return has_face_key(f, key); });
  return found == IdTable::kNone ? -1 : static_cast<long>(found);
}

void Mesh::assemble(ho::Shape shape, const NodeId* vertices, const std::uint32_t* edge_ids, std::uint16_t reversed,
                    const std::uint32_t* face_ids, const std::uint8_t* codes, std::uint32_t first_interior,
                    std::vector<NodeId>& out) const {
  const NodeLayout& layout = node_layout(shape, order_);
  // By runs (the blocks NodeLayout guarantees): the vertices, each edge's nodes forwards or backwards, each
  // face's as stored (code 0) or through its slots, the interior's as stored. The entities' first
  // pool entries are read up front: independent loads, whose cache misses the core overlaps.
  const int nv = ho::num_vertices(shape);
  out.resize(layout.slots.size());
  NodeId* ids = out.data();
  std::copy_n(vertices, nv, ids);
  if (order_ < 2) return;  // no edge, face or element owns a node
  const std::size_t num_edges = ho::edges(shape).size();
  const bool volume = ho::dimension(shape) == 3;
  const std::size_t num_faces = volume ? ho::faces(shape).size() : 1;
  std::array<std::uint32_t, 12> edge_first;
  std::array<std::uint32_t, 6> face_first;
  for (std::size_t k = 0; k < num_edges; ++k) edge_first[k] = edges_[edge_ids[k]].first_node;
  for (std::size_t k = 0; k < num_faces; ++k) face_first[k] = faces_[face_ids[k]].first_node;
  const auto per_edge = static_cast<std::size_t>(edge_interior_count(order_));
  std::size_t at = static_cast<std::size_t>(nv);
  for (std::size_t k = 0; k < num_edges; ++k, at += per_edge) {
    const NodeId* run = edge_pool_.data() + edge_first[k];
    if ((reversed >> k) & 1u)
      std::reverse_copy(run, run + per_edge, ids + at);
    else
      std::copy_n(run, per_edge, ids + at);
  }
  for (std::size_t f = 0; f < num_faces; ++f) {
    const int n = volume ? static_cast<int>(ho::faces(shape)[f].size()) : nv;
    const auto count = static_cast<std::size_t>(face_interior_count(n, order_));
    const NodeId* run = face_pool_.data() + face_first[f];
    if (codes[f] == 0)
      std::copy_n(run, count, ids + at);
    else
      for (std::size_t j = 0; j < count; ++j) ids[at + j] = run[layout.slots[at + j].slot[codes[f]]];
    at += count;
  }
  std::copy_n(interior_pool_.data() + first_interior, layout.num_interior, ids + at);
}

void Mesh::assemble_by_slots(ho::Shape shape, const NodeId* vertices, const std::uint32_t* edge_ids,
                             std::uint16_t reversed, const std::uint32_t* face_ids, const std::uint8_t* codes,
                             std::uint32_t first_interior, std::vector<NodeId>& out) const {
  const NodeLayout& layout = node_layout(shape, order_);
  out.resize(layout.slots.size());
  for (std::size_t i = 0; i < layout.slots.size(); ++i) {
    const NodeSlot& s = layout.slots[i];
    switch (s.kind) {
      case NodeSlot::Vertex: out[i] = vertices[s.local]; break;
      case NodeSlot::Edge:
        out[i] = edge_pool_[edges_[edge_ids[s.local]].first_node + s.slot[(reversed >> s.local) & 1u]];
        break;
      case NodeSlot::Face: out[i] = face_pool_[faces_[face_ids[s.local]].first_node + s.slot[codes[s.local]]]; break;
      case NodeSlot::Interior: out[i] = interior_pool_[first_interior + s.slot[0]]; break;
    }
  }
}

void Mesh::element_nodes(std::size_t element, std::vector<NodeId>& out) const {
  const Element& el = elements_.at(element);
  assemble(el.shape, el.vertices.data(), el.edges.data(), el.edge_reversed, el.faces.data(),
           el.face_orientation.data(), el.first_node, out);
}

void Mesh::element_nodes_at(std::size_t element, const std::vector<int>& positions, std::vector<NodeId>& out) const {
  const Element& el = elements_.at(element);
  const NodeLayout& layout = node_layout(el.shape, order_);
  out.resize(positions.size());
  for (std::size_t k = 0; k < positions.size(); ++k) {
    const NodeSlot& s = layout.slots.at(static_cast<std::size_t>(positions[k]));
    switch (s.kind) {
      case NodeSlot::Vertex: out[k] = el.vertices[s.local]; break;
      case NodeSlot::Edge:
        out[k] = edge_pool_[edges_[el.edges[s.local]].first_node + s.slot[(el.edge_reversed >> s.local) & 1u]];
        break;
      case NodeSlot::Face:
        out[k] = face_pool_[faces_[el.faces[s.local]].first_node + s.slot[el.face_orientation[s.local]]];
        break;
      case NodeSlot::Interior: out[k] = interior_pool_[el.first_node + s.slot[0]]; break;
    }
  }
}

std::vector<NodeId> Mesh::element_nodes_by_slots(std::size_t element) const {
  const Element& el = elements_.at(element);
  std::vector<NodeId> out;
  assemble_by_slots(el.shape, el.vertices.data(), el.edges.data(), el.edge_reversed, el.faces.data(),
                    el.face_orientation.data(), el.first_node, out);
  return out;
}

std::vector<NodeId> Mesh::boundary_face_nodes_by_slots(std::size_t boundary_face) const {
  const BoundaryFace& bf = boundary_.at(boundary_face);
  std::vector<NodeId> out;
  assemble_by_slots(bf.shape, bf.vertices.data(), bf.edges.data(), bf.edge_reversed, &bf.face, &bf.face_orientation,
                    0, out);
  return out;
}

std::vector<NodeId> Mesh::element_nodes(std::size_t element) const {
  std::vector<NodeId> out;
  element_nodes(element, out);
  return out;
}

Eigen::MatrixX3d Mesh::element_coordinates(std::size_t element) const {
  Eigen::MatrixX3d x;
  element_coordinates(element, x);
  return x;
}

void Mesh::element_coordinates(std::size_t element, Eigen::MatrixX3d& out) const {
  thread_local std::vector<NodeId> ids;
  element_nodes(element, ids);
  out.resize(static_cast<Eigen::Index>(ids.size()), 3);
  for (std::size_t i = 0; i < ids.size(); ++i) out.row(static_cast<Eigen::Index>(i)) = nodes_[ids[i]].transpose();
}

std::vector<NodeId> Mesh::boundary_face_nodes(std::size_t boundary_face) const {
  const BoundaryFace& bf = boundary_.at(boundary_face);
  std::vector<NodeId> out;
  assemble(bf.shape, bf.vertices.data(), bf.edges.data(), bf.edge_reversed, &bf.face, &bf.face_orientation, 0, out);
  return out;
}

std::vector<NodeId> Mesh::edge_nodes(std::size_t edge) const {
  std::vector<NodeId> out;
  edge_nodes(edge, out);
  return out;
}

void Mesh::edge_nodes(std::size_t edge, std::vector<NodeId>& out) const {
  const Edge& e = edges_.at(edge);
  const int n = edge_interior_count(order_);
  out.resize(n + 2);
  out.front() = e.vertices[0];
  std::copy_n(edge_pool_.begin() + e.first_node, n, out.begin() + 1);
  out.back() = e.vertices[1];
}

std::vector<NodeId> Mesh::face_nodes(std::size_t face) const {
  std::vector<NodeId> out;
  face_nodes(face, out);
  return out;
}

void Mesh::face_nodes(std::size_t face, std::vector<NodeId>& out) const {
  const Face& f = faces_.at(face);
  const ho::Shape shape = f.num_vertices == 3 ? ho::Shape::Triangle : ho::Shape::Quadrilateral;
  const auto id = static_cast<std::uint32_t>(face);
  const std::uint8_t identity = 0;
  assemble(shape, f.vertices.data(), f.edges.data(), f.edge_reversed, &id, &identity, 0, out);
}

std::vector<char> Mesh::referenced_nodes() const {
  // An element's node list is its vertices, every node of its edges and faces and its interior
  // nodes (assemble): marked through the entities, each pool entry once, without assembling lists.
  std::vector<char> used(nodes_.size(), 0), edge_used(edges_.size(), 0), face_used(faces_.size(), 0);
  for (const Element& el : elements_) {
    for (int k = 0; k < ho::num_vertices(el.shape); ++k) used[el.vertices[k]] = 1;
    for (std::size_t k = 0; k < ho::edges(el.shape).size(); ++k) edge_used[el.edges[k]] = 1;
    for (std::size_t k = 0; k < ho::faces(el.shape).size(); ++k) face_used[el.faces[k]] = 1;
    const int interior = node_layout(el.shape, order_).num_interior;
    for (int k = 0; k < interior; ++k) used[interior_pool_[el.first_node + k]] = 1;
  }
  for (const BoundaryFace& bf : boundary_) {
    for (int k = 0; k < ho::num_vertices(bf.shape); ++k) used[bf.vertices[k]] = 1;
    for (std::size_t k = 0; k < ho::edges(bf.shape).size(); ++k) edge_used[bf.edges[k]] = 1;
    face_used[bf.face] = 1;
  }
  const int per_edge = edge_interior_count(order_);
  for (std::size_t e = 0; e < edges_.size(); ++e)
    if (edge_used[e])
      for (int k = 0; k < per_edge; ++k) used[edge_pool_[edges_[e].first_node + k]] = 1;
  for (std::size_t f = 0; f < faces_.size(); ++f)
    if (face_used[f])
      for (int k = 0; k < face_interior_count(faces_[f].num_vertices, order_); ++k)
        used[face_pool_[faces_[f].first_node + k]] = 1;
  return used;
}

std::vector<NodeId> Mesh::compact_nodes(const std::vector<char>& used,
                                        const std::unordered_map<NodeId, Eigen::Vector3d>& moved) {
  std::vector<NodeId> new_id(nodes_.size(), kNoNode);
  NodeId next = 0;
  for (NodeId id = 0; id < nodes_.size(); ++id) {
    if (!used[id]) continue;
    nodes_[next] = nodes_[id];  // next <= id: never a node still to be read
    new_id[id] = next++;
  }
  nodes_.resize(next);
  // The few moved and attached nodes from their own maps: a lookup per node cost more than the copy.
  for (const auto& [id, x] : moved)
    if (id < new_id.size() && new_id[id] != kNoNode) nodes_[new_id[id]] = x;
  NodeMap<CadAttachment> cad;
  cad.reserve(cad_.size());
  cad_.for_each([&](NodeId id, const CadAttachment& attachment) {
    if (new_id[id] != kNoNode) cad.set(new_id[id], attachment);
  });
  cad_ = std::move(cad);
  return new_id;
}

Mesh::EntityUpdate Mesh::replace_nodes(std::vector<NodeId> to, const std::unordered_map<NodeId, Eigen::Vector3d>& moved,
                                       const std::function<void(double)>& done, std::atomic<std::size_t>* rebuilt) {
  return replace_nodes_with(true, std::move(to), moved, done, rebuilt);
}

void Mesh::replace_nodes_by_rebuild(std::vector<NodeId> to, const std::unordered_map<NodeId, Eigen::Vector3d>& moved,
                                    const std::function<void(double)>& done, std::atomic<std::size_t>* rebuilt) {
  replace_nodes_with(false, std::move(to), moved, done, rebuilt);
}

Mesh::EntityUpdate Mesh::replace_nodes_with(bool remap, std::vector<NodeId> to,
                                            const std::unordered_map<NodeId, Eigen::Vector3d>& moved,
                                            const std::function<void(double)>& done, std::atomic<std::size_t>* rebuilt) {
  for (const auto& [id, x] : moved)
    if (cad_attachment(id).kind != CadAttachment::None)
      throw std::invalid_argument("Mesh::replace_nodes: node " + std::to_string(id) +
                                  " is attached to the CAD and cannot be moved off it");
  if (to.size() != nodes_.size())
    throw std::invalid_argument("Mesh::replace_nodes: a map of " + std::to_string(to.size()) +
                                " nodes for a mesh of " + std::to_string(nodes_.size()));
  // The merges are found in the old ids, through the old lookups, before anything changes; on
  // another thread while this one marks the nodes still used (both only read the mesh).
  std::future<EntityMerges> merging;
  if (remap) {
    try {
      merging = std::async(std::launch::async, [&] { return entity_merges(to); });
    } catch (const std::system_error&) {  // no thread to be had: found below, on this one
    }
  }
  std::vector<char> used(nodes_.size(), 0);
  {
    const std::vector<char> referenced = referenced_nodes();
    for (NodeId v = 0; v < nodes_.size(); ++v)
      if (referenced[v]) used[to[v]] = 1;
  }
  const EntityMerges merges = merging.valid() ? merging.get() : remap ? entity_merges(to) : EntityMerges{};
  // The order a rebuild meets the entities in, on another thread while this one compacts the nodes:
  // it reads the elements' and boundary faces' entity ids only, which nothing below changes before
  // it is taken.
  const bool remapping = remap && !merges.collapsed;
  std::future<EntityOrder> ordering;
  if (remapping) {
    try {
      ordering = std::async(std::launch::async, [&] { return entity_order(merges); });
    } catch (const std::system_error&) {  // no thread to be had: found below, on this one
    }
  }
  {
    // `to` then leads straight to the new ids: one map of 4 bytes a node held through the rebuild.
    const std::vector<NodeId> new_id = compact_nodes(used, moved);
    for (NodeId& t : to) t = t < new_id.size() ? new_id[t] : kNoNode;
  }
  used = {};
  const EntityOrder order = ordering.valid() ? ordering.get() : remapping ? entity_order(merges) : EntityOrder{};
  // The old entities move into a mesh of their own, which still assembles the old node lists. The
  // elements stay: each is rebuilt in its own place once its old node list is read (held once).
  Mesh old(order_, node_set_);
  old.edges_ = std::move(edges_), old.faces_ = std::move(faces_), old.boundary_ = std::move(boundary_);
  old.edge_pool_ = std::move(edge_pool_), old.face_pool_ = std::move(face_pool_);
  old.interior_pool_ = std::move(interior_pool_);
  edges_ = {}, faces_ = {}, boundary_ = {};
  edge_pool_ = {}, face_pool_ = {}, interior_pool_ = {};
  edge_index_.clear(), face_index_.clear();
  if (remapping && remap_entities(old, to, merges, order)) {
    if (rebuilt) rebuilt->store(elements_.size(), std::memory_order_release);
    if (done) done(1.0);
    return EntityUpdate::Remapped;
  }
  // The rebuilt mesh has at most the old entities and pool entries: sized so, nothing regrows (a
  // vector that doubles holds its old and new copies at once).
  boundary_.reserve(old.boundary_.size());
  edges_.reserve(old.edges_.size()), faces_.reserve(old.faces_.size());
  edge_pool_.reserve(old.edge_pool_.size()), face_pool_.reserve(old.face_pool_.size());
  interior_pool_.reserve(old.interior_pool_.size());
  edge_index_.reserve(old.edges_.size(), [&](std::uint32_t e) { return edge_hash(e); });
  face_index_.reserve(old.faces_.size(), [&](std::uint32_t f) { return face_hash(f); });
  // The old node lists a block ahead (link_in_blocks): they read the old entities, `to` and the
  // elements of their block only; this thread links the block before, writing the new entities
  // and that block's elements.
  const std::size_t count = elements_.size(), report_every = std::max<std::size_t>(1, count / 100);
  link_in_blocks(
      count,
      [&](std::size_t first, std::vector<std::vector<NodeId>>& lists) {
        for (std::size_t k = 0; k < lists.size(); ++k) {
          const Element& was = elements_[first + k];
          old.assemble(was.shape, was.vertices.data(), was.edges.data(), was.edge_reversed, was.faces.data(),
                       was.face_orientation.data(), was.first_node, lists[k]);
          for (NodeId& id : lists[k]) id = to[id];
        }
      },
      [&](std::size_t e, const std::vector<NodeId>& ids) {
        if (done && e % report_every == 0) done(static_cast<double>(e) / static_cast<double>(count));
        const Element& was = elements_[e];
        elements_[e] = linked_element(was.shape, ids, was.region, e);
        // The entities were reserved at their largest: no vector moves under a reader of element e.
        if (rebuilt) rebuilt->store(e + 1, std::memory_order_release);
      });
  std::vector<NodeId> ids;
  for (std::size_t b = 0; b < old.boundary_.size(); ++b) {
    ids = old.boundary_face_nodes(b);
    for (NodeId& id : ids) id = to[id];
    add_boundary_face(groups_[old.boundary_[b].group], old.boundary_[b].shape, ids);
  }
  if (done) done(1.0);
  return EntityUpdate::Rebuilt;
}

std::size_t Mesh::memory_bytes() const {
  std::size_t bytes = sizeof(*this);
  bytes += nodes_.capacity() * sizeof(Eigen::Vector3d);
  bytes += edges_.capacity() * sizeof(Edge) + faces_.capacity() * sizeof(Face);
  bytes += elements_.capacity() * sizeof(Element) + boundary_.capacity() * sizeof(BoundaryFace);
  bytes += (edge_pool_.capacity() + face_pool_.capacity() + interior_pool_.capacity()) * sizeof(NodeId);
  bytes += cad_.memory_bytes();
  bytes += edge_index_.memory_bytes() + face_index_.memory_bytes();
  for (const auto& g : groups_) bytes += sizeof(g) + g.capacity();
  for (const auto& r : regions_) bytes += sizeof(r) + r.capacity();
  return bytes;
}

}  // namespace semimesh::mesh
