#include "semimesh/ho/quadrature.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace semimesh::ho {
namespace {

struct Rule1d {
  std::vector<double> x, w;
};

// Gauss-Legendre nodes by Newton on P_n from Chebyshev guesses; w = 2 / ((1 - x^2) P_n'(x)^2).
Rule1d gauss_legendre(int n) {
  Rule1d r{std::vector<double>(n), std::vector<double>(n)};
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;  // P_0, P_1; recurrence up to P_n
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / dp;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    r.x[i] = x;
    r.w[i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  return r;
}

}  // namespace

Quadrature reference_quadrature(Shape shape, int n) {
  if (n < 1) throw std::invalid_argument("reference_quadrature: n must be >= 1");
  const Rule1d g = gauss_legendre(n);
  std::vector<Eigen::RowVector3d> pts;
  std::vector<double> wts;
  const auto add = [&](double x, double y, double z, double w) {
    pts.emplace_back(x, y, z);
    wts.push_back(w);
  };
  const int nz = dimension(shape) == 3 ? n : 1;
  const int ny = dimension(shape) >= 2 ? n : 1;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        const double a = g.x[i], b = g.x[j], c = g.x[k];
        const double w = g.w[i] * (dimension(shape) >= 2 ? g.w[j] : 1.0) * (dimension(shape) == 3 ? g.w[k] : 1.0);
        switch (shape) {
          case Shape::Segment: add(a, 0, 0, w); break;
          case Shape::Quadrilateral: add(a, b, 0, w); break;
          case Shape::Hexahedron: add(a, b, c, w); break;
          case Shape::Triangle: add(0.25 * (1 + a) * (1 - b), 0.5 * (1 + b), 0, w * (1 - b) / 8.0); break;
          case Shape::Prism: add(0.25 * (1 + a) * (1 - b), 0.5 * (1 + b), c, w * (1 - b) / 8.0); break;
          case Shape::Tetrahedron:
            add(0.125 * (1 + a) * (1 - b) * (1 - c), 0.25 * (1 + b) * (1 - c), 0.5 * (1 + c),
                w * (1 - b) * (1 - c) * (1 - c) / 64.0);
            break;
          case Shape::Pyramid: {
            const double z = 0.5 * (1 + c);
            add(a * (1 - z), b * (1 - z), z, w * 0.5 * (1 - z) * (1 - z));
            break;
          }
        }
      }
  Quadrature q{Eigen::MatrixX3d(pts.size(), 3), Eigen::VectorXd(wts.size())};
  for (std::size_t i = 0; i < pts.size(); ++i) {
    q.points.row(i) = pts[i];
    q.weights(i) = wts[i];
  }
  return q;
}

}  // namespace semimesh::ho
