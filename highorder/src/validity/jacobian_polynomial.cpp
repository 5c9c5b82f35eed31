#include "jacobian_polynomial.hpp"

#include <Eigen/LU>

#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <tuple>

namespace semimesh::ho::detail {
namespace {

/// A column of J, d x / d xi_k, from the map's control points: each of its scaled coefficients
/// (coefficient x multinomial) is a sum of a few control points times weights (the derivative's
/// difference, the pyramid's division by 1 - c, d t_k / d xi_k).
struct ColumnMap {
  std::shared_ptr<const BernsteinLayout> layout;
  std::vector<int> first;      // [size + 1] where each coefficient's terms start
  std::vector<int> control;    // [terms] control point
  std::vector<double> weight;  // [terms]
};

/// Linear map from element node positions to the Bezier control points of the order-P map, and
/// what jacobian_determinant needs besides: the columns' maps and the two products' kernels.
struct ControlPointMap {
  std::shared_ptr<const BernsteinLayout> layout;  // Bernstein space of the map
  Eigen::MatrixXd nodes_to_control;              // (layout size, num_nodes)
  std::array<double, 3> column_scale{};          // d t_k / d xi_k
  std::array<ColumnMap, 3> columns;              // d x / d xi_k
  std::unique_ptr<ScaledProduct> cofactor;       // column 0 x column 1
  std::unique_ptr<ScaledProduct> determinant;    // column 2 x cofactor
};

std::vector<SimplexFactor> geometry_factors(Shape shape, int order) {
  switch (shape) {
    case Shape::Tetrahedron: return {{3, order}};
    case Shape::Prism: return {{2, order}, {1, order}};
    case Shape::Hexahedron:
    case Shape::Pyramid: return {{1, order}, {1, order}, {1, order}};
    default: throw std::invalid_argument("Jacobian bounds: shape '" + to_string(shape) + "' is not a 3D element");
  }
}

/// d x / d xi_k from the map's coefficients in one coordinate: the derivative, for a pyramid's
/// dX/da and dX/db divided by the factor (1 - c) the collapsed map's Jacobian removes, scaled.
BernsteinPolynomial reference_column(Shape shape, const BernsteinPolynomial& coordinate, double scale, int k) {
  BernsteinPolynomial column = coordinate.derivative(k);
  if (shape == Shape::Pyramid && k < 2) column = column.divide_by_one_minus(2);
  column *= scale;
  return column;
}

/// Column k of J as reference_column does it, applied to one coefficient at a time: its map.
ColumnMap column_map(Shape shape, const std::shared_ptr<const BernsteinLayout>& layout, double scale, int k) {
  ColumnMap map;
  std::vector<Eigen::VectorXd> images;  // [control point] its image
  for (int j = 0; j < layout->size(); ++j) {
    BernsteinPolynomial unit(layout);
    unit.coefficients()[j] = 1.0;
    BernsteinPolynomial column = reference_column(shape, unit, scale, k);
    if (!map.layout) map.layout = column.layout_ptr();
    images.push_back(column.coefficients());
  }
  map.first.push_back(0);
  for (int i = 0; i < map.layout->size(); ++i) {
    for (int j = 0; j < layout->size(); ++j)
      if (images[j][i] != 0.0) {
        map.control.push_back(j);
        map.weight.push_back(images[j][i] * map.layout->multinomial[i]);
      }
    map.first.push_back(static_cast<int>(map.control.size()));
  }
  return map;
}

/// 1D Bernstein basis of degree n at t; shape (n+1).
Eigen::VectorXd bernstein_1d(int degree, double t) {
  return BernsteinPolynomial::basis_values(*BernsteinLayout::get({{1, degree}}), Eigen::Vector3d(t, 0, 0));
}

/// Gmsh's pyramid space V (see header) in the tensor Bernstein basis of degree (P, P, P):
/// returns the interpolation matrix of V's basis at the nodes and the embedding of V into the tensor
/// space. V's basis: B^{P-s}_i(t_a) B^{P-s}_j(t_b) B^P_s(c), s = 0..P, i, j = 0..P-s.
Eigen::MatrixXd pyramid_nodes_to_control(int order, const Eigen::MatrixX3d& reference, const BernsteinLayout& tensor) {
  const int n = static_cast<int>(reference.rows());
  Eigen::MatrixXd at_nodes(n, n);
  Eigen::MatrixXd embedding = Eigen::MatrixXd::Zero(tensor.size(), n);
  int column = 0;
  for (int s = 0; s <= order; ++s) {
    const int degree = order - s;
    const Eigen::MatrixXd elevate = bernstein_elevation_1d(degree, order);
    for (int j = 0; j <= degree; ++j)
      for (int i = 0; i <= degree; ++i, ++column) {
        for (int node = 0; node < n; ++node) {
          const Eigen::Vector3d t = bernstein_domain_point(Shape::Pyramid, reference.row(node).transpose());
          at_nodes(node, column) = bernstein_1d(degree, t[0])[i] * bernstein_1d(degree, t[1])[j] *
                                   bernstein_1d(order, t[2])[s];
        }
        for (int jj = 0; jj <= order; ++jj)
          for (int ii = 0; ii <= order; ++ii)
            embedding(tensor.id_of({ii, jj, s}), column) = elevate(ii, i) * elevate(jj, j);
      }
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(at_nodes);
  if (!lu.isInvertible())
    throw std::invalid_argument("Jacobian bounds: the pyramid nodes of order " + std::to_string(order) +
                                " are not unisolvent for the pyramid space");
  return embedding * lu.inverse();
}

void add_products(Shape shape, ControlPointMap& map) {
  for (int k = 0; k < 3; ++k) map.columns[k] = column_map(shape, map.layout, map.column_scale[k], k);
  map.cofactor = std::make_unique<ScaledProduct>(*map.columns[0].layout, *map.columns[1].layout);
  map.determinant = std::make_unique<ScaledProduct>(*map.columns[2].layout, *map.cofactor->out());
}

std::shared_ptr<const ControlPointMap> build_control_point_map(Shape shape, int order, NodeSet set) {
  auto map = std::make_shared<ControlPointMap>();
  map->layout = BernsteinLayout::get(geometry_factors(shape, order));
  const Eigen::MatrixX3d reference = reference_nodes(shape, order, set);
  if (reference.rows() != num_nodes(shape, order))
    throw std::logic_error("Jacobian bounds: reference_nodes returned the wrong number of nodes");
  if (shape == Shape::Pyramid) {
    map->nodes_to_control = pyramid_nodes_to_control(order, reference, *map->layout);
    map->column_scale = {0.5, 0.5, 1.0};
    add_products(shape, *map);
    return map;
  }
  if (map->layout->size() != reference.rows())
    throw std::logic_error("Jacobian bounds: Bernstein space and node count differ for " + to_string(shape));
  Eigen::MatrixXd at_nodes(reference.rows(), map->layout->size());
  for (int node = 0; node < reference.rows(); ++node)
    at_nodes.row(node) = BernsteinPolynomial::basis_values(
        *map->layout, bernstein_domain_point(shape, reference.row(node).transpose())).transpose();
  Eigen::FullPivLU<Eigen::MatrixXd> lu(at_nodes);
  if (!lu.isInvertible())
    throw std::invalid_argument("Jacobian bounds: the nodes of the order-" + std::to_string(order) + " " +
                                to_string(shape) + " are not unisolvent");
  map->nodes_to_control = lu.inverse();
  switch (shape) {
    case Shape::Tetrahedron: map->column_scale = {1.0, 1.0, 1.0}; break;
    case Shape::Prism: map->column_scale = {1.0, 1.0, 0.5}; break;
    default: map->column_scale = {0.5, 0.5, 0.5}; break;
  }
  add_products(shape, *map);
  return map;
}

std::shared_ptr<const ControlPointMap> control_point_map(Shape shape, int order, NodeSet set) {
  static std::mutex mutex;
  static std::map<std::tuple<Shape, int, NodeSet>, std::shared_ptr<const ControlPointMap>> cache;
  const auto key = std::make_tuple(shape, order, set);
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto found = cache.find(key);
    if (found != cache.end()) return found->second;
  }
  auto map = build_control_point_map(shape, order, set);  // built outside the lock: may take a while
  std::lock_guard<std::mutex> lock(mutex);
  return cache.emplace(key, map).first->second;
}

}  // namespace

Eigen::Vector3d bernstein_domain_point(Shape shape, const Eigen::Vector3d& r) {
  switch (shape) {
    case Shape::Tetrahedron: return r;
    case Shape::Prism: return {r[0], r[1], 0.5 * (r[2] + 1.0)};
    case Shape::Hexahedron: return 0.5 * (r.array() + 1.0).matrix();
    case Shape::Pyramid: {
      const double scale = 1.0 - r[2];
      const double a = scale > 1e-14 ? r[0] / scale : 0.0;
      const double b = scale > 1e-14 ? r[1] / scale : 0.0;
      return {0.5 * (a + 1.0), 0.5 * (b + 1.0), r[2]};
    }
    default: throw std::invalid_argument("Jacobian bounds: shape '" + to_string(shape) + "' is not a 3D element");
  }
}

namespace {

void check_element(Shape shape, int order, const Eigen::MatrixX3d& element_nodes) {
  if (dimension(shape) != 3)
    throw std::invalid_argument("Jacobian bounds: shape '" + to_string(shape) + "' is not a 3D element");
  if (order < 1 || order > kMaxOrder)
    throw std::invalid_argument("Jacobian bounds: order " + std::to_string(order) + " outside 1.." +
                                std::to_string(kMaxOrder));
  if (element_nodes.rows() != num_nodes(shape, order))
    throw std::invalid_argument("Jacobian bounds: a " + to_string(shape) + " of order " + std::to_string(order) +
                                " has " + std::to_string(num_nodes(shape, order)) + " nodes, got " +
                                std::to_string(element_nodes.rows()));
}

// Relative to the first node: det J does not change, and the conversion (whose norm grows fast with
// the order for equispaced nodes, ~2e8 for a P = 8 hex) then amplifies rounding of the element's
// size, not of its distance from the origin. control: (layout size, 3).
void control_points(const ControlPointMap& map, const Eigen::MatrixX3d& element_nodes, Eigen::MatrixX3d& shifted,
                    Eigen::MatrixX3d& control) {
  shifted = element_nodes.rowwise() - element_nodes.row(0);
  control.resize(map.nodes_to_control.rows(), 3);
  control.noalias() = map.nodes_to_control * shifted;
}

}  // namespace

// In the scaled basis (ScaledProduct) the columns' products chain without a polynomial in between:
// each cofactor u_a v_b - u_b v_a is accumulated in one box, whose entries are its scaled
// coefficients, and det J = sum_c w_c cofactor_c in the next; only that box is divided by the
// multinomials. Per thread, the buffers are reused: no allocation but the result's.
BernsteinPolynomial jacobian_determinant(Shape shape, int order, NodeSet set, const Eigen::MatrixX3d& element_nodes) {
  check_element(shape, order, element_nodes);
  const std::shared_ptr<const ControlPointMap> map = control_point_map(shape, order, set);
  thread_local Eigen::MatrixX3d shifted, control;
  control_points(*map, element_nodes, shifted, control);
  // columns[k][c]: the scaled coefficients of d x_c / d xi_k.
  thread_local std::array<std::array<std::vector<double>, 3>, 3> columns;
  for (int k = 0; k < 3; ++k) {
    const ColumnMap& m = map->columns[k];
    for (int c = 0; c < 3; ++c) {
      std::vector<double>& column = columns[k][c];
      column.assign(m.layout->size(), 0.0);
      for (int i = 0; i < m.layout->size(); ++i)
        for (int t = m.first[i]; t < m.first[i + 1]; ++t) column[i] += m.weight[t] * control(m.control[t], c);
    }
  }
  const BernsteinLayout& middle = *map->cofactor->out();
  const BernsteinLayout& last = *map->determinant->out();
  thread_local std::vector<double> box, cofactor, sum;
  sum.assign(last.box_to_id.size(), 0.0);
  cofactor.resize(middle.size());
  const auto& u = columns[0];
  const auto& v = columns[1];
  const auto& w = columns[2];
  for (int c = 0; c < 3; ++c) {
    const int a = (c + 1) % 3, b = (c + 2) % 3;
    box.assign(middle.box_to_id.size(), 0.0);
    map->cofactor->accumulate(u[a].data(), v[b].data(), 1.0, box.data());
    map->cofactor->accumulate(u[b].data(), v[a].data(), -1.0, box.data());
    map->cofactor->gather(box.data(), cofactor.data());
    map->determinant->accumulate(w[c].data(), cofactor.data(), 1.0, sum.data());
  }
  BernsteinPolynomial det(map->determinant->out());
  map->determinant->gather(sum.data(), det.coefficients().data());
  for (int i = 0; i < last.size(); ++i) det.coefficients()[i] /= last.multinomial[i];
  return det;
}

BernsteinPolynomial jacobian_determinant_by_products(Shape shape, int order, NodeSet set,
                                                     const Eigen::MatrixX3d& element_nodes) {
  check_element(shape, order, element_nodes);
  const std::shared_ptr<const ControlPointMap> map = control_point_map(shape, order, set);
  Eigen::MatrixX3d shifted, control;
  control_points(*map, element_nodes, shifted, control);
  // columns[k][c] = d x_c / d xi_k
  std::array<std::array<BernsteinPolynomial, 3>, 3> columns{
      {{BernsteinPolynomial(map->layout), BernsteinPolynomial(map->layout), BernsteinPolynomial(map->layout)},
       {BernsteinPolynomial(map->layout), BernsteinPolynomial(map->layout), BernsteinPolynomial(map->layout)},
       {BernsteinPolynomial(map->layout), BernsteinPolynomial(map->layout), BernsteinPolynomial(map->layout)}}};
  for (int c = 0; c < 3; ++c) {
    BernsteinPolynomial coordinate(map->layout);
    coordinate.coefficients() = control.col(c);
    for (int k = 0; k < 3; ++k) columns[k][c] = reference_column(shape, coordinate, map->column_scale[k], k);
  }
  const auto& u = columns[0];
  const auto& v = columns[1];
  const auto& w = columns[2];
  return w[0] * (u[1] * v[2] - u[2] * v[1]) + w[1] * (u[2] * v[0] - u[0] * v[2]) + w[2] * (u[0] * v[1] - u[1] * v[0]);
}

}  // namespace semimesh::ho::detail
