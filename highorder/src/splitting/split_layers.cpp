#include "semimesh/ho/splitting/split_layers.hpp"

#include "parallel_for.hpp"
#include "reference_lattice.hpp"
#include "semimesh/ho/basis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>

namespace semimesh::ho {
namespace {

using detail::LatticePoint;
using mesh::NodeId;

/// Reference positions z_0 = -1 < z_1 < ... < z_N = 1 of the layer interfaces: thicknesses h r^k,
/// k = 0..N-1, summing to the reference length 2.
std::vector<double> layer_interfaces(int layers, double ratio) {
  std::vector<double> thickness(layers);
  double total = 0.0, h = 1.0;
  for (int k = 0; k < layers; ++k) {
    thickness[k] = h;
    total += h;
    h *= ratio;
  }
  std::vector<double> z(layers + 1, -1.0);
  for (int k = 0; k < layers; ++k) z[k + 1] = z[k] + 2.0 * thickness[k] / total;
  z[layers] = 1.0;
  return z;
}

/// What does not change from one element of a shape to the next.
struct ShapeData {
  Shape shape;
  std::vector<LatticePoint> lattice;        // [nodes] canonical lattice coordinates
  std::map<LatticePoint, int> index;        // lattice point -> canonical index
  Eigen::MatrixX3d reference;               // (nodes, 3) reference nodes of the mesh's node set
  std::vector<int> bottom;                  // local vertices on the face at coordinate -1
  std::vector<int> top_of;                  // [vertices] partner on the opposite face (-1 if none)
  std::vector<std::array<int, 2>> bottom_edges;
  LagrangeBasis basis;                      // order P, the mesh's node set
  LagrangeBasis linear;                     // order 1: weights of the bottom vertices
  Eigen::MatrixXd uniform_values;           // (layers * nodes, nodes) basis at the sub-nodes for a constant ratio
};

ShapeData make_shape_data(Shape shape, int order, NodeSet set, int direction) {
  ShapeData data{shape, detail::lattice_points(shape, order), detail::lattice_index(shape, order),
                 reference_nodes(shape, order, set), {}, {}, {}, LagrangeBasis(shape, order, set),
                 LagrangeBasis(shape, 1, NodeSet::Equispaced), {}};
  const int nv = num_vertices(shape);
  data.top_of.assign(nv, -1);
  for (int v = 0; v < nv; ++v) {
    if (data.lattice[v][direction] != 0) continue;
    data.bottom.push_back(v);
    LatticePoint partner = data.lattice[v];
    partner[direction] = order;
    data.top_of[v] = data.index.at(partner);
  }
  for (const auto& e : edges(shape))
    if (data.lattice[e[0]][direction] == 0 && data.lattice[e[1]][direction] == 0) data.bottom_edges.push_back(e);
  return data;
}

using NodeKey = std::array<std::int64_t, 7>;

// Split elements whose sub-node positions are held at once (bounds the memory of the parallel pass).
constexpr std::size_t kSplitBlock = 1024;

class Splitter {
 public:
  Splitter(const mesh::Mesh& in, int direction, const LayerDistribution& distribution, const RatioField& ratio,
           std::string caller)
      : in_(in), direction_(direction), distribution_(distribution), ratio_(ratio), caller_(std::move(caller)),
        out_(in.order(), in.node_set()) {}

  mesh::Mesh run(const std::vector<std::size_t>& split, SplitStats* stats);

 private:
  const ShapeData& shape_data(Shape shape);
  /// Positions of the sub-element nodes of one coarse element and its first-layer figures; pure
  /// (runs in parallel).
  struct SplitGeometry {
    Eigen::MatrixX3d x;                  // (layers * nodes, 3) layer k's canonical nodes at rows k * nodes
    std::vector<double> first_heights;   // [bottom vertices] first layer height on its vertical edge
    std::vector<double> ratios;          // [bottom vertices] achieved ratio on that edge
  };
  /// Layer interfaces at each bottom vertex of an element (calls the ratio field; serial).
  std::vector<std::vector<double>> interfaces_of(std::size_t element);
  SplitGeometry place_sub_nodes(std::size_t element, const std::vector<std::vector<double>>& z_of_vertex) const;
  /// Sub-element node lists of one coarse element, bottom layer first; creates the new nodes.
  std::vector<std::vector<NodeId>> split_element(std::size_t element, const SplitGeometry& geometry);
  NodeId node_for(const NodeKey& key, const Eigen::Vector3d& x);
  double ratio_at(const Eigen::Vector3d& x, std::size_t element) const;

