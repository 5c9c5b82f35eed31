// Gauss quadrature on the reference elements against closed-form integrals of monomials.
#include "semimesh/ho/quadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace semimesh::ho {
namespace {

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

// Integral of x^a over [-1, 1].
double symmetric(int a) { return a % 2 == 1 ? 0.0 : 2.0 / (a + 1); }

// Integral of x^a y^b z^c over Gmsh's reference element (element_type.hpp), by hand:
// unit simplices by the Dirichlet formula a! b! c! / (a + b + c + d)!; the pyramid |x|, |y| <= 1 - z
// gives int_0^1 z^c (1 - z)^(a + b + 2) dz = c! (a + b + 2)! / (a + b + c + 3)!.
double exact(Shape shape, int a, int b, int c) {
  switch (shape) {
    case Shape::Segment: return symmetric(a);
    case Shape::Quadrilateral: return symmetric(a) * symmetric(b);
    case Shape::Hexahedron: return symmetric(a) * symmetric(b) * symmetric(c);
    case Shape::Triangle: return factorial(a) * factorial(b) / factorial(a + b + 2);
    case Shape::Prism: return factorial(a) * factorial(b) / factorial(a + b + 2) * symmetric(c);
    case Shape::Tetrahedron: return factorial(a) * factorial(b) * factorial(c) / factorial(a + b + c + 3);
    case Shape::Pyramid:
      return symmetric(a) / 2.0 * symmetric(b) / 2.0 * 4.0 * factorial(c) * factorial(a + b + 2) / factorial(a + b + c + 3);
  }
  return 0.0;
}

bool collapsed(Shape shape) {
  return shape == Shape::Triangle || shape == Shape::Tetrahedron || shape == Shape::Prism || shape == Shape::Pyramid;
}

TEST(ReferenceQuadrature, IntegratesMonomialsExactlyUpToItsDegree) {
  for (Shape shape : {Shape::Segment, Shape::Triangle, Shape::Quadrilateral, Shape::Tetrahedron, Shape::Pyramid,
                      Shape::Prism, Shape::Hexahedron})
    for (int n = 1; n <= 7; ++n) {
      const Quadrature q = reference_quadrature(shape, n);
      const int dim = dimension(shape);
      ASSERT_EQ(q.points.rows(), static_cast<long>(std::pow(n, dim))) << to_string(shape);
      // Tensor rules: degree 2n - 1 per direction; collapsed ones: total degree 2n - 3.
      const int per_direction = collapsed(shape) ? 2 * n - 3 : 2 * n - 1;
      for (int a = 0; a <= per_direction; ++a)
        for (int b = 0; b <= (dim >= 2 ? per_direction : 0); ++b)
          for (int c = 0; c <= (dim == 3 ? per_direction : 0); ++c) {
            if (collapsed(shape) && a + b + c > per_direction) continue;
            double sum = 0.0;
            for (int i = 0; i < q.points.rows(); ++i)
              sum += q.weights(i) * std::pow(q.points(i, 0), a) * std::pow(q.points(i, 1), b) * std::pow(q.points(i, 2), c);
            EXPECT_NEAR(sum, exact(shape, a, b, c), 1e-13)
                << to_string(shape) << " n=" << n << " x^" << a << " y^" << b << " z^" << c;
          }
    }
}

TEST(ReferenceQuadrature, OneDegreeTooManyIsNotExact) {
  // The rule can fail: x^(2n) on the segment is not integrated exactly by n points.
  const Quadrature q = reference_quadrature(Shape::Segment, 3);
  double sum = 0.0;
  for (int i = 0; i < q.points.rows(); ++i) sum += q.weights(i) * std::pow(q.points(i, 0), 6);
  EXPECT_GT(std::abs(sum - 2.0 / 7.0), 1e-3);
}

TEST(ReferenceQuadrature, RejectsNoPoints) { EXPECT_THROW(reference_quadrature(Shape::Prism, 0), std::invalid_argument); }

}  // namespace
}  // namespace semimesh::ho
