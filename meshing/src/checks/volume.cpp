#include "semimesh/checks/volume.hpp"

#include "face_nodes.hpp"

#include "semimesh/ho/quadrature.hpp"

#include "semimesh/ho/basis.hpp"
#include "semimesh/ho/validity.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <thread>

namespace semimesh::checks {
namespace {

// Quadrature points pulled into one shape's reference element with its basis derivatives there.
struct ShapeRule {
  Eigen::VectorXd weights;                   // [q]
  Eigen::MatrixXd values;                    // (q, nodes)
  std::array<Eigen::MatrixXd, 3> gradients;  // 3 x (q, nodes)
};

// The same on one local face, for the flux through it: reference tangents t1, t2 with (t1 x t2)
// pointing out of the element, and only the element's nodes on that face. The basis functions of
// the others vanish on the face, with their derivatives along it (the face's map is its own
// nodes' Lagrange map: that is what makes neighbours conform), so they add nothing: at order 4 a
// hexahedron's face point reads 25 nodes instead of 125, and two derivatives instead of three.
struct FaceRule {
  std::vector<int> positions;         // [face nodes] canonical indices of the element's nodes kept
  Eigen::VectorXd weights;            // [q]
  Eigen::MatrixXd values;             // (q, face nodes)
  Eigen::MatrixXd along_t1, along_t2;  // (q, face nodes): derivatives along t1 and t2
};

// A prism or hexahedron as its (xi, eta) base (triangle, quadrilateral) times the zeta segment:
// its Lagrange functions are products of the factors' (basis.hpp) and its quadrature the base's
// times the segment's (quadrature.cpp), so the map's derivatives at the points follow from the
// nodes contracted along zeta first, then across the base (sum factorisation): at order 4 about a
// fifth of the multiply-adds of the full (points, nodes) products.
struct ProductRule {
  int base_nodes = 0, line_nodes = 0;
  std::vector<int> node_of;             // [base node + base_nodes * line node] the element's node
  Eigen::MatrixXd line_values_t;        // (line nodes, line points): psi_l at point b
  Eigen::MatrixXd line_derivatives_t;   // (line nodes, line points): d psi_l / d zeta
  Eigen::MatrixXd base_values;          // (base points, base nodes)
  std::array<Eigen::MatrixXd, 2> base_gradients;  // d / d xi, d / d eta: (base points, base nodes)
  Eigen::VectorXd base_weights, line_weights;
};

// Index of the row of `nodes` at `point` in its first `dims` coordinates; throws when none is.
int matching_node(const Eigen::MatrixX3d& nodes, const Eigen::RowVector3d& point, int dims) {
  for (int i = 0; i < nodes.rows(); ++i)
    if ((nodes.row(i).head(dims) - point.head(dims)).cwiseAbs().maxCoeff() < 1e-12) return i;
  throw std::logic_error("volume: an element node is not a product of its factors' nodes");
}

ProductRule product_rule(ho::Shape shape, int order, ho::NodeSet set, int points_per_direction) {
  const ho::Shape base = shape == ho::Shape::Prism ? ho::Shape::Triangle : ho::Shape::Quadrilateral;
  const ho::LagrangeBasis element(shape, order, set), base_basis(base, order, set), line(ho::Shape::Segment, order, set);
  ProductRule r;
  r.base_nodes = base_basis.size();
  r.line_nodes = line.size();
  r.node_of.assign(static_cast<std::size_t>(r.base_nodes * r.line_nodes), -1);
  for (int i = 0; i < element.size(); ++i) {
    const Eigen::RowVector3d x = element.nodes().row(i);
    const int t = matching_node(base_basis.nodes(), x, 2);
    const int l = matching_node(line.nodes(), Eigen::RowVector3d(x[2], 0.0, 0.0), 1);
    r.node_of[static_cast<std::size_t>(t + r.base_nodes * l)] = i;
  }
  const ho::Quadrature qb = ho::reference_quadrature(base, points_per_direction);
  const ho::Quadrature ql = ho::reference_quadrature(ho::Shape::Segment, points_per_direction);
  r.line_values_t = line.values(ql.points).transpose();
  r.line_derivatives_t = line.gradients(ql.points)[0].transpose();
  r.base_values = base_basis.values(qb.points);
  const std::array<Eigen::MatrixXd, 3> g = base_basis.gradients(qb.points);
  r.base_gradients = {g[0], g[1]};
  r.base_weights = qb.weights;
  r.line_weights = ql.weights;
  return r;
}

ShapeRule pull(const ho::LagrangeBasis& basis, const ho::Quadrature& q) {
  return ShapeRule{q.weights, basis.values(q.points), basis.gradients(q.points)};
}

// On the unit triangle (0,0) (1,0) (0,1), Gmsh's reference triangle, or on the unit square [0, 1]^2
// (Gmsh's reference quadrangle [-1, 1]^2 halved).
ho::Quadrature unit_face_quadrature(bool triangle, int n) {
  if (triangle) return ho::reference_quadrature(ho::Shape::Triangle, n);
  ho::Quadrature q = ho::reference_quadrature(ho::Shape::Quadrilateral, n);
  q.points.leftCols<2>() = (q.points.leftCols<2>().array() + 1.0) / 2.0;
  q.weights /= 4.0;
  return q;
}

// Points per direction: det J of an order-P element has degree <= 3P per variable; the collapsed
// maps add up to two more.
int points_per_direction(int order) { return (3 * order + 2) / 2 + 1; }

// The fewest points per direction that integrate det J of an order-P element of `shape` exactly:
// det J is in P_{3P-3} on a tet, P_{3P-2} (triangle) x P_{3P-1} on a prism, Q_{3P-1} on a hex, and
// n Gauss-Legendre points are exact to degree 2n - 1 per collapsed direction, where the collapse
// (quadrature.cpp) adds the weight's degree: (1 - b) on the prism's triangle, (1 - b)(1 - c)^2 on
// the tet. Each needs n >= 3P / 2. The pyramid keeps points_per_direction. At order 4: 6 points
// per direction (216) instead of 8 (512).
int exact_points_per_direction(ho::Shape shape, int order) {
  switch (shape) {
    case ho::Shape::Tetrahedron:
    case ho::Shape::Prism:
    case ho::Shape::Hexahedron: return (3 * order + 1) / 2;
    default: return points_per_direction(order);
  }
}

// A face's rule from the element's whole one at the face's points, kept for the element's nodes
// on that face (`positions`: detail::nodes_on_faces, the conformity check's own).
FaceRule face_rule(const ShapeRule& whole, const Eigen::Vector3d& t1, const Eigen::Vector3d& t2,
                   const std::vector<int>& positions) {
  FaceRule r;
  r.positions = positions;
  r.weights = whole.weights;
  const auto n = static_cast<Eigen::Index>(positions.size()), q = whole.values.rows();
  r.values.resize(q, n), r.along_t1.resize(q, n), r.along_t2.resize(q, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const int i = positions[static_cast<std::size_t>(k)];
    r.values.col(k) = whole.values.col(i);
    r.along_t1.col(k) = t1[0] * whole.gradients[0].col(i) + t1[1] * whole.gradients[1].col(i) + t1[2] * whole.gradients[2].col(i);
    r.along_t2.col(k) = t2[0] * whole.gradients[0].col(i) + t2[1] * whole.gradients[1].col(i) + t2[2] * whole.gradients[2].col(i);
  }
  return r;
}

class RuleCache {
 public:
  RuleCache(int order, ho::NodeSet set, VolumeRule rule = VolumeRule::Exact) : order_(order), set_(set), rule_(rule) {}

