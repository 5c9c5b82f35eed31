#include "harmonic_extension.hpp"

#include "semimesh/ho/curving/extend_inward.hpp"

#include "semimesh/ho/quadrature.hpp"
#include "semimesh/ho/basis.hpp"
#include "semimesh/mesh/node_layout.hpp"

#include <Eigen/Cholesky>

#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>

namespace semimesh::ho::detail {
namespace {

HarmonicExtension build_extension(Shape shape, int order, NodeSet set, double lateral) {
  HarmonicExtension h;
  const mesh::NodeLayout& layout = mesh::node_layout(shape, order);
  const auto inside = dimension(shape) == 3 ? mesh::NodeSlot::Interior : mesh::NodeSlot::Face;
  for (std::size_t i = 0; i < layout.slots.size(); ++i)
    (layout.slots[i].kind == inside ? h.interior : h.boundary).push_back(static_cast<int>(i));
  if (h.interior.empty()) return h;

  // Stiffness K = sum_q w_q sum_c dphi/dx_c dphi/dx_c; gradients of degree <= order per direction
  // (plus the collapse factors), so order + 3 points per direction integrate it exactly.
  const LagrangeBasis basis(shape, order, set);
  const Quadrature q = reference_quadrature(shape, order + 3);
  const auto grads = basis.gradients(q.points);
  const int n = basis.size();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (int c = 0; c < dimension(shape); ++c)
    K += (c < 2 ? lateral : 1.0) * grads[c].transpose() * q.weights.asDiagonal() * grads[c];

  const int ni = static_cast<int>(h.interior.size()), nb = static_cast<int>(h.boundary.size());
  Eigen::MatrixXd Kii(ni, ni), Kib(ni, nb);
  for (int i = 0; i < ni; ++i) {
    for (int j = 0; j < ni; ++j) Kii(i, j) = K(h.interior[i], h.interior[j]);
    for (int j = 0; j < nb; ++j) Kib(i, j) = K(h.interior[i], h.boundary[j]);
  }
  h.extension = -Kii.ldlt().solve(Kib);
  return h;
}

}  // namespace

namespace {

const HarmonicExtension& cached_extension(Shape shape, int order, NodeSet set, double lateral) {
  static std::mutex mutex;
  static std::map<std::tuple<Shape, int, NodeSet, double>, std::unique_ptr<HarmonicExtension>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto& slot = cache[{shape, order, set, lateral}];
  if (!slot) slot = std::make_unique<HarmonicExtension>(build_extension(shape, order, set, lateral));
  return *slot;
}

}  // namespace

const HarmonicExtension& harmonic_extension(Shape shape, int order, NodeSet set) {
  return cached_extension(shape, order, set, 1.0);
}

const HarmonicExtension& prism_extension(int order, NodeSet set, double lateral) {
  return cached_extension(Shape::Prism, order, set, lateral);
}

double prism_lateral_weight(const Eigen::MatrixXd& x) {
  constexpr int kSteps = 5;  // the thinnest weight: 4^-5
  double delta = 0.0, length = 0.0;
  for (int k = 0; k < 3; ++k) {
    delta += (x.row(k + 3) - x.row(k)).norm();
    length += (x.row((k + 1) % 3) - x.row(k)).norm() + (x.row(3 + (k + 1) % 3) - x.row(3 + k)).norm();
  }
  delta /= 3.0;
  length /= 6.0;
  if (!(delta > 0.0) || !(length > 0.0)) return 1.0;
  const double weight = std::pow(delta / (2.0 * length), 2);
  int step = 0;
  while (step < kSteps && weight < std::pow(4.0, -step)) ++step;
  return std::pow(4.0, -step);
}

void extend_harmonically(const HarmonicExtension& h, Eigen::MatrixXd& values) {
  if (h.interior.empty()) return;
  Eigen::MatrixXd boundary(h.boundary.size(), values.cols());
  for (std::size_t j = 0; j < h.boundary.size(); ++j) boundary.row(j) = values.row(h.boundary[j]);
  const Eigen::MatrixXd inner = h.extension * boundary;
  for (std::size_t i = 0; i < h.interior.size(); ++i) values.row(h.interior[i]) = inner.row(i);
}

}  // namespace semimesh::ho::detail

namespace semimesh::ho {

void extend_inward(Shape shape, int order, NodeSet set, Eigen::MatrixXd& x) {
  detail::extend_harmonically(detail::harmonic_extension(shape, order, set), x);
}

}  // namespace semimesh::ho
