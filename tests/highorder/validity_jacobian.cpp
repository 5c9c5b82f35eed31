// Certified det J bounds checked against closed-form maps (exact det J known by hand) and against
// dense sampling through the Lagrange basis (an independent implementation).
#include "semimesh/ho/basis.hpp"
#include "mapped_nodes.hpp"
#include "semimesh/ho/quality.hpp"
#include "semimesh/ho/validity.hpp"
#include "validity/jacobian_polynomial.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>

namespace semimesh::ho {
namespace {

const Shape kShapes[] = {Shape::Tetrahedron, Shape::Pyramid, Shape::Prism, Shape::Hexahedron};

using testing::Map;
using testing::mapped_nodes;

std::string label(Shape shape, int order) { return to_string(shape) + " P" + std::to_string(order); }

TEST(CertifyJacobian, AffineElementsHaveConstantDetJ) {
  Eigen::Matrix3d a;
  a << 2.0, 0.3, 0.1, 0.2, 1.5, -0.2, 0.1, 0.4, 0.8;
  const Eigen::Vector3d shift(3.0, -1.0, 0.5);
  // For x = A xi + b, det J = det A = element volume / reference volume.
  const double expected = a.determinant();
  for (Shape shape : kShapes)
    for (NodeSet set : {NodeSet::Equispaced, NodeSet::GLL})
      for (int order : {1, 2, 3, 5, 8}) {
        const Eigen::MatrixX3d nodes =
            mapped_nodes(shape, order, set, [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return a * x + shift; });
        // The Bernstein path itself (certify_jacobian takes the affine fast path here).
        const JacobianBounds b = certify_jacobian_by_subdivision(shape, order, set, nodes);
        SCOPED_TRACE(label(shape, order) + (set == NodeSet::GLL ? " GLL" : " equispaced"));
        // Equispaced nodes of order 8 make the node-to-Bezier conversion ill-conditioned (norm ~1e8).
        const double tolerance = (set == NodeSet::Equispaced && order == 8 ? 1e-7 : 1e-9) * expected;
        EXPECT_TRUE(b.valid);
        EXPECT_TRUE(b.proven);
        EXPECT_EQ(b.subdivisions, 0);
        EXPECT_NEAR(b.min_lower, expected, tolerance);
        EXPECT_NEAR(b.min_upper, expected, tolerance);
        EXPECT_NEAR(b.max_upper, expected, tolerance);
        EXPECT_NEAR(scaled_jacobian(b), 1.0, 2 * tolerance / expected);
      }
}

// The affine fast path against the Bernstein reference: the same verdict and bounds on random affine
// elements (valid and inverted) of every shape, order and node set, and no fast path as soon as one
// node leaves the affine image or the element is nearly flat.
TEST(CertifyJacobian, AffineFastPathAgreesWithSubdivision) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (Shape shape : kShapes)
    for (NodeSet set : {NodeSet::Equispaced, NodeSet::GLL})
      for (int order : {1, 2, 4, 6}) {
        SCOPED_TRACE(label(shape, order) + (set == NodeSet::GLL ? " GLL" : " equispaced"));
        for (int trial = 0; trial < 4; ++trial) {
          Eigen::Matrix3d a = Eigen::Matrix3d::Identity() * 2.0;
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) a(i, j) += 0.6 * u(rng);
          if (trial == 3) a.col(0) *= -1.0;  // inverted
          const Eigen::Vector3d shift(5.0 * u(rng), 5.0 * u(rng), 5.0 * u(rng));
          Eigen::MatrixX3d nodes =
              mapped_nodes(shape, order, set, [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return a * x + shift; });
          JacobianBounds fast;
          ASSERT_TRUE(affine_jacobian(shape, order, set, nodes, fast));
          const JacobianBounds slow = certify_jacobian_by_subdivision(shape, order, set, nodes);
          EXPECT_EQ(fast.valid, slow.valid);
          EXPECT_EQ(fast.proven, slow.proven);
          const double tolerance = 1e-7 * std::abs(a.determinant());
          EXPECT_NEAR(fast.min_lower, slow.min_lower, tolerance);
          EXPECT_NEAR(fast.max_upper, slow.max_upper, tolerance);
          EXPECT_NEAR(scaled_jacobian(fast), scaled_jacobian(slow), 1e-7);
          if (order > 1) {  // one node off the affine image: the general path decides
            nodes(nodes.rows() - 1, 1) += 1e-6;
            JacobianBounds unused;
            EXPECT_FALSE(affine_jacobian(shape, order, set, nodes, unused));
          }
        }
        // Thin (1e-9) and far from the origin: the round-off of the node positions is then large
        // against the element's smallest stretch, so it is left to the general path.
        Eigen::Matrix3d thin = Eigen::Matrix3d::Identity();
        thin(2, 2) = 1e-9;
        const Eigen::Vector3d far(1e3, 1e3, 1e3);
        JacobianBounds unused;
        EXPECT_FALSE(affine_jacobian(
            shape, order, set,
            mapped_nodes(shape, order, set, [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return thin * x + far; }),
            unused));
      }
}