  const ShapeRule& volume(ho::Shape shape) {
    auto it = volume_.find(shape);
    if (it == volume_.end()) {
      ho::LagrangeBasis basis(shape, order_, set_);
      const int n =
          rule_ == VolumeRule::Generous ? points_per_direction(order_) : exact_points_per_direction(shape, order_);
      it = volume_.emplace(shape, pull(basis, ho::reference_quadrature(shape, n))).first;
    }
    return it->second;
  }

  // The factored rule of a prism or hexahedron under VolumeRule::Exact, else nullptr.
  const ProductRule* product(ho::Shape shape) {
    if (rule_ != VolumeRule::Exact || (shape != ho::Shape::Prism && shape != ho::Shape::Hexahedron)) return nullptr;
    auto it = product_.find(shape);
    if (it == product_.end())
      it = product_.emplace(shape, product_rule(shape, order_, set_, exact_points_per_direction(shape, order_))).first;
    return &it->second;
  }

  const FaceRule& face(ho::Shape shape, int local) {
    auto key = std::make_pair(shape, local);
    auto it = face_.find(key);
    if (it == face_.end()) {
      ho::LagrangeBasis basis(shape, order_, set_);
      const Eigen::MatrixX3d vertices = ho::reference_vertices(shape);
      const std::vector<int>& f = ho::faces(shape)[local];
      const Eigen::Vector3d r0 = vertices.row(f[0]);
      // Triangle r0 + s (r1 - r0) + t (r2 - r0) on the unit triangle; quad faces are reference
      // parallelograms r0 + s (r1 - r0) + t (r3 - r0) on the unit square.
      const bool triangle = f.size() == 3;
      const Eigen::Vector3d t1 = Eigen::Vector3d(vertices.row(f[1])) - r0;
      const Eigen::Vector3d t2 = Eigen::Vector3d(vertices.row(f[triangle ? 2 : 3])) - r0;
      const int n = points_per_direction(order_);
      ho::Quadrature q = unit_face_quadrature(triangle, n);
      Eigen::MatrixX3d points(q.points.rows(), 3);
      for (int i = 0; i < q.points.rows(); ++i) points.row(i) = (r0 + q.points(i, 0) * t1 + q.points(i, 1) * t2).transpose();
      q.points = points;
      it = face_.emplace(key, face_rule(pull(basis, q), t1, t2, detail::nodes_on_faces(shape, order_, set_)[local])).first;
    }
    return it->second;
  }

