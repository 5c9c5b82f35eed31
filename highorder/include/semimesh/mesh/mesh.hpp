// The mesh data model (docs/architecture.md, section 3).
//
// All nodes (vertices and high-order nodes) live in one array and are named by a NodeId. Edges and
// faces are shared entities keyed by their sorted vertex ids; each owns the nodes strictly inside
// it exactly once, so two elements that share an edge or face use the same nodes and conform by
// construction.
//  - An edge stores its vertices sorted (low id first); that is its own direction, and its
//    interior nodes run from vertices[0] to vertices[1].
//  - A face stores its vertices in the order of the element that created it (its reference
//    orientation); its interior nodes are in the canonical (Gmsh) order of a triangle/quad of
//    order P whose vertices are the stored ones. An element records, per face, the orientation
//    code relating its local face to the stored one (see node_layout.hpp).
//  - An element stores its shape, vertex ids, edge ids (with a reversed bit), face ids (with the
//    orientation code) and owns its interior nodes.
// All elements of a mesh share one order P and one node set.
//
// Every element belongs to a named region (block: "wing_layer", "wall_layer", "junction", "wake",
// "farfield"; region 0 is "fluid" until a builder names its own), which every stage keeps and every
// writer emits. Boundary faces (triangles and quadrilaterals) belong to named groups ("wing", "wall", ...); they
// reference the shared face entity and keep their own (outward) vertex order. Every node can carry
// one CAD attachment; it is changed only together with the node position.
#pragma once

#include "semimesh/ho/element_type.hpp"
#include "semimesh/mesh/id_table.hpp"
#include "semimesh/mesh/node_map.hpp"

#include <Eigen/Core>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

namespace semimesh::mesh {

struct NodeLayout;  // node_layout.hpp

using NodeId = std::uint32_t;
constexpr NodeId kNoNode = 0xffffffffu;

/// Where a node sits on the CAD model: nothing, a CAD vertex, a curve at parameter u, or a surface
/// at (u, v). `entity` is the cadapi id of the vertex/curve/surface.
struct CadAttachment {
  enum Kind { None, Vertex, Curve, Surface };
  Kind kind = None;
  int entity = -1;
  double u = 0.0;
  double v = 0.0;
};

struct Edge {
  std::array<NodeId, 2> vertices{};  ///< sorted ascending: the edge's own direction
  std::uint32_t first_node = 0;      ///< interior nodes: Mesh::edge_pool()[first_node, +P-1)
};

struct Face {
  std::array<NodeId, 4> vertices{kNoNode, kNoNode, kNoNode, kNoNode};  ///< reference orientation
  std::array<std::uint32_t, 4> edges{};  ///< edge ids in ho::edges(tri/quad) order of `vertices`
  std::uint32_t first_node = 0;          ///< interior nodes: Mesh::face_pool()[first_node, +count)
  std::uint8_t num_vertices = 0;         ///< 3 or 4
  std::uint8_t edge_reversed = 0;        ///< bit e set: local edge e runs against the edge
};

struct Element {
  ho::Shape shape = ho::Shape::Tetrahedron;
  std::array<NodeId, 8> vertices{};           ///< first num_vertices(shape) used, canonical order
  std::array<std::uint32_t, 12> edges{};      ///< edge ids in ho::edges(shape) order
  std::uint16_t edge_reversed = 0;            ///< bit e set: local edge e runs against the edge
  std::array<std::uint32_t, 6> faces{};       ///< face ids in ho::faces(shape) order
  std::array<std::uint8_t, 6> face_orientation{};  ///< code per face (node_layout.hpp)
  std::uint32_t first_node = 0;               ///< interior nodes: Mesh::interior_pool()[first_node, +n)
  std::uint16_t region = 0;                   ///< index into Mesh::region_names(): the block it belongs to
};

struct BoundaryFace {
  ho::Shape shape = ho::Shape::Triangle;  ///< Triangle or Quadrilateral
  std::array<NodeId, 4> vertices{};       ///< the boundary element's own vertex order
  std::array<std::uint32_t, 4> edges{};
  std::uint8_t edge_reversed = 0;
  std::uint32_t face = 0;                 ///< shared face entity
  std::uint8_t face_orientation = 0;
  std::uint16_t group = 0;                ///< index into Mesh::group_names()
};

class Mesh {
 public:
  /// order in [1, ho::kMaxOrder].
  explicit Mesh(int order = 1, ho::NodeSet node_set = ho::NodeSet::Equispaced);

