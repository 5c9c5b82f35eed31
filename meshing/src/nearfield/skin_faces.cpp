// The H-type's skin, the near field's outer faces handed to the far field, and its quads cut in
// advance where the split will cut the elements under them.
#include "semimesh/ho/element_type.hpp"
#include "semimesh/mesh/open_faces.hpp"

#include "h_shell_steps.hpp"
#include "labels.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace semimesh::nearfield::h_type {
namespace {

// A face one element uses (its vertices in that element's order), keyed by its sorted vertices.
struct FaceUse {
  std::array<NodeId, 4> key{};
  int count = 3;
  SkinFace face;
};

// Keys in the order of their sorted vertex lists compared as sequences (a shorter one first where
// it is the other's start).
bool key_less(const FaceUse& a, const FaceUse& b) {
  return std::lexicographical_compare(a.key.begin(), a.key.begin() + a.count, b.key.begin(), b.key.begin() + b.count);
}

// The faces exactly one element uses and no boundary face lies on (the open faces), in key order.
std::vector<FaceUse> single_uses(const mesh::Mesh& m) {
  std::vector<FaceUse> single;
  for (const mesh::OpenFace& open : mesh::open_faces(m)) {
    const mesh::Element& el = m.elements()[open.element];
    const std::vector<int>& local = ho::faces(el.shape)[open.local];
    FaceUse u;
    u.count = static_cast<int>(local.size());
    for (int k = 0; k < u.count; ++k) u.face.nodes[k] = el.vertices[local[k]];
    if (u.count == 3) u.face.nodes[3] = mesh::kNoNode;
    u.face.count = u.count;
    std::copy(u.face.nodes.begin(), u.face.nodes.begin() + u.count, u.key.begin());
    std::sort(u.key.begin(), u.key.begin() + u.count);
    single.push_back(u);
  }
  std::sort(single.begin(), single.end(), key_less);
  return single;
}

// Vertex pairs (bottom, top) along reference axis 0, 1, 2 of a hexahedron (Gmsh order).
constexpr int kHexAxisEdges[3][4][2] = {
    {{0, 1}, {3, 2}, {4, 5}, {7, 6}}, {{0, 3}, {1, 2}, {4, 7}, {5, 6}}, {{0, 4}, {1, 5}, {2, 6}, {3, 7}}};

// A layer edge of the near field's stacks: its ends sorted (the key), its bottom and top vertex and
// its family.
struct LayerEdge {
  NodeId lo = 0, hi = 0;
  NodeId bottom = 0, top = 0;
  LayerFamily family = LayerFamily::Wing;
};

// Every layer edge of the stacks, sorted by key (one array and a binary search, not a map node per
// edge); where stacks give an edge more than once, the last stack's entry.
class LayerEdges {
 public:
  explicit LayerEdges(const NearField& f) {
    for (const LayerStack& s : f.stacks) {
      const mesh::Element& e = f.mesh.elements()[s.element];
      for (const LayerDirection& d : s.directions) {
        auto add = [&](int a, int b) {
          const NodeId u = e.vertices[a], w = e.vertices[b];
          edges_.push_back({std::min(u, w), std::max(u, w), u, w, d.family});
        };
        if (e.shape == ho::Shape::Prism)
          for (int i = 0; i < 3; ++i) add(i, i + 3);
        else
          for (const auto& pair : kHexAxisEdges[d.axis]) add(pair[0], pair[1]);
      }
    }
    std::stable_sort(edges_.begin(), edges_.end(), less);
    // Of each run of one key, its last entry (the stack seen last).
    std::size_t kept = 0;
    for (std::size_t i = 0; i < edges_.size(); ++i)
      if (i + 1 == edges_.size() || less(edges_[i], edges_[i + 1])) edges_[kept++] = edges_[i];
    edges_.resize(kept);
  }

  /// The layer edge between a and b (either way round), or null.
  const LayerEdge* find(NodeId a, NodeId b) const {
    const LayerEdge key{std::min(a, b), std::max(a, b)};
    const auto it = std::lower_bound(edges_.begin(), edges_.end(), key, less);
    return it != edges_.end() && it->lo == key.lo && it->hi == key.hi ? &*it : nullptr;
  }

 private:
  static bool less(const LayerEdge& x, const LayerEdge& y) { return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi); }
  std::vector<LayerEdge> edges_;
};

// The split's interfaces on the wing layer's edges as nodes, made once and shared by every skin
// quad on an edge.
class LayerEdgeCuts {
 public:
  LayerEdgeCuts(NearField& field, const LayerFractions& fractions, InterfaceNodes& made)
      : field_(field), fractions_(fractions), edges_(field), made_(made) {}

  bool is_layer_edge(NodeId a, NodeId b) const { return edges_.find(a, b) != nullptr; }