  const mesh::Mesh& in_;
  int direction_;
  LayerDistribution distribution_;
  RatioField ratio_;
  std::string caller_;
  mesh::Mesh out_;
  std::map<Shape, ShapeData> shapes_;
  std::map<NodeKey, NodeId> created_;
  double height_min_ = 1e300, height_max_ = 0.0, ratio_sum_ = 0.0;
  int vertical_edges_ = 0;
};

const ShapeData& Splitter::shape_data(Shape shape) {
  auto it = shapes_.find(shape);
  if (it != shapes_.end()) return it->second;
  ShapeData data = make_shape_data(shape, in_.order(), in_.node_set(), direction_);
  if (!ratio_) {
    const int N = distribution_.layers, nn = static_cast<int>(data.reference.rows());
    const std::vector<double> z = layer_interfaces(N, distribution_.ratio);
    Eigen::MatrixX3d q(N * nn, 3);
    for (int k = 0; k < N; ++k)
      for (int i = 0; i < nn; ++i) {
        Eigen::RowVector3d r = data.reference.row(i);
        r(direction_) = z[k] + 0.5 * (r(direction_) + 1.0) * (z[k + 1] - z[k]);
        q.row(k * nn + i) = r;
      }
    data.uniform_values = data.basis.values(q);
  }
  return shapes_.emplace(shape, std::move(data)).first->second;
}

double Splitter::ratio_at(const Eigen::Vector3d& x, std::size_t element) const {
  const double r = ratio_ ? ratio_(x) : distribution_.ratio;
  if (!(r >= 1.0) || !std::isfinite(r))
    throw std::invalid_argument(caller_ + ": layer ratio " + std::to_string(r) + " at a vertex of element " +
                                std::to_string(element) + " must be a finite number >= 1");
  return r;
}

NodeId Splitter::node_for(const NodeKey& key, const Eigen::Vector3d& x) {
  const auto it = created_.find(key);
  if (it != created_.end()) return it->second;
  const NodeId id = out_.add_node(x);
  created_.emplace(key, id);
  return id;
}

std::vector<std::vector<double>> Splitter::interfaces_of(std::size_t element) {
  const mesh::Element& el = in_.elements()[element];
  const ShapeData& data = shape_data(el.shape);
  std::vector<std::vector<double>> z_of_vertex(num_vertices(el.shape));
  for (int v : data.bottom)
    z_of_vertex[v] = layer_interfaces(distribution_.layers, ratio_at(in_.node(el.vertices[v]), element));
  return z_of_vertex;
}

Splitter::SplitGeometry Splitter::place_sub_nodes(std::size_t element,
                                                  const std::vector<std::vector<double>>& z_of_vertex) const {
  const mesh::Element& el = in_.elements()[element];
  const ShapeData& data = shapes_.at(el.shape);
  const int N = distribution_.layers, d = direction_;
  const Eigen::MatrixX3d X = in_.element_coordinates(element);
  const int nn = static_cast<int>(X.rows());

  // Interfaces per bottom vertex, interpolated linearly in between (see RatioField).
  const auto interface_at = [&](const Eigen::RowVector3d& q, int k) {
    Eigen::MatrixX3d foot = q;
    foot(0, d) = -1.0;
    const Eigen::MatrixXd w = data.linear.values(foot);
    double z = 0.0;
    for (int v : data.bottom) z += w(0, v) * z_of_vertex[v][k];
    return z;
  };

  // Coarse reference points of every node of every sub-element, then chi at all of them at once. With
  // a constant ratio they are the same for every element of a shape: the basis values are cached.
  SplitGeometry out;
  if (!ratio_) {
    out.x = data.uniform_values * X;
  } else {
    Eigen::MatrixX3d q(N * nn, 3);
    for (int k = 0; k < N; ++k)
      for (int i = 0; i < nn; ++i) {
        Eigen::RowVector3d r = data.reference.row(i);
        const double z0 = interface_at(r, k), z1 = interface_at(r, k + 1);
        r(d) = z0 + 0.5 * (r(d) + 1.0) * (z1 - z0);
        q.row(k * nn + i) = r;
      }
    out.x = map_points(data.basis, X, q);
  }

  // Heights along the vertical edges, for the stats.
  const Eigen::MatrixX3d corners = reference_vertices(el.shape);
  for (int v : data.bottom) {
    Eigen::MatrixX3d ends(4, 3);
    const std::vector<double>& z = z_of_vertex[v];
    const double zs[4] = {z[0], z[1], z[N - 1], z[N]};
    for (int j = 0; j < 4; ++j) {
      ends.row(j) = corners.row(v);
      ends(j, d) = zs[j];
    }
    const Eigen::MatrixX3d p = map_points(data.basis, X, ends);
    const double first = (p.row(1) - p.row(0)).norm(), last = (p.row(3) - p.row(2)).norm();
    out.first_heights.push_back(first);
    out.ratios.push_back(N > 1 ? std::pow(last / first, 1.0 / (N - 1)) : 1.0);
  }
  return out;
}

std::vector<std::vector<NodeId>> Splitter::split_element(std::size_t element, const SplitGeometry& geometry) {
  const mesh::Element& el = in_.elements()[element];
  const ShapeData& data = shapes_.at(el.shape);
  const int P = in_.order(), N = distribution_.layers, d = direction_;
  const std::vector<NodeId> coarse = in_.element_nodes(element);
  const int nn = static_cast<int>(coarse.size());
  const Eigen::MatrixX3d& x = geometry.x;

  std::vector<std::vector<NodeId>> subs(N, std::vector<NodeId>(nn));
  for (int k = 0; k < N; ++k)
    for (int i = 0; i < nn; ++i) {
      const LatticePoint& l = data.lattice[i];
      const int g = k * P + l[d];  // lattice coordinate along the split direction, refined N times
      if (g == 0 || g == N * P) {
        LatticePoint c = l;
        c[d] = g == 0 ? 0 : P;
        subs[k][i] = coarse[data.index.at(c)];
        continue;
      }
      LatticePoint h = l;
      h[d] = 0;
      NodeKey key{};
      bool found = false;
      for (int v : data.bottom)
        if (data.lattice[v] == h) {  // on a coarse edge across the layer
          key = {1, coarse[v], coarse[data.top_of[v]], g, 0, 0, 0};
          found = true;
        }
      for (const auto& e : data.bottom_edges) {
        if (found) break;
        const LatticePoint &a = data.lattice[e[0]], &b = data.lattice[e[1]];
        int steps = 0, along = 0;
        bool on = true;
        for (int c = 0; c < 3; ++c) steps = std::max(steps, std::abs(b[c] - a[c]));
        for (int c = 0; c < 3; ++c) along = std::max(along, std::abs(h[c] - a[c]));
        for (int c = 0; c < 3 && on; ++c) on = (h[c] - a[c]) * steps == (b[c] - a[c]) * along;
        if (!on || along <= 0 || along >= steps) continue;
        // On a coarse side face: name the slot from the lower node id so both neighbours agree.
        NodeId va = coarse[e[0]], vb = coarse[e[1]], ta = coarse[data.top_of[e[0]]], tb = coarse[data.top_of[e[1]]];
        if (va > vb) {
          std::swap(va, vb);
          std::swap(ta, tb);
          along = steps - along;
        }
        key = {2, va, vb, ta, tb, along, g};
        found = true;
      }
      if (!found) key = {3, static_cast<std::int64_t>(element), h[0], h[1], h[2], g, 0};
      subs[k][i] = node_for(key, x.row(k * nn + i).transpose());
    }

  for (std::size_t j = 0; j < geometry.first_heights.size(); ++j) {
    height_min_ = std::min(height_min_, geometry.first_heights[j]);
    height_max_ = std::max(height_max_, geometry.first_heights[j]);
    ratio_sum_ += geometry.ratios[j];
    ++vertical_edges_;
  }
  return subs;
}

mesh::Mesh Splitter::run(const std::vector<std::size_t>& split, SplitStats* stats) {
  if (distribution_.layers < 1)
    throw std::invalid_argument(caller_ + ": LayerDistribution::layers = " + std::to_string(distribution_.layers) +
                                " must be >= 1");
  if (!ratio_) ratio_at(Eigen::Vector3d::Zero(), 0);  // checks the constant ratio up front
  std::vector<int> position(in_.elements().size(), -1);  // [elements] index into `split` or -1
  for (std::size_t j = 0; j < split.size(); ++j) {
    const std::size_t e = split[j];
    if (e >= in_.elements().size())
      throw std::invalid_argument(caller_ + ": element index " + std::to_string(e) + " out of range (mesh has " +
                                  std::to_string(in_.elements().size()) + " elements)");
    const Shape s = in_.elements()[e].shape;
    if (s != Shape::Hexahedron && !(s == Shape::Prism && direction_ == 2))
      throw std::invalid_argument(caller_ + ": element " + std::to_string(e) + " is a " + to_string(s) +
                                  (direction_ == 2 ? "; only prisms and hexahedra" : "; only hexahedra") +
                                  " can be split in this direction");
    if (position[e] >= 0)
      throw std::invalid_argument(caller_ + ": element " + std::to_string(e) + " is listed twice");
    position[e] = static_cast<int>(j);
  }

  for (NodeId id = 0; id < in_.num_nodes(); ++id) out_.add_node(in_.node(id), in_.cad_attachment(id));
  for (const std::string& g : in_.group_names()) out_.group_index(g);
  out_.copy_regions_from(in_);

  // Blocks of split elements in mesh order: interfaces (user ratio field) serially, the sub-element
  // nodes' positions (the costly part) in parallel, then node creation and elements serially in a
  // fixed order, so the output does not depend on the thread count.
  std::vector<std::size_t> ascending;
  for (std::size_t e = 0; e < in_.elements().size(); ++e)
    if (position[e] >= 0) ascending.push_back(e);
  std::vector<std::vector<std::vector<NodeId>>> subs(split.size());
  std::size_t next = 0;  // next input element to emit
  const auto copy_until = [&](std::size_t end) {
    for (; next < end; ++next)
      out_.add_element(in_.elements()[next].shape, in_.element_nodes(next), in_.elements()[next].region);
  };
  for (std::size_t first = 0; first < ascending.size(); first += kSplitBlock) {
    const std::size_t count = std::min(kSplitBlock, ascending.size() - first);
    std::vector<std::vector<std::vector<double>>> interfaces(count);
    for (std::size_t k = 0; k < count; ++k) interfaces[k] = interfaces_of(ascending[first + k]);
    std::vector<SplitGeometry> geometry(count);
    detail::parallel_for(count, true,
                         [&](std::size_t k) { geometry[k] = place_sub_nodes(ascending[first + k], interfaces[k]); });
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t e = ascending[first + k];
      copy_until(e);
      subs[position[e]] = split_element(e, geometry[k]);
      for (const auto& nodes : subs[position[e]])
        out_.add_element(in_.elements()[e].shape, nodes, in_.elements()[e].region);
      next = e + 1;
    }
  }
  copy_until(in_.elements().size());