  int order() const { return order_; }
  ho::NodeSet node_set() const { return node_set_; }
  /// Declares that the nodes now sit at the positions of another node set; only for code that has
  /// just moved every node accordingly (io::to_equispaced).
  void relabel_node_set(ho::NodeSet set) { node_set_ = set; }

  // ---- nodes ----------------------------------------------------------------------------------
  NodeId add_node(const Eigen::Vector3d& x, const CadAttachment& cad = {});
  std::size_t num_nodes() const { return nodes_.size(); }
  const Eigen::Vector3d& node(NodeId id) const { return nodes_[id]; }
  const std::vector<Eigen::Vector3d>& nodes() const { return nodes_; }
  /// The node's CAD attachment (kind None if it has none).
  const CadAttachment& cad_attachment(NodeId id) const;
  /// Moves a node that has no CAD attachment; throws std::logic_error if it has one (its
  /// parameters would go stale: use place_node_on_cad).
  void place_node(NodeId id, const Eigen::Vector3d& x);
  /// Moves a node and sets its CAD attachment in one step (kind None detaches it).
  void place_node_on_cad(NodeId id, const Eigen::Vector3d& x, const CadAttachment& cad);
  /// Forgets every CAD attachment (e.g. on a resampled copy whose nodes are new points).
  void clear_cad_attachments() { cad_.clear(); }