// The trilinear fast path against the Bernstein reference: the same verdict and bounds (to
// rounding) on random trilinear hexahedra, graded like the wake's layers, of every order and node
// set; its volume; bounds that hold against dense sampling; no fast path for a curved or inverted element.
TEST(CertifyJacobian, TrilinearFastPathAgreesWithSubdivision) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (NodeSet set : {NodeSet::Equispaced, NodeSet::GLL})
    for (int order : {2, 3, 4, 6}) {
      SCOPED_TRACE(label(Shape::Hexahedron, order) + (set == NodeSet::GLL ? " GLL" : " equispaced"));
      for (int trial = 0; trial < 6; ++trial) {
        // A box 1 x 0.5 x 0.02 whose eight corners move by up to a fifth of the thinnest side
        // (trial 5: a quarter of its length, so that some corner's det J comes near zero).
        std::array<Eigen::Vector3d, 8> corners;
        const double reach = trial == 5 ? 0.4 : 0.2;
        for (int v = 0; v < 8; ++v) {
          const Eigen::Vector3d r = reference_nodes(Shape::Hexahedron, 1).row(v).transpose();
          corners[v] = Eigen::Vector3d(0.5 * r[0], 0.25 * r[1], 0.01 * r[2]) + Eigen::Vector3d(3, -2, 7) +
                       0.02 * reach * Eigen::Vector3d(u(rng), u(rng), u(rng));
        }
        const auto trilinear = [&](const Eigen::Vector3d& r) -> Eigen::Vector3d {
          Eigen::Vector3d x = Eigen::Vector3d::Zero();
          for (int v = 0; v < 8; ++v) {
            const Eigen::Vector3d c = reference_nodes(Shape::Hexahedron, 1).row(v).transpose();
            x += corners[v] * (1 + c[0] * r[0]) * (1 + c[1] * r[1]) * (1 + c[2] * r[2]) / 8;
          }
          return x;
        };
        Eigen::MatrixX3d nodes = mapped_nodes(Shape::Hexahedron, order, set, trilinear);
        const JacobianBounds slow = certify_jacobian_by_subdivision(Shape::Hexahedron, order, set, nodes, 8, 0.1);
        JacobianBounds fast;
        if (!slow.valid) {
          EXPECT_FALSE(trilinear_jacobian(order, set, nodes, fast, 8, 0.1));
          continue;
        }
        ASSERT_TRUE(trilinear_jacobian(order, set, nodes, fast, 8, 0.1));
        const double scale = std::abs(slow.max_upper);
        EXPECT_NEAR(fast.min_lower, slow.min_lower, 1e-9 * scale);
        EXPECT_NEAR(fast.min_upper, slow.min_upper, 1e-9 * scale);
        EXPECT_NEAR(fast.max_upper, slow.max_upper, 1e-9 * scale);
        EXPECT_EQ(fast.subdivisions, slow.subdivisions);
        // Its volume against the mean of the element's own det J coefficients (all its nodes).
        const double volume = detail::jacobian_determinant(Shape::Hexahedron, order, set, nodes).coefficients().mean() *
                              reference_volume(Shape::Hexahedron);
        EXPECT_NEAR(fast.integral, volume, 1e-12 * std::abs(volume));
        const SampledJacobian sampled = sample_jacobian(Shape::Hexahedron, order, set, nodes, 9);
        EXPECT_LE(fast.min_lower, sampled.min * (1 + 1e-9));
        EXPECT_GE(fast.max_upper, sampled.max * (1 - 1e-9));
        // One interior node moved by a hundredth of the thickness: curved, left to the general path.
        nodes(nodes.rows() - 1, 2) += 2e-4;
        EXPECT_FALSE(trilinear_jacobian(order, set, nodes, fast));
        // A node that is not a number (corrupt input) is no trilinear element's either.
        nodes(nodes.rows() - 1, 2) = std::numeric_limits<double>::quiet_NaN();
        EXPECT_FALSE(trilinear_jacobian(order, set, nodes, fast));
      }
      // Inverted (two corners' layers swapped): refused, and the general path finds it invalid.
      Eigen::MatrixX3d flipped = mapped_nodes(Shape::Hexahedron, order, set, [](const Eigen::Vector3d& r) -> Eigen::Vector3d {
        return {r[0], r[1], -0.1 * r[2]};
      });
      JacobianBounds unused;
      EXPECT_FALSE(trilinear_jacobian(order, set, flipped, unused));
      EXPECT_FALSE(certify_jacobian(Shape::Hexahedron, order, set, flipped).valid);
    }
  JacobianBounds unused;
  EXPECT_FALSE(trilinear_jacobian(1, NodeSet::Equispaced, reference_nodes(Shape::Hexahedron, 1), unused))
      << "order 1: the general path is that element";
}