  /// [interfaces] the nodes from -> to on a layer edge.
  std::vector<NodeId> along(NodeId from, NodeId to) {
    mesh::Mesh& m = field_.mesh;
    const LayerEdge* edge = edges_.find(from, to);
    if (!edge)
      throw std::logic_error("H-type skin: no layer edge between nodes " + std::to_string(from) + " and " +
                             std::to_string(to));
    const NodeId bottom = edge->bottom, top = edge->top;
    if (edge->family != LayerFamily::Wing)
      fail("the skin quad at " + point_label(m.node(from)) + " is cut by the wall layer's split (not supported)");
    const std::vector<double> f = fractions_(m.node(bottom), field_.wake);
    std::vector<NodeId> ids;
    for (std::size_t k = 0; k < f.size(); ++k) {
      NodeId id = k == 0 ? bottom : k + 1 == f.size() ? top : mesh::kNoNode;
      if (id == mesh::kNoNode) {
        auto [it, fresh] = made_.emplace(std::make_tuple(bottom, top, static_cast<int>(k)), mesh::kNoNode);
        if (fresh) it->second = m.add_node(m.node(bottom) + f[k] * (m.node(top) - m.node(bottom)));
        id = it->second;
      }
      ids.push_back(id);
    }
    if (bottom != from) std::reverse(ids.begin(), ids.end());
    return ids;
  }

 private:
  NearField& field_;
  const LayerFractions& fractions_;
  LayerEdges edges_;
  InterfaceNodes& made_;
};

}  // namespace

std::vector<SkinFace> skin_faces(const NearField& field, const std::vector<std::set<NodeId>>& fan_planes,
                                 const std::vector<Quad>& exposed_base, const std::vector<std::array<int, 3>>& bare) {
  std::set<NodeId> on_footprint(field.footprint.begin(), field.footprint.end());
  on_footprint.insert(field.footprint_top.begin(), field.footprint_top.end());
  std::vector<SkinFace> skin;
  for (const FaceUse& use : single_uses(field.mesh)) {
    const auto all_in = [&](const std::set<NodeId>& nodes) {
      return std::all_of(use.key.begin(), use.key.begin() + use.count, [&](NodeId v) { return nodes.count(v) > 0; });
    };
    if (!all_in(on_footprint) && std::none_of(fan_planes.begin(), fan_planes.end(), all_in)) skin.push_back(use.face);
  }
  for (const auto& q : exposed_base) skin.push_back({{q[0], q[1], q[2], q[3]}, 4});
  for (const auto& t : bare)
    skin.push_back(
        {{static_cast<NodeId>(t[0]), static_cast<NodeId>(t[1]), static_cast<NodeId>(t[2]), mesh::kNoNode}, 3});
  return skin;
}

void cut_skin_at_split_interfaces(NearField& field, const std::vector<SkinFace>& skin, const LayerFractions& fractions,
                                  InterfaceNodes& interface_node) {
  LayerEdgeCuts cuts(field, fractions, interface_node);
  field.skin.clear();
  for (SkinFace f : skin) {
    if (f.count == 4 && fractions && !cuts.is_layer_edge(f.nodes[0], f.nodes[3]) &&
        cuts.is_layer_edge(f.nodes[0], f.nodes[1]))
      f.nodes = {f.nodes[1], f.nodes[2], f.nodes[3], f.nodes[0]};
    if (f.count != 4 || !fractions || !cuts.is_layer_edge(f.nodes[0], f.nodes[3]) ||
        !cuts.is_layer_edge(f.nodes[1], f.nodes[2])) {
      field.skin.push_back(f);
      continue;
    }
    const std::vector<NodeId> left = cuts.along(f.nodes[0], f.nodes[3]), right = cuts.along(f.nodes[1], f.nodes[2]);
    for (std::size_t k = 0; k + 1 < left.size(); ++k)
      field.skin.push_back({{left[k], right[k], right[k + 1], left[k + 1]}, 4});
  }
}

std::vector<NodeId> outlet_outline(NearField& field, const std::vector<std::vector<NodeId>>& outflow,
                                   const LayerFractions& fractions, InterfaceNodes& interface_node) {
  if (outflow.empty()) return {};
  std::set<std::pair<NodeId, NodeId>> directed;
  for (const auto& f : outflow)
    for (std::size_t k = 0; k < f.size(); ++k) directed.insert({f[k], f[(k + 1) % f.size()]});
  std::map<NodeId, NodeId> next;  // along the outline: the edges no neighbouring face runs back along
  for (const auto& [a, b] : directed)
    if (!directed.count({b, a}) && !next.emplace(a, b).second)
      fail("the wake block's outflow face touches itself at " + point_label(field.mesh.node(a)));
  std::vector<NodeId> corners;
  for (NodeId v = next.begin()->first; corners.size() <= next.size(); v = next.at(v)) {
    if (!corners.empty() && v == corners.front()) break;
    corners.push_back(v);
  }
  if (corners.size() != next.size())
    fail("the wake block's outflow face is not bounded by one loop (" + std::to_string(next.size()) +
         " boundary edges, the loop from " + point_label(field.mesh.node(corners.front())) + " closes after " +
         std::to_string(corners.size()) + ")");
  LayerEdgeCuts cuts(field, fractions, interface_node);
  std::vector<NodeId> loop;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const NodeId a = corners[i], b = corners[(i + 1) % corners.size()];
    if (!fractions || !cuts.is_layer_edge(a, b)) {
      loop.push_back(a);
      continue;
    }
    const std::vector<NodeId> along = cuts.along(a, b);
    loop.insert(loop.end(), along.begin(), along.end() - 1);
  }
  return loop;
}

}  // namespace semimesh::nearfield::h_type