  // ---- building -------------------------------------------------------------------------------
  /// Adds a 3D element from its full canonical (Gmsh-order) node list of num_nodes(shape, P) ids,
  /// in region `region` (an index from region_index; 0, "fluid", by default).
  /// Edges and faces are created or found by their vertices. If an edge/face already exists, the
  /// nodes given for it must be the stored ones or sit at the same place (else the elements do
  /// not conform: std::invalid_argument naming the element and the entity). Returns its index.
  std::size_t add_element(ho::Shape shape, const std::vector<NodeId>& canonical_nodes, int region = 0);
  /// add_element of elements [first, end) of `other` (a mesh whose node ids mean the same nodes
  /// here), in order, with their regions: the same elements, entities and errors; their node lists
  /// are read from `other` a block ahead on another thread.
  void add_elements_of(const Mesh& other, std::size_t first, std::size_t end);
  /// add_element of each linear element of `shape` in `vertices` (num_vertices(shape) ids each, in
  /// canonical order), in order, in region `region`: the same elements, entities and ids, linked on
  /// two threads (edges, and a block behind them faces). Only for a mesh of order 1. The refusals of
  /// an unknown node id or a repeated vertex (naming the element) come before anything is added;
  /// after any other (a twisted quadrilateral face) none of these elements is added.
  void add_linear_elements(ho::Shape shape, const std::vector<NodeId>& vertices, int region = 0);
  /// Takes the edges and faces of `linear`, a mesh with the same vertices (same ids) whose elements
  /// this mesh is about to get in the same order at its own order (ho::curve_mesh): the same
  /// entity ids, vertices, reference orientations and lookups (no key is hashed again), each
  /// entity owning the nodes given here: edge e the P - 1 of edge_nodes[e * (P - 1), ...) from its
  /// vertices[0] to vertices[1], face f the first face_interior_count of face_nodes[f *
  /// face_stride, ...) in the canonical order of its stored vertices. The elements then come from
  /// add_element_as. Throws std::logic_error if this mesh has elements or entities already, and
  /// std::invalid_argument if the node lists do not have those sizes.
  void adopt_entities(const Mesh& linear, const std::vector<NodeId>& edge_nodes, const std::vector<NodeId>& face_nodes,
                      std::size_t face_stride);
  /// Takes every edge and face of `other` (a mesh of the same order whose node ids mean the same
  /// nodes here) with their ids, nodes and lookups, so that its elements can come over as they are
  /// (add_elements_as_in) while new elements find or add entities as usual (add_element). Entities
  /// that no element comes to use stay, unused: replace_nodes (without_unreferenced_nodes) drops
  /// them, and renumbers the rest as add_element in element order would have. Throws
  /// std::logic_error if this mesh has elements or entities already, std::invalid_argument if the
  /// orders differ or `lookups_from` is given and is not `other`. `lookups_from`: `other` itself,
  /// given up: its lookups move here instead of being copied, and it is left without any (its
  /// find_edge and find_face then find nothing; its elements and entities stay readable).
  void adopt_all_entities(const Mesh& other, Mesh* lookups_from = nullptr);
  /// Elements [first, end) of `other`, whose entities this mesh took (adopt_all_entities, same
  /// ids), as they are, with their regions and interior nodes: the elements add_element would
  /// make of their node lists, without a lookup. Throws std::logic_error unless this mesh took
  /// `other`'s entities, std::out_of_range for a bad range.
  void add_elements_as_in(const Mesh& other, std::size_t first, std::size_t end);
  /// add_element of element `element` of `linear` (whose entities adopt_entities took), the next
  /// one, from its full canonical node list at this mesh's order: its edges, faces and their
  /// orientations are linear's element's; its interior nodes are appended. The list must give the
  /// element's vertices and the adopted entities' nodes (else std::logic_error naming the element:
  /// the same mesh add_element would build, or none). Returns its index.
  std::size_t add_element_as(const Mesh& linear, std::size_t element, const std::vector<NodeId>& canonical_nodes);
  /// add_element_as given only the element's interior nodes (in canonical order; none for a shape
  /// without), for a caller whose other nodes are the adopted entities' by construction (ho::curve_mesh,
  /// whose output tests pin to add_element's): nothing else is compared (add_element_as is this
  /// plus that comparison). Throws as add_element_as for the order of elements, the region, a
  /// count or an unknown node id.
  std::size_t add_element_adopted(const Mesh& linear, std::size_t element, const std::vector<NodeId>& interior_nodes);
  /// Adds a boundary triangle/quad (full canonical node list) to group `group` (created on first
  /// use). Its face entity is shared with the volume element that has the same vertices.
  std::size_t add_boundary_face(const std::string& group, ho::Shape shape, const std::vector<NodeId>& canonical_nodes);
  /// Moves boundary face `face` to group `group` (created on first use): a far-field face found to
  /// lie on a symmetry plane. Throws std::out_of_range for a face that does not exist.
  void set_boundary_group(std::size_t face, const std::string& group);
  /// Index of a group, creating it if new.
  int group_index(const std::string& name);
  /// Index of a region, creating it if new.
  int region_index(const std::string& name);
  /// Gives this mesh the regions of `other` with the same indices (for stages that copy elements
  /// into a new mesh). Throws std::logic_error if this mesh already has different regions.
  void copy_regions_from(const Mesh& other);
  /// Reserves storage for about this many elements of one shape (avoids regrowing; optional).
  void reserve(ho::Shape typical_shape, std::size_t num_elements);
  /// Sizes the edge and face lookups for this many entities (a builder that knows its counts: the
  /// curving's are its input's): no table is rehashed as it fills, each rehash reading every
  /// entity's key again (optional; the tables take the size they would grow to).
  void reserve_lookups(std::size_t num_edges, std::size_t num_faces);
  /// Reserves storage for this many nodes (avoids regrowing; optional).
  void reserve_nodes(std::size_t num_nodes) { nodes_.reserve(num_nodes); }
  /// Reserves storage for exactly this many elements holding this many interior nodes in all, for
  /// a builder that knows its counts (optional): no regrowth copies them, and no room is touched
  /// that the mesh will not use.
  void reserve_elements(std::size_t num_elements, std::size_t num_interior_nodes) {
    elements_.reserve(num_elements);
    interior_pool_.reserve(num_interior_nodes);
  }
  /// Takes the nodes and CAD attachments of `other` (same ids; this mesh must have none), leaving it
  /// without nodes: for a stage that builds a new mesh on an old one's nodes and reads the old one's
  /// topology only (ho::split_layers).
  void take_nodes(Mesh& other);
  /// A copy of the nodes and CAD attachments of `other` (same ids; this mesh must have none), into
  /// the room reserve_nodes made: add_node of each in turn, without a lookup of each one's attachment.
  void copy_nodes(const Mesh& other);
  /// Every node's position, to be moved to another node set's positions of the same element maps
  /// and back (io::EquispacedNodes for the writers): the CAD attachments and the node set are left
  /// as they are, so nobody else may read the positions until they are back.
  std::vector<Eigen::Vector3d>& positions_for_resampling() { return nodes_; }