TEST(CertifyJacobian, ReferenceVolumesGiveUnitDetJ) {
  // The reference element itself: det J = 1; a pyramid scaled by 2 in z only: det J = 2.
  for (Shape shape : kShapes) {
    const JacobianBounds b = certify_jacobian(shape, 2, NodeSet::Equispaced, reference_nodes(shape, 2));
    EXPECT_NEAR(b.min_lower, 1.0, 1e-12) << to_string(shape);
    EXPECT_NEAR(b.max_upper, 1.0, 1e-12) << to_string(shape);
  }
  const Eigen::MatrixX3d tall = mapped_nodes(Shape::Pyramid, 3, NodeSet::Equispaced,
                                             [](const Eigen::Vector3d& x) -> Eigen::Vector3d { return {x[0], x[1], 2 * x[2]}; });
  const JacobianBounds b = certify_jacobian(Shape::Pyramid, 3, NodeSet::Equispaced, tall);
  EXPECT_NEAR(b.min_lower, 2.0, 1e-12);
  EXPECT_NEAR(b.max_upper, 2.0, 1e-12);
}

TEST(CertifyJacobian, CurvedValidElementAgreesWithSampling) {
  // A smooth bump of small amplitude on the whole element (so on every face too).
  const Map bump = [](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return {x[0] + 0.04 * std::sin(2.0 * x[1] + 1.0), x[1] + 0.05 * std::cos(1.5 * x[2]) * x[0],
            x[2] + 0.08 * std::sin(3.0 * x[0]) * std::cos(2.0 * x[1])};
  };
  for (Shape shape : kShapes)
    for (int order : {2, 3, 4}) {
      SCOPED_TRACE(label(shape, order));
      const Eigen::MatrixX3d nodes = mapped_nodes(shape, order, NodeSet::Equispaced, bump);
      const JacobianBounds b = certify_jacobian(shape, order, NodeSet::Equispaced, nodes);
      const SampledJacobian s = sample_jacobian(shape, order, NodeSet::Equispaced, nodes, 15);
      EXPECT_TRUE(b.valid);
      EXPECT_TRUE(b.proven);
      EXPECT_GT(b.min_lower, 0.0);
      EXPECT_GE(s.min, b.min_lower - 1e-12);
      EXPECT_LE(s.max, b.max_upper + 1e-12);
      EXPECT_LT(s.min, 1.0);  // really curved: det J is not the affine 1
      EXPECT_GT(s.max, 1.0);
      // The bounds are not wildly loose for a mildly curved element.
      EXPECT_GT(b.min_lower, 0.5 * s.min);
      EXPECT_LT(b.max_upper, 1.5 * s.max);
      const double quality = scaled_jacobian(b);
      EXPECT_GT(quality, 0.0);
      EXPECT_LE(quality, s.min / s.max + 1e-12);
    }
}

