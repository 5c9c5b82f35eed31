// Lagrange values of the product shapes (quadrilateral, hexahedron, prism) through their factors
// against the modal reference, at the work of one split element with a varying layer ratio (the
// H-type's wake hexes): N = 5 pieces x every node of the element, GLL nodes. Prints a table; the
// figures depend on the machine and on its load.
#include "semimesh/ho/basis.hpp"

#include <chrono>
#include <cstdio>
#include <random>

namespace {

using semimesh::ho::LagrangeBasis;
using semimesh::ho::NodeSet;
using semimesh::ho::Shape;

template <typename F>
double microseconds_per_call(F&& f) {
  int calls = 0;
  const auto start = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  do {
    f();
    ++calls;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } while (elapsed < 0.5);
  return 1e6 * elapsed / calls;
}

}  // namespace

int main() {
  std::printf("%-14s %2s %8s | %14s %14s %8s\n", "shape", "P", "points", "product (us)", "modal (us)", "speed-up");
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (Shape shape : {Shape::Quadrilateral, Shape::Prism, Shape::Hexahedron})
    for (int p : {2, 4, 6}) {
      const LagrangeBasis basis(shape, p, NodeSet::GLL);
      Eigen::MatrixX3d points(5 * basis.size(), 3);
      for (Eigen::Index i = 0; i < points.rows(); ++i) {
        const double a = u(rng), b = u(rng), c = u(rng);
        if (shape == Shape::Prism) points.row(i) << a * (1 - b), b, 2 * c - 1;
        else points.row(i) << 2 * a - 1, 2 * b - 1, shape == Shape::Hexahedron ? 2 * c - 1 : 0.0;
      }
      double sink = 0.0;
      const double fast = microseconds_per_call([&] { sink += basis.values(points)(0, 0); });
      const double slow = microseconds_per_call([&] { sink += basis.values_by_modes(points)(0, 0); });
      std::printf("%-14s %2d %8ld | %14.1f %14.1f %7.1fx%s\n", semimesh::ho::to_string(shape).c_str(), p,
                  static_cast<long>(points.rows()), fast, slow, slow / fast, sink == 0.123 ? " " : "");
    }
}