  // ---- entities -------------------------------------------------------------------------------
  const std::vector<Edge>& edges() const { return edges_; }
  const std::vector<Face>& faces() const { return faces_; }
  const std::vector<Element>& elements() const { return elements_; }
  const std::vector<BoundaryFace>& boundary_faces() const { return boundary_; }
  const std::vector<std::string>& group_names() const { return groups_; }
  const std::vector<std::string>& region_names() const { return regions_; }
  const std::vector<NodeId>& edge_pool() const { return edge_pool_; }
  const std::vector<NodeId>& face_pool() const { return face_pool_; }
  const std::vector<NodeId>& interior_pool() const { return interior_pool_; }
  /// Id of the edge / face with these vertices (any order), or -1.
  long find_edge(NodeId a, NodeId b) const;
  long find_face(const std::vector<NodeId>& vertices) const;

  // ---- assembly -------------------------------------------------------------------------------
  /// Node ids of an element in canonical (Gmsh) order, shape (num_nodes(shape, P)).
  std::vector<NodeId> element_nodes(std::size_t element) const;
  void element_nodes(std::size_t element, std::vector<NodeId>& out) const;
  /// The element's node ids at canonical positions `positions` (indices into element_nodes), in
  /// that order: element_nodes(element)[positions[k]] without assembling the others (a face's
  /// nodes out of a hexahedron's 125 at order 4).
  void element_nodes_at(std::size_t element, const std::vector<int>& positions, std::vector<NodeId>& out) const;
  /// Node coordinates of an element in canonical order, shape (num_nodes, 3).
  Eigen::MatrixX3d element_coordinates(std::size_t element) const;
  /// The same into `out` (resized), through a buffer of the calling thread's for the ids: no
  /// allocation per element in the loops that read every element's nodes.
  void element_coordinates(std::size_t element, Eigen::MatrixX3d& out) const;
  /// Node ids of a boundary face in canonical order of its own vertex order.
  std::vector<NodeId> boundary_face_nodes(std::size_t boundary_face) const;
  /// element_nodes and boundary_face_nodes as their slow reference gathers them (node by node
  /// through its layout slot, where the fast path copies runs): the tests pin them together.
  std::vector<NodeId> element_nodes_by_slots(std::size_t element) const;
  std::vector<NodeId> boundary_face_nodes_by_slots(std::size_t boundary_face) const;
  /// Node ids along an edge, vertices included, from vertices[0] to vertices[1]; shape (P+1).
  std::vector<NodeId> edge_nodes(std::size_t edge) const;
  void edge_nodes(std::size_t edge, std::vector<NodeId>& out) const;
  /// Node ids of a face in the canonical order of a tri/quad whose vertices are the stored ones.
  std::vector<NodeId> face_nodes(std::size_t face) const;
  void face_nodes(std::size_t face, std::vector<NodeId>& out) const;

