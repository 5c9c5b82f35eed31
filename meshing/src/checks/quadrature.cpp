#include "quadrature.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace semimesh::checks::detail {

QuadratureRule gauss_legendre_01(int n) {
  // Roots of P_n by Newton's method from Chebyshev-like guesses; weights 2 / ((1 - x^2) P_n'(x)^2)
  // on [-1, 1] (Abramowitz & Stegun 25.4.29), then mapped to [0, 1].
  QuadratureRule rule;
  rule.points = Eigen::MatrixX3d::Zero(n, 3);
  rule.weights.resize(n);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-15) break;
    }
    rule.points(i, 0) = 0.5 * (1.0 - x);
    rule.weights(i) = 1.0 / ((1.0 - x * x) * derivative * derivative);  // half of the [-1, 1] weight
  }
  return rule;
}

QuadratureRule unit_square_rule(int n) {
  const QuadratureRule g = gauss_legendre_01(n);
  QuadratureRule rule;
  rule.points = Eigen::MatrixX3d::Zero(n * n, 3);
  rule.weights.resize(n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      rule.points.row(i * n + j) << g.points(i, 0), g.points(j, 0), 0.0;
      rule.weights(i * n + j) = g.weights(i) * g.weights(j);
    }
  return rule;
}

QuadratureRule unit_triangle_rule(int n) {
  // (a, b) in [0,1]^2 -> (a (1 - b), b), Jacobian (1 - b).
  QuadratureRule rule = unit_square_rule(n);
  for (int q = 0; q < rule.points.rows(); ++q) {
    const double a = rule.points(q, 0), b = rule.points(q, 1);
    rule.points.row(q) << a * (1.0 - b), b, 0.0;
    rule.weights(q) *= 1.0 - b;
  }
  return rule;
}

QuadratureRule volume_rule(ho::Shape shape, int n) {
  const QuadratureRule g = gauss_legendre_01(n);
  QuadratureRule rule;
  rule.points = Eigen::MatrixX3d::Zero(n * n * n, 3);
  rule.weights.resize(n * n * n);
  int q = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k, ++q) {
        const double a = g.points(i, 0), b = g.points(j, 0), c = g.points(k, 0);
        double w = g.weights(i) * g.weights(j) * g.weights(k);
        Eigen::Vector3d x;
        switch (shape) {
          case ho::Shape::Tetrahedron:  // unit tetrahedron
            x << a * (1 - b) * (1 - c), b * (1 - c), c;
            w *= (1 - b) * (1 - c) * (1 - c);
            break;
          case ho::Shape::Prism:  // unit triangle x [-1, 1]
            x << a * (1 - b), b, 2 * c - 1;
            w *= 2 * (1 - b);
            break;
          case ho::Shape::Hexahedron:  // [-1, 1]^3
            x << 2 * a - 1, 2 * b - 1, 2 * c - 1;
            w *= 8;
            break;
          case ho::Shape::Pyramid:  // base [-1, 1]^2 at z = 0, apex (0, 0, 1)
            x << (2 * a - 1) * (1 - c), (2 * b - 1) * (1 - c), c;
            w *= 4 * (1 - c) * (1 - c);
            break;
          default:
            throw std::invalid_argument("volume_rule: " + ho::to_string(shape) + " is not a 3D shape");
        }
        rule.points.row(q) = x.transpose();
        rule.weights(q) = w;
      }
  return rule;
}

}  // namespace semimesh::checks::detail
