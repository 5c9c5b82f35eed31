#include "semimesh/ho/validity.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <tuple>

namespace semimesh::ho {
namespace {

const Eigen::MatrixX3d& cached_reference_nodes(Shape shape, int order, NodeSet set) {
  // The last one this thread asked for first: the checks ask for the same one element after
  // element, on every thread, and a shared lock per element made them queue.
  thread_local struct {
    Shape shape;
    int order = 0;
    NodeSet set;
    const Eigen::MatrixX3d* nodes = nullptr;
  } last;
  if (last.nodes && last.shape == shape && last.order == order && last.set == set) return *last.nodes;
  static std::mutex mutex;
  static std::map<std::tuple<Shape, int, NodeSet>, std::unique_ptr<Eigen::MatrixX3d>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto& slot = cache[{shape, order, set}];
  if (!slot) slot = std::make_unique<Eigen::MatrixX3d>(reference_nodes(shape, order, set));
  last.shape = shape, last.order = order, last.set = set, last.nodes = slot.get();  // entries never move
  return *slot;
}

/// Four vertices spanning the element (vertex 0 and its three neighbours along edges), Gmsh order.
std::array<int, 4> spanning_vertices(Shape shape) {
  switch (shape) {
    case Shape::Pyramid:
    case Shape::Hexahedron: return {0, 1, 3, 4};
    default: return {0, 1, 2, 3};  // tetrahedron, prism
  }
}

}  // namespace

double reference_volume(Shape shape) {
  switch (shape) {
    case Shape::Tetrahedron: return 1.0 / 6.0;
    case Shape::Pyramid: return 4.0 / 3.0;
    case Shape::Prism: return 1.0;
    case Shape::Hexahedron: return 8.0;
    default: throw std::invalid_argument("reference_volume: '" + to_string(shape) + "' is not a 3D shape");
  }
}

bool affine_jacobian(Shape shape, int order, NodeSet set, const Eigen::MatrixX3d& element_nodes,
                     JacobianBounds& bounds) {
  if (dimension(shape) != 3 || order < 1 || order > kMaxOrder || element_nodes.rows() != num_nodes(shape, order))
    return false;  // certify_jacobian_by_subdivision reports the bad input
  const Eigen::MatrixX3d& r = cached_reference_nodes(shape, order, set);
  const std::array<int, 4> v = spanning_vertices(shape);
  Eigen::Matrix3d dr, dx;
  for (int k = 0; k < 3; ++k) {
    dr.col(k) = (r.row(v[k + 1]) - r.row(v[0])).transpose();
    dx.col(k) = (element_nodes.row(v[k + 1]) - element_nodes.row(v[0])).transpose();
  }
  const Eigen::Matrix3d a = dx * dr.inverse();
  // sigma_min = |det A| / (sigma_1 sigma_2) >= 2 |det A| / |A|_F^2: a lower bound, no SVD needed.
  const double det = a.determinant();
  const double smallest_stretch = 2.0 * std::abs(det) / a.squaredNorm();
  const Eigen::RowVector3d b = element_nodes.row(v[0]) - r.row(v[0]) * a.transpose();
  // The deviation as computed, plus what rounding at the coordinates' magnitude can hide from it.
  const double rounding = 8.0 * std::numeric_limits<double>::epsilon() * element_nodes.rowwise().norm().maxCoeff();
  // Row by row: the (nodes, 3) image as one expression cost an allocation per element.
  double deviation = 0.0;
  for (Eigen::Index i = 0; i < r.rows(); ++i) {
    const double d = (r.row(i) * a.transpose() + b - element_nodes.row(i)).norm();
    if (std::isnan(d)) return false;
    deviation = std::max(deviation, d);
  }
  deviation += rounding;
  if (!(smallest_stretch > 0.0) || !(deviation <= kAffineTolerance * smallest_stretch)) return false;
  bounds = JacobianBounds{};
  bounds.min_lower = bounds.min_upper = bounds.max_upper = det;
  bounds.valid = det > 0.0;
  bounds.proven = true;
  bounds.integral = det * reference_volume(shape);
  return true;
}

}  // namespace semimesh::ho