  // Boundary faces: split with the element whose side face they are, copied otherwise.
  std::map<std::uint32_t, std::size_t> side_face_owner;  // input face id -> split element
  for (std::size_t e : split) {
    const mesh::Element& el = in_.elements()[e];
    const ShapeData& data = shape_data(el.shape);
    for (std::size_t f = 0; f < faces(el.shape).size(); ++f) {
      const auto& fv = faces(el.shape)[f];
      const bool all_bottom = std::all_of(fv.begin(), fv.end(), [&](int v) { return data.top_of[v] >= 0; });
      const bool all_top = std::none_of(fv.begin(), fv.end(), [&](int v) { return data.top_of[v] >= 0; });
      if (!all_bottom && !all_top) side_face_owner[el.faces[f]] = e;
    }
  }
  for (std::size_t b = 0; b < in_.boundary_faces().size(); ++b) {
    const mesh::BoundaryFace& bf = in_.boundary_faces()[b];
    const std::string& group = in_.group_names()[bf.group];
    const auto owner = side_face_owner.find(bf.face);
    if (owner == side_face_owner.end()) {
      out_.add_boundary_face(group, bf.shape, in_.boundary_face_nodes(b));
      continue;
    }
    const mesh::Element& el = in_.elements()[owner->second];
    const int nv = num_vertices(bf.shape);
    std::vector<int> local(nv);
    for (int j = 0; j < nv; ++j)
      local[j] = static_cast<int>(std::find(el.vertices.begin(), el.vertices.end(), bf.vertices[j]) - el.vertices.begin());
    for (const auto& nodes : subs[position[owner->second]])
      out_.add_boundary_face(group, bf.shape, detail::face_nodes_of_element(el.shape, in_.order(), nodes, local));
  }