// Elements whose det J is positive at every node but negative between nodes. The map
// (x, y, z) = (xi, eta, zeta * q(xi)) has det J = q(xi) exactly; q is a quadratic that is positive at
// every node coordinate xi of the element and negative in between.
struct TrapCase {
  Shape shape;
  int order;
  std::function<double(double)> q;
};

TEST(CertifyJacobian, ValidAtEveryNodeButInvalidBetweenIsRejected) {
  const TrapCase cases[] = {
      // Hexahedron P2: nodes at xi in {-1, 0, 1}; q(-1/2) = -0.1.
      {Shape::Hexahedron, 2, [](double x) { return (x + 0.5) * (x + 0.5) - 0.1; }},
      // Prism P2: nodes at xi in {0, 1/2, 1}; q(1/4) = -0.03.
      {Shape::Prism, 2, [](double x) { return (x - 0.25) * (x - 0.25) - 0.03; }},
      // Tetrahedron P3 (z has total degree 3): nodes at xi in {0, 1/3, 2/3, 1}; q(1/6) = -0.01.
      {Shape::Tetrahedron, 3, [](double x) { return (x - 1.0 / 6) * (x - 1.0 / 6) - 0.01; }},
      // Pyramid P3: nodes at xi in {0, +-1/3, +-2/3, +-1}; q(-1/6) = -0.01.
      {Shape::Pyramid, 3, [](double x) { return (x + 1.0 / 6) * (x + 1.0 / 6) - 0.01; }},
  };
  for (const TrapCase& trap : cases) {
    SCOPED_TRACE(label(trap.shape, trap.order));
    const Eigen::MatrixX3d nodes = mapped_nodes(trap.shape, trap.order, NodeSet::Equispaced,
                                                [&](const Eigen::Vector3d& x) -> Eigen::Vector3d {
                                                  return {x[0], x[1], x[2] * trap.q(x[0])};
                                                });
    const LagrangeBasis basis(trap.shape, trap.order);
    for (const Eigen::Matrix3d& j : jacobians(basis, nodes, basis.nodes())) ASSERT_GT(j.determinant(), 0.0);
    ASSERT_LT(sample_jacobian(trap.shape, trap.order, NodeSet::Equispaced, nodes, 25).min, 0.0);

    const JacobianBounds b = certify_jacobian(trap.shape, trap.order, NodeSet::Equispaced, nodes);
    EXPECT_FALSE(b.valid);
    EXPECT_TRUE(b.proven);
    EXPECT_LE(b.min_upper, 0.0);
    EXPECT_GT(b.subdivisions, 0);
    EXPECT_LT(scaled_jacobian(b), 0.0);
  }
}

TEST(CertifyJacobian, InvertedElementIsInvalid) {
  const Map mirror = [](const Eigen::Vector3d& x) -> Eigen::Vector3d { return {-x[0], x[1], x[2]}; };
  for (Shape shape : kShapes)
    for (int order : {1, 2, 4}) {
      SCOPED_TRACE(label(shape, order));
      const JacobianBounds b =
          certify_jacobian(shape, order, NodeSet::Equispaced, mapped_nodes(shape, order, NodeSet::Equispaced, mirror));
      EXPECT_FALSE(b.valid);
      EXPECT_TRUE(b.proven);
      EXPECT_NEAR(b.max_upper, -1.0, 1e-12);
      EXPECT_DOUBLE_EQ(scaled_jacobian(b), -1.0);
    }
}

TEST(CertifyJacobian, NodeSetDoesNotChangeTheBoundsOfAPolynomialMap) {
  // The same order-2 polynomial map given by equispaced and by GLL nodes is the same element.
  const Map quadratic = [](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return {x[0] + 0.1 * x[1] * x[1], x[1] - 0.05 * x[0] * x[2], x[2] + 0.1 * x[0] * x[0]};
  };
  for (Shape shape : kShapes)
    for (int order : {2, 4}) {
      SCOPED_TRACE(label(shape, order));
      const JacobianBounds eq = certify_jacobian(shape, order, NodeSet::Equispaced,
                                                 mapped_nodes(shape, order, NodeSet::Equispaced, quadratic));
      const JacobianBounds gll =
          certify_jacobian(shape, order, NodeSet::GLL, mapped_nodes(shape, order, NodeSet::GLL, quadratic));
      EXPECT_NEAR(eq.min_lower, gll.min_lower, 1e-9);
      EXPECT_NEAR(eq.max_upper, gll.max_upper, 1e-9);
    }
}

