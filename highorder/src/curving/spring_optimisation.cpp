#include "spring_optimisation.hpp"
#include "per_element_type.hpp"

#include "splitting/reference_lattice.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>
#include <utility>
#include <vector>

namespace semimesh::ho::detail {
namespace {

// The free nodes of a lattice and, for each, its lattice neighbours with the spring weights.
struct SpringNetwork {
  std::vector<int> free;  // canonical indices
  std::vector<std::vector<std::pair<int, double>>> neighbours;  // [free] (canonical index, weight)
};

bool on_lattice_boundary(Shape shape, const LatticePoint& l, int order) {
  switch (shape) {
    case Shape::Segment: return l[0] == 0 || l[0] == order;
    case Shape::Triangle: return l[0] == 0 || l[1] == 0 || l[0] + l[1] == order;
    default: return l[0] == 0 || l[1] == 0 || l[0] == order || l[1] == order;
  }
}

// Weights w_n: the smallest-norm solution of sum w_n r_n = r_j, sum w_n = 1 (r: reference positions
// of the node set): forces w_n (x_n - x_j) balance exactly when x is an affine image of r, so an
// affine face keeps the node set's own spacing.
SpringNetwork build_network(Shape shape, int order, NodeSet set) {
  static const std::vector<std::array<int, 2>> segment{{1, 0}, {-1, 0}};
  static const std::vector<std::array<int, 2>> quad{{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  static const std::vector<std::array<int, 2>> triangle{{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, -1}, {-1, 1}};
  const auto& offsets = shape == Shape::Segment ? segment : shape == Shape::Triangle ? triangle : quad;
  const int dim = dimension(shape);
  const std::vector<LatticePoint> lattice = lattice_points(shape, order);
  const std::map<LatticePoint, int> index = lattice_index(shape, order);
  const Eigen::MatrixX3d r = reference_nodes(shape, order, set);

  SpringNetwork net;
  for (std::size_t j = 0; j < lattice.size(); ++j) {
    if (on_lattice_boundary(shape, lattice[j], order)) continue;
    std::vector<int> nb;
    for (const auto& o : offsets) nb.push_back(index.at({lattice[j][0] + o[0], lattice[j][1] + o[1], 0}));
    const int m = static_cast<int>(nb.size());
    Eigen::MatrixXd A(dim + 1, m);
    Eigen::VectorXd b(dim + 1);
    for (int k = 0; k < m; ++k) {
      for (int c = 0; c < dim; ++c) A(c, k) = r(nb[k], c);
      A(dim, k) = 1.0;
    }
    for (int c = 0; c < dim; ++c) b(c) = r(j, c);
    b(dim) = 1.0;
    const Eigen::VectorXd w = A.transpose() * (A * A.transpose()).lu().solve(b);
    net.free.push_back(static_cast<int>(j));
    net.neighbours.emplace_back();
    for (int k = 0; k < m; ++k) net.neighbours.back().emplace_back(nb[k], w(k));
  }
  return net;
}

const SpringNetwork& spring_network(Shape shape, int order, NodeSet set) {
  static PerElementType<SpringNetwork> table;
  return table.get(shape, order, set, build_network);
}

}  // namespace

bool optimise_on_surface(const cad::Surface& surface, Shape shape, int order, NodeSet set, Eigen::MatrixX2d& uv,
                         Eigen::MatrixX3d& x, int iterations, double tolerance) {
  const SpringNetwork& net = spring_network(shape, order, set);
  const int m = static_cast<int>(net.free.size());
  if (m == 0) return true;
  std::vector<int> slot(uv.rows(), -1);  // canonical index -> free index
  for (int k = 0; k < m; ++k) slot[net.free[k]] = k;
  const auto box = surface.bounds();

  std::vector<Eigen::Matrix<double, 3, 2>> J(m);
  // Places the free nodes at S(uv) (and their tangents in J); returns the squared force imbalance.
  const auto evaluate = [&](const Eigen::MatrixX2d& at, Eigen::MatrixX3d& xs) {
    for (int k = 0; k < m; ++k) {
      const cad::SurfaceDerivatives d = surface.derivatives(at.row(net.free[k]).transpose());
      xs.row(net.free[k]) = d.p.transpose();
      J[k].col(0) = d.du;
      J[k].col(1) = d.dv;
    }
    double energy = 0.0;
    for (int k = 0; k < m; ++k) {
      Eigen::RowVector3d f = xs.row(net.free[k]);
      for (const auto& [n, w] : net.neighbours[k]) f -= w * xs.row(n);
      energy += f.squaredNorm();
    }
    return energy;
  };

  const Eigen::MatrixX2d uv_start = uv;
  double energy = evaluate(uv, x);
  const Eigen::MatrixX3d x_start = x;
  bool converged = false;
  for (int it = 0; it < iterations && !converged; ++it) {
    // Gauss-Newton on the linearised imbalance R_k = x_k - sum_n w_kn x_n, x_n + J_n du_n.
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3 * m, 2 * m);
    Eigen::VectorXd R(3 * m);
    for (int k = 0; k < m; ++k) {
      Eigen::RowVector3d f = x.row(net.free[k]);
      A.block<3, 2>(3 * k, 2 * k) += J[k];
      for (const auto& [n, w] : net.neighbours[k]) {
        f -= w * x.row(n);
        if (slot[n] >= 0) A.block<3, 2>(3 * k, 2 * slot[n]) -= w * J[slot[n]];
      }
      R.segment<3>(3 * k) = f.transpose();
    }
    Eigen::MatrixXd H = A.transpose() * A;
    H.diagonal().array() += 1e-14 * H.diagonal().maxCoeff();
    const Eigen::VectorXd step = -H.ldlt().solve(A.transpose() * R);
    std::vector<Eigen::Matrix<double, 3, 2>> J_old = J;
    double alpha = 1.0;
    bool accepted = false;
    Eigen::MatrixX2d uv_try = uv;
    Eigen::MatrixX3d x_try = x;
    for (int halving = 0; halving < 30 && !accepted; ++halving, alpha *= 0.5) {
      for (int k = 0; k < m; ++k) {
        const int i = net.free[k];
        uv_try(i, 0) = box[0].clamp(uv(i, 0) + alpha * step(2 * k));
        uv_try(i, 1) = box[1].clamp(uv(i, 1) + alpha * step(2 * k + 1));
      }
      const double e = evaluate(uv_try, x_try);
      accepted = e <= energy * (1.0 + 1e-12) + 1e-300;
      if (accepted) energy = e;
    }
    if (!accepted) {
      // No descent left: converged if the full step was already below the tolerance.
      J = J_old;
      double predicted = 0.0;
      for (int k = 0; k < m; ++k) predicted = std::max(predicted, (J[k] * step.segment<2>(2 * k)).norm());
      converged = predicted < tolerance;
      break;
    }
    double move = 0.0;
    for (int k = 0; k < m; ++k) move = std::max(move, (x_try.row(net.free[k]) - x.row(net.free[k])).norm());
    uv = uv_try;
    x = x_try;
    converged = move < tolerance;
  }
  for (int k = 0; k < m && converged; ++k) converged = surface.contains(uv.row(net.free[k]).transpose());
  if (!converged) {
    uv = uv_start;
    x = x_start;
  }
  return converged;
}

}  // namespace semimesh::ho::detail
