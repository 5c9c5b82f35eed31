// Lagrange bases: modal basis, Vandermonde at the nodes, inverted once per (shape, order, set).
#include "semimesh/ho/basis.hpp"

#include "modal_basis.hpp"

#include <Eigen/Dense>

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
};

namespace {

std::shared_ptr<const LagrangeBasis::Data> build(Shape shape, int order, NodeSet set) {
  auto data = std::make_shared<LagrangeBasis::Data>();
  data->shape = shape;
  data->order = order;
  data->set = set;
  data->nodes = reference_nodes(shape, order, set);
  const Eigen::MatrixXd vandermonde = detail::modal_values(shape, order, data->nodes);  // V(node, mode)
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(vandermonde);
  data->modal_to_nodal = lu.solve(Eigen::MatrixXd::Identity(vandermonde.rows(), vandermonde.cols()));
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
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(vandermonde);  // singular values only
  const Eigen::VectorXd& sigma = svd.singularValues();
  return sigma(0) / sigma(sigma.size() - 1);
}

}  // namespace semimesh::ho