/// Reference element with every node moved by up to `amplitude` / order in each coordinate.
Eigen::MatrixX3d perturbed_nodes(Shape shape, int order, double amplitude, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::MatrixX3d nodes = reference_nodes(shape, order);
  for (int i = 0; i < nodes.rows(); ++i)
    for (int k = 0; k < 3; ++k) nodes(i, k) += amplitude / order * unit(rng);
  return nodes;
}

TEST(CertifyJacobian, AgreesWithSamplingOnRandomElements) {
  std::mt19937 rng(20261125);
  std::uniform_real_distribution<double> amplitude(0.0, 0.5);
  int valid_count = 0, invalid_count = 0;
  for (Shape shape : kShapes)
    for (int order : {1, 2, 3, 4, 6}) {
      const int trials = order <= 4 ? 30 : 4;
      const int samples = order <= 4 ? 13 : 9;
      for (int trial = 0; trial < trials; ++trial) {
        SCOPED_TRACE(label(shape, order) + " trial " + std::to_string(trial));
        const Eigen::MatrixX3d nodes = perturbed_nodes(shape, order, amplitude(rng), rng);
        const JacobianBounds b = certify_jacobian(shape, order, NodeSet::Equispaced, nodes);
        const SampledJacobian s = sample_jacobian(shape, order, NodeSet::Equispaced, nodes, samples);
        const double tolerance = 1e-9 * std::max(1.0, std::abs(s.max));
        EXPECT_GE(s.min, b.min_lower - tolerance);
        EXPECT_LE(s.max, b.max_upper + tolerance);
        if (s.min <= 0.0) {
          EXPECT_FALSE(b.valid);  // sampling found a non-positive det J
        }
        if (b.valid) {
          EXPECT_GT(s.min, 0.0);
        }
        // A proven-invalid verdict rests on an evaluated value <= 0; sampling sees a value at least
        // close to it (the negative region may be narrower than the sampling grid).
        if (b.proven && !b.valid) {
          EXPECT_LE(s.min, 0.05 * s.max);
        }
        EXPECT_TRUE(b.proven);
        (b.valid ? valid_count : invalid_count)++;
      }
    }
  // The random set exercises both verdicts.
  EXPECT_GT(valid_count, 50);
  EXPECT_GT(invalid_count, 20);
}

TEST(CertifyJacobian, RejectsBadInput) {
  const Eigen::MatrixX3d nodes = reference_nodes(Shape::Hexahedron, 2);
  EXPECT_THROW(certify_jacobian(Shape::Hexahedron, 3, NodeSet::Equispaced, nodes), std::invalid_argument);
  EXPECT_THROW(certify_jacobian(Shape::Quadrilateral, 2, NodeSet::Equispaced, reference_nodes(Shape::Quadrilateral, 2)),
               std::invalid_argument);
  EXPECT_THROW(sample_jacobian(Shape::Hexahedron, 2, NodeSet::Equispaced, nodes, 1), std::invalid_argument);
}

TEST(ScaledJacobian, FromBounds) {
  JacobianBounds b;
  b.min_lower = 1.0;
  b.max_upper = 4.0;
  EXPECT_DOUBLE_EQ(scaled_jacobian(b), 0.25);
  b.min_lower = -1.0;
  b.max_upper = 2.0;
  EXPECT_DOUBLE_EQ(scaled_jacobian(b), -0.5);
  b.min_lower = -3.0;
  b.max_upper = 1.0;
  EXPECT_DOUBLE_EQ(scaled_jacobian(b), -1.0);
  b.min_lower = -3.0;
  b.max_upper = -1.0;
  EXPECT_DOUBLE_EQ(scaled_jacobian(b), -1.0);
}