  if (stats) {
    stats->elements_in = static_cast<int>(in_.elements().size());
    stats->elements_out = static_cast<int>(out_.elements().size());
    stats->first_cell_height_min = vertical_edges_ ? height_min_ : 0.0;
    stats->first_cell_height_max = height_max_;
    stats->achieved_ratio = vertical_edges_ ? ratio_sum_ / vertical_edges_ : 1.0;
  }
  return std::move(out_);
}

}  // namespace

mesh::Mesh split_layers(const mesh::Mesh& mesh, const std::vector<std::size_t>& layer_elements,
                        const LayerDistribution& distribution, const RatioField& ratio, SplitStats* stats) {
  return Splitter(mesh, 2, distribution, ratio, "split_layers").run(layer_elements, stats);
}

mesh::Mesh split_hex_direction(const mesh::Mesh& mesh, const std::vector<std::size_t>& hexes, int direction,
                               const LayerDistribution& distribution, SplitStats* stats) {
  if (direction < 0 || direction > 2)
    throw std::invalid_argument("split_hex_direction: direction " + std::to_string(direction) +
                                " must be 0 (xi), 1 (eta) or 2 (zeta)");
  return Splitter(mesh, direction, distribution, {}, "split_hex_direction").run(hexes, stats);
}

}  // namespace semimesh::ho