  // ---- renumbering ----------------------------------------------------------------------------
  /// Whether some element or boundary face uses node v: [num_nodes()].
  std::vector<char> referenced_nodes() const;
  /// How replace_nodes brought the edges and faces up to date.
  enum class EntityUpdate {
    Remapped,  ///< renamed, merged and renumbered in linear passes (remap_entities.cpp)
    Rebuilt,   ///< rebuilt element by element (replace_nodes_by_rebuild): a case the remap does not take
  };
  /// In place, what mesh::with_nodes_replaced gives (compact.hpp): every node id v of an element or
  /// boundary face replaced by to[v] ([num_nodes()]), only the nodes then referenced kept, in their
  /// relative order with their CAD attachments (those listed in `moved`, by old id, at the listed
  /// points), and the edges, faces and pools exactly as add_element would build them in element
  /// order (replace_nodes_by_rebuild, the reference, does so). The old entities are renamed and the
  /// few whose vertices were merged join the entity holding their new vertices; where that would
  /// not give the rebuild's mesh (merged entities with different inner nodes, an element naming a
  /// vertex twice, a twisted face), the rebuild runs instead and gives its result or its error.
  /// The nodes and elements are held once; the old edges, faces and pools only until the new ones
  /// are built. `to` is taken by value: a caller that moves it in holds no second map of the nodes.
  /// Throws std::invalid_argument, leaving the mesh unchanged, if `to` has the wrong size or a
  /// listed node is attached to the CAD; the exceptions of add_element (two elements giving one
  /// entity different nodes) leave it unusable. `done` (optional) receives the fraction of
  /// elements done, up to a hundred times. `rebuilt` (optional) is set (release) to the number
  /// of elements done: their node lists and the nodes' positions no longer change, and another
  /// thread may read them (element_nodes, element_coordinates, node) while the rest goes on.
  EntityUpdate replace_nodes(std::vector<NodeId> to, const std::unordered_map<NodeId, Eigen::Vector3d>& moved = {},
                             const std::function<void(double)>& done = {}, std::atomic<std::size_t>* rebuilt = nullptr);
  /// replace_nodes by the rebuild alone: each element's renamed node list linked anew, as
  /// add_element does (the reference the remap is tested against).
  void replace_nodes_by_rebuild(std::vector<NodeId> to, const std::unordered_map<NodeId, Eigen::Vector3d>& moved = {},
                                const std::function<void(double)>& done = {},
                                std::atomic<std::size_t>* rebuilt = nullptr);

  /// Bytes held by the mesh (nodes, entities, pools, lookup tables; hash tables estimated).
  std::size_t memory_bytes() const;