TEST(ElementQuality, MatchesBoundsOfCertification) {
  const Eigen::MatrixX3d nodes = mapped_nodes(Shape::Prism, 3, NodeSet::Equispaced, [](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return {x[0], x[1], x[2] * (1.0 + 0.3 * x[0])};  // det J = 1 + 0.3 xi in [1, 1.3]
  });
  const ElementQuality q = element_quality(Shape::Prism, 3, NodeSet::Equispaced, nodes);
  EXPECT_TRUE(q.bounds.valid);
  EXPECT_NEAR(q.bounds.min_lower, 1.0, 1e-12);
  EXPECT_NEAR(q.bounds.max_upper, 1.3, 1e-12);
  EXPECT_NEAR(q.scaled_jacobian, 1.0 / 1.3, 1e-12);
}

// A straight prism whose top vertex above vertex 1 is at height s: det J = 1 + (s - 1) xi is linear
// (Gmsh's reference prism: xi, eta in the unit triangle, zeta in [-1, 1]; det J at vertex 1 is s
// times the others'), so min / max det J = s exactly.
Eigen::MatrixX3d tapered_prism(int order, double s) {
  return mapped_nodes(Shape::Prism, order, NodeSet::GLL, [s](const Eigen::Vector3d& r) -> Eigen::Vector3d {
    const double height = 1.0 + (s - 1.0) * r.x();
    return {r.x(), r.y(), 0.5 * (r.z() + 1.0) * height};
  });
}

TEST(CertifyJacobian, FloorSeparatesNumericallyDegenerateFromValid) {
  for (int order : {1, 2, 4}) {
    SCOPED_TRACE(order);
    const JacobianBounds thin = certify_jacobian(Shape::Prism, order, NodeSet::GLL, tapered_prism(order, 1e-4), 8, 1e-3);
    EXPECT_TRUE(thin.valid);
    EXPECT_NEAR(scaled_jacobian(thin), 1e-4, 1e-9);
    EXPECT_FALSE(acceptable(thin, 1e-3));
    EXPECT_TRUE(acceptable(thin, 1e-5));
    EXPECT_TRUE(acceptable(thin, 0.0));
    // Numerically degenerate: the scaled Jacobian of the tip prism of issue #10 was 8e-17.
    const JacobianBounds flat = certify_jacobian(Shape::Prism, order, NodeSet::GLL, tapered_prism(order, 1e-16), 8, 1e-5);
    EXPECT_FALSE(acceptable(flat, 1e-5));
  }
}

// A curved element whose Bezier bound is loose: the hex x = u + a u^3 / 3 (u in [-1, 1]) has
// det J proportional to 1 + a u^2, so min / max = 1 / (1 + a), but the Bezier coefficients of det J
// dip below its minimum; with a floor the certification refines until the bound clears it.
TEST(CertifyJacobian, FloorRefinesALooseBoundInsteadOfFailingAGoodElement) {
  const double a = 0.9;  // Bezier coefficients of 1 + a u^2 on [-1, 1]: 1 + a, 1 - a, 1 + a: positive but loose
  // On [-1, 1]: x = u + a u^3 / 3 gives dx/du = 1 + a u^2 >= 1, max 1 + a: scaled Jacobian 1 / 41.
  const Eigen::MatrixX3d nodes = mapped_nodes(Shape::Hexahedron, 3, NodeSet::GLL, [a](const Eigen::Vector3d& r) -> Eigen::Vector3d {
    return {r.x() + a * r.x() * r.x() * r.x() / 3.0, r.y(), r.z()};
  });
  const double truth = 1.0 / (1.0 + a);
  const JacobianBounds plain = certify_jacobian(Shape::Hexahedron, 3, NodeSet::GLL, nodes);
  ASSERT_TRUE(plain.valid);
  const double floor = 0.9 * truth;
  ASSERT_LT(scaled_jacobian(plain), floor);  // without the floor the bound alone would fail it
  const JacobianBounds refined = certify_jacobian(Shape::Hexahedron, 3, NodeSet::GLL, nodes, 8, floor);
  EXPECT_TRUE(acceptable(refined, floor));
  EXPECT_LE(scaled_jacobian(refined), truth * (1.0 + 1e-9));  // still a lower bound
  // Above the true value, the floor is proven unreachable.
  EXPECT_FALSE(acceptable(certify_jacobian(Shape::Hexahedron, 3, NodeSet::GLL, nodes, 8, 1.1 * truth), 1.1 * truth));
}

}  // namespace
}  // namespace semimesh::ho
