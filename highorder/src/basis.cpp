// Lagrange bases: modal basis, Vandermonde at the nodes, inverted once per (shape, order, set).
// Values of the product shapes (quadrilateral, hexahedron: segment^2, segment^3; prism: triangle x
// segment) are the products of their factors' Lagrange values: their node sets are the products of
// the factors' node sets (node_set.cpp), so the product of the factors' Lagrange functions is 1 at
// its node and 0 at the others, and it lies in the shape's space: it is the Lagrange function. That
// costs O(size) per point instead of O(size^2); values_by_modes is the reference.
#include "semimesh/ho/basis.hpp"

#include "modal_basis.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <tuple>

namespace semimesh::ho {

struct LagrangeBasis::Data {
  Shape shape;
  int order;
  NodeSet set;
  Eigen::MatrixX3d nodes;        // (size, 3)
  Eigen::MatrixXd modal_to_nodal;  // (size, size): inverse Vandermonde; Lagrange = modal * this
  // Product shapes: each factor (its shape, the reference coordinates it takes) and, per node, the
  // factor's node it is made of. Empty for the other shapes.
  struct Factor {
    Shape shape;
    std::vector<int> coordinates;
    std::vector<int> node_of;  // [node] the factor's node
    Eigen::VectorXd line_nodes;  // a segment's nodes (its values by the product formula)
  };
  std::vector<Factor> factors;
};

namespace {

std::vector<LagrangeBasis::Data::Factor> product_factors(Shape shape) {
  switch (shape) {
    case Shape::Quadrilateral: return {{Shape::Segment, {0}, {}, {}}, {Shape::Segment, {1}, {}, {}}};
    case Shape::Hexahedron:
      return {{Shape::Segment, {0}, {}, {}}, {Shape::Segment, {1}, {}, {}}, {Shape::Segment, {2}, {}, {}}};
    case Shape::Prism: return {{Shape::Triangle, {0, 1}, {}, {}}, {Shape::Segment, {2}, {}, {}}};
    default: return {};
  }
}

// Each node of a product shape as the factors' nodes it is made of (coordinates equal to round-off).
void match_factor_nodes(LagrangeBasis::Data& data) {
  data.factors = product_factors(data.shape);
  for (auto& factor : data.factors) {
    const Eigen::MatrixX3d own = reference_nodes(factor.shape, data.order, data.set);
    if (factor.shape == Shape::Segment) factor.line_nodes = own.col(0);
    for (int n = 0; n < data.nodes.rows(); ++n) {
      int found = -1;
      for (int m = 0; m < own.rows() && found < 0; ++m) {
        bool same = true;
        for (std::size_t k = 0; k < factor.coordinates.size(); ++k)
          same = same && std::abs(own(m, static_cast<int>(k)) - data.nodes(n, factor.coordinates[k])) < 1e-12;
        if (same) found = m;
      }
      if (found < 0)
        throw std::logic_error("LagrangeBasis: node " + std::to_string(n) + " of the " + to_string(data.shape) +
                               " is not a product of its factors' nodes");
      factor.node_of.push_back(found);
    }
  }
}

std::shared_ptr<const LagrangeBasis::Data> build(Shape shape, int order, NodeSet set) {
  auto data = std::make_shared<LagrangeBasis::Data>();
  data->shape = shape;
  data->order = order;
  data->set = set;
  data->nodes = reference_nodes(shape, order, set);
  const Eigen::MatrixXd vandermonde = detail::modal_values(shape, order, data->nodes);  // V(node, mode)
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(vandermonde);
  data->modal_to_nodal = lu.solve(Eigen::MatrixXd::Identity(vandermonde.rows(), vandermonde.cols()));
  match_factor_nodes(*data);
  return data;
}

std::shared_ptr<const LagrangeBasis::Data> cached(Shape shape, int order, NodeSet set) {
  static std::mutex mutex;
  static std::map<std::tuple<Shape, int, NodeSet>, std::shared_ptr<const LagrangeBasis::Data>> cache;
  const auto key = std::make_tuple(shape, order, set);
  {
    const std::lock_guard<std::mutex> lock(mutex);
    const auto found = cache.find(key);
    if (found != cache.end()) return found->second;
  }
  // Built outside the lock (large orders take a moment); if two threads race, the first stored wins.
  auto data = build(shape, order, set);
  const std::lock_guard<std::mutex> lock(mutex);
  return cache.emplace(key, std::move(data)).first->second;
}

// (points, nodes): the 1D Lagrange functions of `nodes` at x, l_m(x) = prod_{j != m} (x - t_j) / (t_m - t_j).
Eigen::MatrixXd line_lagrange_values(const Eigen::VectorXd& nodes, const Eigen::VectorXd& x) {
  const Eigen::Index n = nodes.size();
  Eigen::MatrixXd out = Eigen::MatrixXd::Ones(x.size(), n);
  for (Eigen::Index m = 0; m < n; ++m)
    for (Eigen::Index j = 0; j < n; ++j)
      if (j != m) out.col(m).array() *= (x.array() - nodes[j]) / (nodes[m] - nodes[j]);
  return out;
}

void check_points(const Eigen::MatrixX3d& points) {
  if (!points.allFinite()) throw std::invalid_argument("LagrangeBasis: reference points contain NaN or infinity");
}

}  // namespace

LagrangeBasis::LagrangeBasis(Shape shape, int order, NodeSet set) {
  if (order < 1 || order > kMaxOrder) {
    throw std::invalid_argument("LagrangeBasis: order of " + to_string(shape) + " must be in [1, " +
                                std::to_string(kMaxOrder) + "], got " + std::to_string(order));
  }
  data_ = cached(shape, order, set);
}

Shape LagrangeBasis::shape() const { return data_->shape; }
int LagrangeBasis::order() const { return data_->order; }
NodeSet LagrangeBasis::node_set() const { return data_->set; }
int LagrangeBasis::size() const { return static_cast<int>(data_->nodes.rows()); }
const Eigen::MatrixX3d& LagrangeBasis::nodes() const { return data_->nodes; }

Eigen::MatrixXd LagrangeBasis::values(const Eigen::MatrixX3d& points) const {
  if (data_->factors.empty()) return values_by_modes(points);
  check_points(points);
  Eigen::MatrixXd out = Eigen::MatrixXd::Ones(points.rows(), size());
  for (const Data::Factor& factor : data_->factors) {
    Eigen::MatrixXd v;
    if (factor.shape == Shape::Segment) {
      v = line_lagrange_values(factor.line_nodes, points.col(factor.coordinates[0]));
    } else {
      Eigen::MatrixX3d own = Eigen::MatrixX3d::Zero(points.rows(), 3);
      for (std::size_t k = 0; k < factor.coordinates.size(); ++k)
        own.col(static_cast<int>(k)) = points.col(factor.coordinates[k]);
      v = LagrangeBasis(factor.shape, data_->order, data_->set).values_by_modes(own);
    }
    for (int n = 0; n < size(); ++n) out.col(n).array() *= v.col(factor.node_of[n]).array();
  }
  return out;
}

Eigen::MatrixXd LagrangeBasis::values_by_modes(const Eigen::MatrixX3d& points) const {
  check_points(points);
  return detail::modal_values(data_->shape, data_->order, points) * data_->modal_to_nodal;
}

std::array<Eigen::MatrixXd, 3> LagrangeBasis::gradients(const Eigen::MatrixX3d& points) const {
  check_points(points);
  std::array<Eigen::MatrixXd, 3> modal;
  detail::modal_values(data_->shape, data_->order, points, &modal);
  for (auto& g : modal) g = g * data_->modal_to_nodal;
  return modal;
}

Eigen::MatrixXd interpolation_matrix(const LagrangeBasis& from, const LagrangeBasis& to) {
  if (from.shape() != to.shape()) {
    throw std::invalid_argument("interpolation_matrix: shapes differ (" + to_string(from.shape()) + " to " +
                                to_string(to.shape()) + ")");
  }
  return from.values(to.nodes());
}

namespace {

void check_element_nodes(const LagrangeBasis& basis, const Eigen::MatrixX3d& element_nodes, const char* caller) {
  if (element_nodes.rows() != basis.size()) {
    throw std::invalid_argument(std::string(caller) + ": " + to_string(basis.shape()) + " of order " +
                                std::to_string(basis.order()) + " needs " + std::to_string(basis.size()) +
                                " element nodes, got " + std::to_string(element_nodes.rows()));
  }
}

}  // namespace

Eigen::MatrixX3d map_points(const LagrangeBasis& basis, const Eigen::MatrixX3d& element_nodes,
                            const Eigen::MatrixX3d& ref_points) {
  check_element_nodes(basis, element_nodes, "map_points");
  return basis.values(ref_points) * element_nodes;
}

std::vector<Eigen::Matrix3d> jacobians(const LagrangeBasis& basis, const Eigen::MatrixX3d& element_nodes,
                                       const Eigen::MatrixX3d& ref_points) {
  check_element_nodes(basis, element_nodes, "jacobians");
  const std::array<Eigen::MatrixXd, 3> gradients = basis.gradients(ref_points);
  std::array<Eigen::MatrixX3d, 3> columns;  // columns[j] (npoints, 3) = d chi / d xi_j
  for (int j = 0; j < 3; ++j) columns[j] = gradients[j] * element_nodes;
  std::vector<Eigen::Matrix3d> out(ref_points.rows());
  for (Eigen::Index q = 0; q < ref_points.rows(); ++q)
    for (int j = 0; j < 3; ++j) out[q].col(j) = columns[j].row(q).transpose();
  return out;
}

double vandermonde_condition_number(Shape shape, int order, NodeSet set) {
  const Eigen::MatrixXd vandermonde = detail::modal_values(shape, order, reference_nodes(shape, order, set));
  // Singular values as the square roots of V^T V's eigenvalues: the smallest loses about
  // eps * cond^2 relative, 1e-8 at the worst case here (order-10 equispaced prism, cond ~4e3).
  // Eigen's BDCSVD alone took ~35 s of this file's compile.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(vandermonde.transpose() * vandermonde,
                                                             Eigen::EigenvaluesOnly);
  const Eigen::VectorXd& lambda = eigen.eigenvalues();  // ascending
  return std::sqrt(lambda(lambda.size() - 1) / lambda(0));
}

}  // namespace semimesh::ho