 private:
  int order_;
  ho::NodeSet set_;
  VolumeRule rule_;
  std::map<ho::Shape, ShapeRule> volume_;
  std::map<ho::Shape, ProductRule> product_;
  std::map<std::pair<ho::Shape, int>, FaceRule> face_;
};

}  // namespace

double MeshVolume::boundary_relative_error() const {
  return std::abs(element_volume - boundary_volume) / std::max(std::abs(boundary_volume), 1e-300);
}

double VolumeCheck::expected_relative_error() const {
  return std::abs(mesh.element_volume - expected_volume()) / std::max(std::abs(expected_volume()), 1e-300);
}

namespace {

// Elements of one shape, at most kBatchSize of them.
struct ElementBatch {
  ho::Shape shape;
  std::vector<std::size_t> elements;
};
constexpr std::size_t kBatchSize = 256;

std::vector<ElementBatch> element_batches(const mesh::Mesh& mesh) {
  std::map<ho::Shape, std::vector<std::size_t>> by_shape;
  for (std::size_t e = 0; e < mesh.elements().size(); ++e) by_shape[mesh.elements()[e].shape].push_back(e);
  std::vector<ElementBatch> batches;
  for (const auto& [shape, elements] : by_shape)
    for (std::size_t i = 0; i < elements.size(); i += kBatchSize)
      batches.push_back({shape, std::vector<std::size_t>(elements.begin() + static_cast<long>(i),
                                                         elements.begin() + static_cast<long>(std::min(i + kBatchSize, elements.size())))});
  return batches;
}

// Sum of the integrals of det J of the `n` elements in x (nodes, 3 n) (element i in columns
// 3i..3i+2). The reference derivatives of the map at all quadrature points of all of them come from
// three products (q, nodes) x (nodes, 3 n): one product per batch instead of one per element, which
// spends its time packing the left matrix.
double quadrature_volume(const Eigen::Ref<const Eigen::MatrixXd>& x, long n, const ShapeRule& rule) {
  // Per-thread products, reused batch after batch: fresh ones of this size were mapped and
  // faulted in anew each time (a third of the volume's time).
  thread_local Eigen::MatrixXd d_xi, d_eta, d_zeta;
  d_xi.noalias() = rule.gradients[0] * x;
  d_eta.noalias() = rule.gradients[1] * x;
  d_zeta.noalias() = rule.gradients[2] * x;
  double volume = 0.0;
  for (long i = 0; i < n; ++i)
    for (int q = 0; q < rule.weights.size(); ++q) {
      const Eigen::Vector3d a = d_xi.block<1, 3>(q, 3 * i).transpose(), b = d_eta.block<1, 3>(q, 3 * i).transpose(),
                            c = d_zeta.block<1, 3>(q, 3 * i).transpose();
      volume += rule.weights(q) * a.dot(b.cross(c));
    }
  return volume;
}

// The same integrals by sum factorisation (ProductRule): the nodes as rows (base node, coordinate,
// element) by columns (line node) are contracted along zeta at every line point b (values and
// derivatives), and each such (base nodes, 3 n) matrix then across the base at every base point.
double factored_volume(const Eigen::Ref<const Eigen::MatrixXd>& x, long n, const ProductRule& rule) {
  const long nt = rule.base_nodes;
  thread_local Eigen::MatrixXd by_line, values, derivatives, d_xi, d_eta, d_zeta;  // as quadrature_volume's
  by_line.resize(nt * 3 * n, rule.line_nodes);
  for (long i = 0; i < n; ++i)
    for (int l = 0; l < rule.line_nodes; ++l)
      for (long t = 0; t < nt; ++t)
        for (int c = 0; c < 3; ++c) by_line(t + nt * (c + 3 * i), l) = x(rule.node_of[static_cast<std::size_t>(t + nt * l)], 3 * i + c);
  values.noalias() = by_line * rule.line_values_t;
  derivatives.noalias() = by_line * rule.line_derivatives_t;
  double volume = 0.0;
  for (int b = 0; b < rule.line_weights.size(); ++b) {
    const Eigen::Map<const Eigen::MatrixXd> at_b(values.col(b).data(), nt, 3 * n);
    const Eigen::Map<const Eigen::MatrixXd> d_at_b(derivatives.col(b).data(), nt, 3 * n);
    d_xi.noalias() = rule.base_gradients[0] * at_b;
    d_eta.noalias() = rule.base_gradients[1] * at_b;
    d_zeta.noalias() = rule.base_values * d_at_b;
    for (long i = 0; i < n; ++i)
      for (int a = 0; a < rule.base_weights.size(); ++a) {
        const Eigen::Vector3d u = d_xi.block<1, 3>(a, 3 * i).transpose(), v = d_eta.block<1, 3>(a, 3 * i).transpose(),
                              w = d_zeta.block<1, 3>(a, 3 * i).transpose();
        volume += rule.base_weights(a) * rule.line_weights(b) * u.dot(v.cross(w));
      }
  }
  return volume;
}

// How a batch is integrated: VolumeRule::Exact takes affine elements in closed form and prisms and
// hexahedra by factors; VolumeRule::Quadrature and Generous integrate every element with `full`.
struct BatchRule {
  const ShapeRule* full = nullptr;
  const ProductRule* factored = nullptr;  // prisms and hexahedra under VolumeRule::Exact
  bool closed_form = false;
};

// Sum over the batch of the integral of det J. An affine element (ho::affine_jacobian: every
// straight-sided far-field tet) has the constant det J = det A, so its integral is det A times the
// reference volume, with no quadrature. `known` (may be null): by element, the integral its
// certification found (NaN where none), taken as it is; `taken` counts them.
double batch_volume(const mesh::Mesh& mesh, const ElementBatch& batch, const BatchRule& rule,
                    const std::vector<double>* known, std::size_t& taken) {
  thread_local Eigen::MatrixXd x;  // elements in x: element i in columns 3i..3i+2
  thread_local Eigen::MatrixX3d nodes;
  x.resize(rule.full->gradients[0].cols(), 3 * static_cast<long>(batch.elements.size()));
  long integrated = 0;
  double volume = 0.0;
  for (std::size_t e : batch.elements) {
    if (known && std::isfinite((*known)[e])) {
      volume += (*known)[e];
      ++taken;
      continue;
    }
    mesh.element_coordinates(e, nodes);
    ho::JacobianBounds affine;
    if (rule.closed_form && ho::affine_jacobian(batch.shape, mesh.order(), mesh.node_set(), nodes, affine))
      volume += affine.integral;
    else
      x.middleCols<3>(3 * integrated++) = nodes;
  }
  if (integrated == 0) return volume;
  const auto used = x.leftCols(3 * integrated);
  return volume + (rule.factored ? factored_volume(used, integrated, *rule.factored)
                                 : quadrature_volume(used, integrated, *rule.full));
}

}  // namespace

namespace {

// Owner of each face entity: element * 8 + local face (the last one seen; a boundary face has one).
std::vector<long> face_owners(const mesh::Mesh& mesh) {
  std::vector<long> owner(mesh.faces().size(), -1);
  for (std::size_t e = 0; e < mesh.elements().size(); ++e) {
    const mesh::Element& element = mesh.elements()[e];
    for (std::size_t f = 0; f < ho::faces(element.shape).size(); ++f) owner[element.faces[f]] = static_cast<long>(e * 8 + f);
  }
  return owner;
}

// The terms of one face's flux, weight times field at each point, in point order.
template <class Field>
void face_flux_terms(const mesh::Mesh& mesh, std::size_t element, const FaceRule& rule, Field field, double* terms) {
  thread_local std::vector<mesh::NodeId> ids;
  thread_local Eigen::MatrixX3d x;
  mesh.element_nodes_at(element, rule.positions, ids);
  x.resize(static_cast<Eigen::Index>(ids.size()), 3);
  for (std::size_t i = 0; i < ids.size(); ++i) x.row(static_cast<Eigen::Index>(i)) = mesh.node(ids[i]).transpose();
  for (int q = 0; q < rule.weights.size(); ++q) {
    const Eigen::Vector3d point = (rule.values.row(q) * x).transpose();
    const Eigen::Vector3d a = (rule.along_t1.row(q) * x).transpose(), b = (rule.along_t2.row(q) * x).transpose();
    terms[q] = rule.weights(q) * field(point, a.cross(b));
  }
}

// The integral of field(x, dA) over the boundary faces `keep` accepts, each at the mesh's order
// (dA: the area element, outward through the face's element); faces without an element are
// counted in `orphans` and skipped. One running sum over the faces and their points: the reference.
template <class Keep, class Field>
double boundary_flux_one_thread(const mesh::Mesh& mesh, RuleCache& rules, Keep keep, Field field, std::size_t* orphans) {
  const std::vector<long> owner = face_owners(mesh);
  double flux = 0.0;
  std::vector<double> terms;
  for (const mesh::BoundaryFace& face : mesh.boundary_faces()) {
    if (!keep(face)) continue;
    if (owner[face.face] < 0) {
      if (orphans) ++*orphans;
      continue;
    }
    const std::size_t e = static_cast<std::size_t>(owner[face.face] / 8);
    const FaceRule& rule = rules.face(mesh.elements()[e].shape, static_cast<int>(owner[face.face] % 8));
    terms.resize(static_cast<std::size_t>(rule.weights.size()));
    face_flux_terms(mesh, e, rule, field, terms.data());
    for (double t : terms) flux += t;
  }
  return flux;
}

// One face of boundary_flux's sum: its element, its rule and where its terms start in a block.
struct FluxFace {
  std::size_t element = 0;
  const FaceRule* rule = nullptr;
  std::size_t first_term = 0;
};
constexpr std::size_t kFluxBlock = 8192;  // faces whose terms are held at once

// boundary_flux_one_thread's sum with its terms computed on `workers` threads, a block of faces at
// a time, and added on this thread in the same order: the same bits (the serial tail of the checks).
template <class Keep, class Field>
double boundary_flux(const mesh::Mesh& mesh, RuleCache& rules, Keep keep, Field field, std::size_t* orphans,
                     std::size_t workers) {
  const std::vector<long> owner = face_owners(mesh);
  std::vector<FluxFace> faces;  // the rules looked up here: the cache is not thread-safe
  for (const mesh::BoundaryFace& face : mesh.boundary_faces()) {
    if (!keep(face)) continue;
    if (owner[face.face] < 0) {
      if (orphans) ++*orphans;
      continue;
    }
    const std::size_t e = static_cast<std::size_t>(owner[face.face] / 8);
    faces.push_back({e, &rules.face(mesh.elements()[e].shape, static_cast<int>(owner[face.face] % 8)), 0});
  }
  double flux = 0.0;
  std::vector<double> terms;
  for (std::size_t first = 0; first < faces.size(); first += kFluxBlock) {
    const std::size_t end = std::min(faces.size(), first + kFluxBlock);
    std::size_t count = 0;
    for (std::size_t k = first; k < end; ++k)
      faces[k].first_term = count, count += static_cast<std::size_t>(faces[k].rule->weights.size());
    terms.resize(count);
    auto terms_of_stride = [&](std::size_t w) {
      for (std::size_t k = first + w; k < end; k += workers)
        face_flux_terms(mesh, faces[k].element, *faces[k].rule, field, terms.data() + faces[k].first_term);
    };
    std::vector<std::thread> pool;
    for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(terms_of_stride, w);
    terms_of_stride(0);
    for (std::thread& t : pool) t.join();
    for (double t : terms) flux += t;
  }
  return flux;
}

std::size_t volume_workers() { return std::max<std::size_t>(1, std::thread::hardware_concurrency()); }

// mesh_volume on `threads` threads; 1: the reference, every sum a plain loop on this thread.
MeshVolume mesh_volume_on(const mesh::Mesh& mesh, VolumeRule rule, std::size_t threads,
                          const std::vector<double>* known) {
  RuleCache rules(mesh.order(), mesh.node_set(), rule);
  MeshVolume result;
  const std::vector<ElementBatch> batches = element_batches(mesh);
  std::vector<BatchRule> batch_rules;  // looked up before the threads: the cache is not thread-safe
  for (const ElementBatch& batch : batches)
    batch_rules.push_back({&rules.volume(batch.shape), rules.product(batch.shape), rule == VolumeRule::Exact});
  if (known && known->size() != mesh.elements().size())
    throw std::invalid_argument("mesh_volume: " + std::to_string(known->size()) + " known integrals for a mesh of " +
                                std::to_string(mesh.elements().size()) + " elements");
  std::vector<double> partial(batches.size(), 0.0);
  std::vector<std::size_t> taken(batches.size(), 0);
  const std::size_t workers = std::max<std::size_t>(1, std::min<std::size_t>(threads, batches.size()));
  auto integrate_stride = [&](std::size_t first) {
    for (std::size_t b = first; b < batches.size(); b += workers)
      partial[b] = batch_volume(mesh, batches[b], batch_rules[b], known, taken[b]);
  };
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(integrate_stride, w);
  integrate_stride(0);
  for (std::thread& t : pool) t.join();
  for (double v : partial) result.element_volume += v;  // in batch order: independent of the threads
  for (std::size_t t : taken) result.known += t;

  const auto all = [](const mesh::BoundaryFace&) { return true; };
  const auto x_dot_area = [](const Eigen::Vector3d& x, const Eigen::Vector3d& area) { return x.dot(area); };
  result.boundary_volume =
      threads == 1 ? boundary_flux_one_thread(mesh, rules, all, x_dot_area, &result.boundary_faces_without_element)
                   : boundary_flux(mesh, rules, all, x_dot_area, &result.boundary_faces_without_element, threads);
  result.boundary_volume /= 3.0;
  return result;
}

}  // namespace

MeshVolume mesh_volume(const mesh::Mesh& mesh, VolumeRule rule, const std::vector<double>* known) {
  return mesh_volume_on(mesh, rule, volume_workers(), known);
}

MeshVolume mesh_volume_one_thread(const mesh::Mesh& mesh, VolumeRule rule) {
  return mesh_volume_on(mesh, rule, 1, nullptr);
}

namespace {

// The sum of term(a, b, c) over the flat facets of `faces` (each quad as the triangles 012, 023).
template <typename Term>
double sum_over_facets(const std::vector<const surface::SurfaceMesh*>& faces, Term term) {
  double sum = 0.0;
  for (const surface::SurfaceMesh* mesh : faces) {
    for (const auto& t : mesh->triangles) sum += term(mesh->points[t[0]], mesh->points[t[1]], mesh->points[t[2]]);
    for (const auto& q : mesh->quads) {
      sum += term(mesh->points[q[0]], mesh->points[q[1]], mesh->points[q[2]]);
      sum += term(mesh->points[q[0]], mesh->points[q[2]], mesh->points[q[3]]);
    }
  }
  return sum;
}

// (1/3) the flux of x - p through `faces` along their fluid normals: minus their share of the
// fluid's volume (divergence theorem with div (x - p) / 3 = 1; exact on flat facets).
double fluid_normal_flux(const std::vector<const surface::SurfaceMesh*>& faces, const Eigen::Vector3d& p) {
  return sum_over_facets(faces, [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    return (0.5 * (b - a).cross(c - a)).dot((a + b + c) / 3.0 - p) / 3.0;
  });
}

}  // namespace

double volume_under_surfaces(const std::vector<const surface::SurfaceMesh*>& faces, const Eigen::Vector3d& plane_point,
                             const Eigen::Vector3d& plane_normal) {
  // Divergence theorem with F = ((x - p) . n) n: div F = 1 and F . n = 0 on the plane, so the plane
  // part of the boundary adds nothing. On a flat triangle F . N is linear: its integral is the
  // value at the centroid times the area.
  const Eigen::Vector3d n = plane_normal.normalized();
  return sum_over_facets(faces, [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const Eigen::Vector3d area = 0.5 * (b - a).cross(c - a);
    return n.dot(area) * n.dot((a + b + c) / 3.0 - plane_point);
  });
}

VolumeCheck check_volume_curved_wall(const mesh::Mesh& mesh, const std::vector<const surface::SurfaceMesh*>& body,
                                     const std::vector<const surface::SurfaceMesh*>& farfield,
                                     const surface::SurfaceMesh& wall,
                                     const std::vector<double>* known) {
  const Eigen::Vector3d p = wall.points.empty() ? Eigen::Vector3d::Zero() : wall.points.front();
  VolumeCheck result;
  result.mesh = mesh_volume(mesh, VolumeRule::Exact, known);
  result.body_volume = fluid_normal_flux(body, p);
  result.box_volume = -fluid_normal_flux({&wall}, p);
  if (!farfield.empty()) {
    result.box_volume -= fluid_normal_flux(farfield, p);
    return result;
  }
  RuleCache rules(mesh.order(), mesh.node_set());
  const auto it = std::find(mesh.group_names().begin(), mesh.group_names().end(), "farfield");
  const int group = static_cast<int>(it - mesh.group_names().begin());
  result.box_volume += boundary_flux(
                           mesh, rules, [&](const mesh::BoundaryFace& f) { return f.group == group; },
                           [&](const Eigen::Vector3d& x, const Eigen::Vector3d& area) { return area.dot(x - p); },
                           nullptr, volume_workers()) / 3.0;
  return result;
}

VolumeCheck check_volume(const mesh::Mesh& mesh, const std::vector<const surface::SurfaceMesh*>& body,
                         const std::vector<const surface::SurfaceMesh*>& farfield, const surface::SurfaceMesh& wall,
                         const std::vector<double>* known) {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (const auto& t : wall.triangles)
    normal += (wall.points[t[1]] - wall.points[t[0]]).cross(wall.points[t[2]] - wall.points[t[0]]);
  for (const auto& q : wall.quads)
    normal += (wall.points[q[2]] - wall.points[q[0]]).cross(wall.points[q[3]] - wall.points[q[1]]);
  const Eigen::Vector3d point = wall.points.empty() ? Eigen::Vector3d::Zero() : wall.points.front();

  VolumeCheck result;
  result.mesh = mesh_volume(mesh, VolumeRule::Exact, known);
  result.body_volume = volume_under_surfaces(body, point, normal);
  // The far-field faces' normals point into the box: their flux is minus the box volume.
  if (!farfield.empty()) {
    result.box_volume = -volume_under_surfaces(farfield, point, normal);
    return result;
  }
  // The mesh's own far-field faces, at its order, outward through their elements (out of the box):
  // the same field F = ((x - p) . n) n, whose flux through the wall plane is zero.
  RuleCache rules(mesh.order(), mesh.node_set());
  const Eigen::Vector3d n = normal.normalized();
  const auto it = std::find(mesh.group_names().begin(), mesh.group_names().end(), "farfield");
  const int group = static_cast<int>(it - mesh.group_names().begin());
  result.box_volume = boundary_flux(
      mesh, rules, [&](const mesh::BoundaryFace& f) { return f.group == group; },
      [&](const Eigen::Vector3d& x, const Eigen::Vector3d& area) { return n.dot(area) * n.dot(x - point); }, nullptr,
      volume_workers());
  return result;
}

}  // namespace semimesh::checks