 private:
  /// An element or boundary face as errors name it: the text is made for a message only (building
  /// it for every element cost an allocation each).
  struct Named {
    ho::Shape shape;
    std::size_t index;
    const std::string* group;  ///< a boundary face's group; null for an element
    std::string text() const;
  };
  /// `hash`: IdTable::mix of the edge's key.
  std::uint32_t find_or_add_edge(NodeId a, NodeId b, std::uint64_t hash);
  /// `key`: the face's sorted vertices; `edge_ids`: the ids of the face's edges, in the order of its
  /// shape's edges (a new face keeps them).
  std::uint32_t find_or_add_face(const NodeId* local_vertices, int n, const std::array<NodeId, 4>& key,
                                 const std::uint32_t* edge_ids, std::uint8_t& code, const Named& who);
  /// Finds/creates the edges and faces of an element or boundary face and stores (or checks) the
  /// nodes it gives for them. For 2D shapes the single face is the shape itself.
  void link_entities(ho::Shape shape, const std::vector<NodeId>& canonical, const NodeId* vertices,
                     std::uint32_t* edge_ids, std::uint16_t& reversed, std::uint32_t* face_ids, std::uint8_t* codes,
                     const Named& who);
  void check_same_node(NodeId stored, NodeId given, const Named& who) const;
  /// add_element's element (its entities found or created, its interior nodes appended), not yet
  /// stored; `index` names it in errors.
  Element linked_element(ho::Shape shape, const std::vector<NodeId>& canonical_nodes, int region, std::size_t index);
  /// Appends an element's interior nodes (its canonical list's Interior slots) to the interior
  /// pool; returns where they start.
  std::uint32_t append_interior(const NodeLayout& layout, const std::vector<NodeId>& canonical_nodes);
  /// Old edge and face ids whose vertices, renamed by `to` (old ids onto old ids), are those of
  /// another entity: the one they join. `collapsed`: an entity whose renamed vertices repeat.
  struct EntityMerges {
    std::unordered_map<std::uint32_t, std::uint32_t> edges, faces;
    bool collapsed = false;
  };
  EntityMerges entity_merges(const std::vector<NodeId>& to) const;
  /// The order in which a rebuild, element by element then boundary face by boundary face, meets
  /// the entities once `merges` joined some into others: read from the entity ids alone (no node
  /// id), so it is found while the nodes are compacted.
  struct EntityOrder {
    struct FirstUser {
      std::uint32_t owner;
      std::uint8_t local;
      bool boundary;
    };
    std::vector<std::uint32_t> edge_target, face_target;  ///< [old id] the entity it is (itself unless merged)
    std::vector<std::uint32_t> new_edge, new_face;        ///< [old id of a target] its new id
    std::vector<std::uint32_t> edge_order, face_order;    ///< [new id] the old id
    std::vector<FirstUser> first_user;                    ///< [new face id] the element or boundary face meeting it first
  };
  EntityOrder entity_order(const EntityMerges& merges) const;
  /// replace_nodes' remap of the entities moved into `old` (its edges, faces, pools and boundary
  /// faces; this mesh's elements still name them), `to`: old node ids onto new, `order` the
  /// entity_order of `merges`. False, with this mesh's elements and boundary untouched, where the
  /// result would not be the rebuild's.
  bool remap_entities(const Mesh& old, const std::vector<NodeId>& to, const EntityMerges& merges,
                      const EntityOrder& order);
  EntityUpdate replace_nodes_with(bool remap, std::vector<NodeId> to,
                                  const std::unordered_map<NodeId, Eigen::Vector3d>& moved,
                                  const std::function<void(double)>& done, std::atomic<std::size_t>* rebuilt);
  /// Keeps the nodes `used` marks, in order (the `moved` ones at their new points); new id by old.
  std::vector<NodeId> compact_nodes(const std::vector<char>& used,
                                    const std::unordered_map<NodeId, Eigen::Vector3d>& moved);
  void assemble(ho::Shape shape, const NodeId* vertices, const std::uint32_t* edge_ids, std::uint16_t reversed,
                const std::uint32_t* face_ids, const std::uint8_t* codes, std::uint32_t first_interior,
                std::vector<NodeId>& out) const;
  /// assemble's reference: every node through its layout slot, one at a time.
  void assemble_by_slots(ho::Shape shape, const NodeId* vertices, const std::uint32_t* edge_ids,
                         std::uint16_t reversed, const std::uint32_t* face_ids, const std::uint8_t* codes,
                         std::uint32_t first_interior, std::vector<NodeId>& out) const;

  bool has_face_key(std::uint32_t face, const std::array<NodeId, 4>& sorted_vertices) const;
  std::uint64_t edge_hash(std::uint32_t edge) const;
  std::uint64_t face_hash(std::uint32_t face) const;

  int order_;
  ho::NodeSet node_set_;
  std::vector<Eigen::Vector3d> nodes_;
  NodeMap<CadAttachment> cad_;  // sparse: only boundary nodes are attached
  std::vector<Edge> edges_;
  std::vector<Face> faces_;
  std::vector<Element> elements_;
  std::vector<BoundaryFace> boundary_;
  std::vector<std::string> groups_;
  std::vector<std::string> regions_{"fluid"};
  std::vector<NodeId> edge_pool_, face_pool_, interior_pool_;
  IdTable edge_index_;  // edge ids by their vertices
  IdTable face_index_;  // face ids by their sorted vertices
};

}  // namespace semimesh::mesh
