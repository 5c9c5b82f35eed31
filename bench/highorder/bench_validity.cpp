// Certification throughput: certify_jacobian on valid curved elements, per shape at orders 2 and 4.
// Prints a table; the figures depend on the machine and on its load.
#include "semimesh/ho/quality.hpp"
#include "semimesh/ho/validity.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace {

using semimesh::ho::NodeSet;
using semimesh::ho::Shape;

/// A valid curved element: the reference nodes moved by a smooth bump with random phases.
Eigen::MatrixX3d curved_element(Shape shape, int order, std::mt19937& rng) {
  std::uniform_real_distribution<double> phase(0.0, 6.283);
  const double p0 = phase(rng), p1 = phase(rng), p2 = phase(rng);
  Eigen::MatrixX3d nodes = semimesh::ho::reference_nodes(shape, order);
  for (int i = 0; i < nodes.rows(); ++i) {
    const Eigen::Vector3d x = nodes.row(i).transpose();
    nodes(i, 0) = x[0] + 0.04 * std::sin(2.0 * x[1] + p0);
    nodes(i, 1) = x[1] + 0.04 * std::sin(2.0 * x[2] + p1);
    nodes(i, 2) = x[2] + 0.06 * std::sin(2.0 * x[0] + p2);
  }
  return nodes;
}

}  // namespace

int main() {
  using Clock = std::chrono::steady_clock;
  const Shape shapes[] = {Shape::Tetrahedron, Shape::Pyramid, Shape::Prism, Shape::Hexahedron};
  std::printf("%-12s %5s %8s %12s %10s %10s %12s\n", "shape", "order", "elements", "elements/s", "us/elem",
              "valid", "min scaledJ");
  for (Shape shape : shapes)
    for (int order : {2, 4}) {
      std::mt19937 rng(7);
      std::vector<Eigen::MatrixX3d> elements;
      for (int e = 0; e < 256; ++e) elements.push_back(curved_element(shape, order, rng));
      semimesh::ho::certify_jacobian(shape, order, NodeSet::Equispaced, elements[0]);  // builds the caches
      long certified = 0, valid = 0;
      double worst_quality = 1.0;
      const Clock::time_point start = Clock::now();
      double seconds = 0.0;
      while (seconds < 0.5) {
        for (const Eigen::MatrixX3d& nodes : elements) {
          const semimesh::ho::ElementQuality q = semimesh::ho::element_quality(shape, order, NodeSet::Equispaced, nodes);
          ++certified;
          valid += q.bounds.valid ? 1 : 0;
          worst_quality = std::min(worst_quality, q.scaled_jacobian);
        }
        seconds = std::chrono::duration<double>(Clock::now() - start).count();
      }
      std::printf("%-12s %5d %8ld %12.0f %10.1f %9.1f%% %12.3f\n", semimesh::ho::to_string(shape).c_str(), order,
                  certified, certified / seconds, 1e6 * seconds / certified, 100.0 * valid / certified, worst_quality);
    }
  return 0;
}
