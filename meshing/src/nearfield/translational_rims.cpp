#include "translational_rims.hpp"

#include "semimesh/ho/element_type.hpp"
#include "semimesh/ho/validity.hpp"
#include "semimesh/nearfield/error.hpp"

#include "labels.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace semimesh::nearfield::detail {
namespace {

using mesh::NodeId;

// The surface of the one layer triangle on each open edge (sorted layer node pair).
std::map<std::pair<int, int>, int> open_edge_surfaces(const BodyMesh& layer) {
  std::map<std::pair<int, int>, int> surface;
  for (std::size_t t = 0; t < layer.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = layer.triangles[t][k], b = layer.triangles[t][(k + 1) % 3];
      surface[{std::min(a, b), std::max(a, b)}] = layer.triangle_surface[t];
    }
  return surface;
}

// Every element using a moved node still valid (first order); otherwise the place is named.
void check_elements_around(const mesh::Mesh& m, const std::set<NodeId>& moved) {
  for (const mesh::Element& e : m.elements()) {
    const int n = ho::num_vertices(e.shape);
    if (std::none_of(e.vertices.begin(), e.vertices.begin() + n, [&](NodeId v) { return moved.count(v) > 0; }))
      continue;
    Eigen::MatrixX3d x(n, 3);
    for (int k = 0; k < n; ++k) x.row(k) = m.node(e.vertices[k]).transpose();
    if (!ho::certify_jacobian(e.shape, 1, ho::NodeSet::Equispaced, x).valid)
      throw NearFieldError("near field: output.target = \"pyfr\": the wing layer's prism at " +
                           point_label(m.node(e.vertices[0])) +
                           " folds once the layer edges over the trailing edge are made one vector per side "
                           "(PyFR's parallelogram rule); use a finer trailing edge or a thinner layer");
  }
}

}  // namespace

TranslationalRims make_rear_interfaces_translational(JunctionShell& js, const Vec3* along) {
  mesh::Mesh& m = js.field.mesh;
  const std::set<int> chain(js.chain.begin(), js.chain.end());
  const bool sharp = std::any_of(js.crack.begin(), js.crack.end(), [](char c) { return c != 0; });
  const auto surface_of = open_edge_surfaces(js.layer);
  std::map<int, std::set<int>> sides_of;  // layer node -> the sides whose rear interfaces it bounds
  for (const auto& [a, b] : open_edges(js.layer)) {
    const NodeId na = js.layer_body[a], nb = js.layer_body[b];
    if (chain.count(static_cast<int>(na)) && chain.count(static_cast<int>(nb))) continue;  // the root row
    if (sharp && !(js.crack[na] && js.crack[nb])) continue;  // a bare triangle's rim: no wake behind it
    const int side = surface_of.at({std::min(a, b), std::max(a, b)});
    sides_of[a].insert(side), sides_of[b].insert(side);
  }
  TranslationalRims rims;
  std::map<int, std::vector<int>> nodes_of;  // side -> its own nodes (no corner, no strip top)
  std::vector<int> corners;                  // nodes two sides share, off the root row
  for (const auto& [v, sides] : sides_of) {
    const bool on_root_row = chain.count(static_cast<int>(js.layer_body[v])) > 0;
    if (sides.size() != 1) {
      if (!on_root_row) corners.push_back(v);
      continue;
    }
    if (on_root_row)
      rims.root_corner[v] = *sides.begin();
    else
      nodes_of[*sides.begin()].push_back(v);
  }
  auto edge_of = [&](int v) { return Vec3(m.node(static_cast<NodeId>(v) + js.offset) - m.node(js.layer_body[v])); };
  for (const auto& [side, nodes] : nodes_of) {
    Vec3 mean = Vec3::Zero();
    for (int v : nodes) mean += edge_of(v);
    rims.side_edge[side] = mean / static_cast<double>(nodes.size());
  }
  std::map<int, Vec3> corner_edge;
  if (along) {
    // One reach downstream for every layer edge: the largest, as lowering one could tip its prism's
    // top over the next one upstream.
    double reach = -1e300;
    for (const auto& [side, edge] : rims.side_edge) reach = std::max(reach, edge.dot(*along));
    for (int v : corners) reach = std::max(reach, edge_of(v).dot(*along));
    for (auto& [side, edge] : rims.side_edge) edge += (reach - edge.dot(*along)) * *along;
    for (int v : corners) corner_edge[v] = edge_of(v) + (reach - edge_of(v).dot(*along)) * *along;
  }
  std::set<NodeId> moved;
  auto place = [&](int v, const Vec3& edge) {
    m.place_node(static_cast<NodeId>(v) + js.offset, m.node(js.layer_body[v]) + edge);
    moved.insert(static_cast<NodeId>(v) + js.offset);
  };
  for (const auto& [side, nodes] : nodes_of)
    for (int v : nodes) place(v, rims.side_edge.at(side));
  for (const auto& [v, edge] : corner_edge) place(v, edge);
  check_elements_around(m, moved);
  rims.moved = moved.size();
  return rims;
}

}  // namespace semimesh::nearfield::detail
