// Reference values for the certified bounds: det J from the Lagrange basis on a dense grid. Shares
// nothing with the Bernstein code, so tests can compare the two.
#include "semimesh/ho/basis.hpp"
#include "semimesh/ho/validity.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace semimesh::ho {
namespace {

/// Grid of the reference element with n points per direction, boundary included; shape (count, 3).
Eigen::MatrixX3d reference_grid(Shape shape, int n) {
  std::vector<Eigen::Vector3d> points;
  const double step = 1.0 / (n - 1);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double a = i * step, b = j * step, c = k * step;  // in [0, 1]
        switch (shape) {
          case Shape::Tetrahedron:
            if (i + j + k < n) points.emplace_back(a, b, c);
            break;
          case Shape::Prism:
            if (i + j < n) points.emplace_back(a, b, 2 * c - 1);
            break;
          case Shape::Hexahedron: points.emplace_back(2 * a - 1, 2 * b - 1, 2 * c - 1); break;
          case Shape::Pyramid: {
            const double z = std::min(c, 1.0 - 1e-6);  // the rational basis is undefined at the apex
            points.emplace_back((2 * a - 1) * (1 - z), (2 * b - 1) * (1 - z), z);
            break;
          }
          default: throw std::invalid_argument("sample_jacobian: shape '" + to_string(shape) + "' is not 3D");
        }
      }
  Eigen::MatrixX3d grid(points.size(), 3);
  for (std::size_t p = 0; p < points.size(); ++p) grid.row(p) = points[p].transpose();
  return grid;
}

}  // namespace

SampledJacobian sample_jacobian(Shape shape, int order, NodeSet set, const Eigen::MatrixX3d& element_nodes,
                                int samples_per_direction) {
  if (samples_per_direction < 2)
    throw std::invalid_argument("sample_jacobian: samples_per_direction must be >= 2, got " +
                                std::to_string(samples_per_direction));
  if (dimension(shape) != 3) throw std::invalid_argument("sample_jacobian: shape '" + to_string(shape) + "' is not 3D");
  const LagrangeBasis basis(shape, order, set);
  if (element_nodes.rows() != basis.size())
    throw std::invalid_argument("sample_jacobian: a " + to_string(shape) + " of order " + std::to_string(order) +
                                " has " + std::to_string(basis.size()) + " nodes, got " +
                                std::to_string(element_nodes.rows()));
  SampledJacobian sampled{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const Eigen::Matrix3d& jacobian : jacobians(basis, element_nodes, reference_grid(shape, samples_per_direction))) {
    const double det = jacobian.determinant();
    sampled.min = std::min(sampled.min, det);
    sampled.max = std::max(sampled.max, det);
  }
  return sampled;
}

}  // namespace semimesh::ho
