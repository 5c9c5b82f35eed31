// Orthonormal modal bases (Dubiner/Sherwin-Karniadakis type) of each element's space.
//
// Collapsed-coordinate bases are written with scaled Jacobi polynomials Q_n(X, t) = t^n P_n(X / t)
// (polynomials in X and t), so triangles, tets and prisms need no special case at collapsed vertices.
//   segment      L_i(x), L_i = Legendre
//   quad / hex   L_i(x) L_j(y) (L_k(z))
//   triangle     Q^{(0)}_i(2x+y-1, 1-y) P^{(2i+1,0)}_j(2y-1),  i+j <= P
//   tetrahedron  Q^{(0)}_i(2x+y+z-1, 1-y-z) Q^{(2i+1)}_j(2y+z-1, 1-z) P^{(2i+2j+2,0)}_k(2z-1), i+j+k <= P
//   prism        triangle(x, y) L_k(z)
//   pyramid      (Bergot, Cohen & Durufle 2010, "Higher-order finite elements for hybrid meshes using
//                new nodal pyramidal elements", their orthogonal basis of the space Gmsh also uses)
//                with t = 1-z, xi = x/t, eta = y/t, m = max(i, j):
//                  L_i(xi) L_j(eta) t^m P^{(2m+2,0)}_k(2z-1),  0 <= i, j <= P, 0 <= k <= P-m.
//                These are rational when min(i, j) >= 1, bounded on the pyramid, and tend to 0 at the
//                apex when m >= 1. At the apex itself (z = 1 exactly) values are these limits; the
//                gradient of a mode with m = 1 has no limit there (it depends on the direction of
//                approach), and we return its limit along the pyramid's axis (xi = eta = 0).
// Each function is divided by its L2 norm on the reference element of the collapsed coordinates, which
// keeps Vandermonde matrices well conditioned up to P = 10.
#include "modal_basis.hpp"

#include "polynomials.hpp"

#include <cmath>
#include <stdexcept>

namespace semimesh::ho::detail {

int modal_size(Shape shape, int order) { return num_nodes(shape, order); }

namespace {

// One point's modal values and gradients, filled in the same mode order.
struct PointModes {
  Eigen::VectorXd value, dx, dy, dz;
  int next = 0;
  explicit PointModes(int n) : value(Eigen::VectorXd::Zero(n)), dx(Eigen::VectorXd::Zero(n)),
                               dy(Eigen::VectorXd::Zero(n)), dz(Eigen::VectorXd::Zero(n)) {}
  void add(double scale, double v, double gx, double gy, double gz) {
    value[next] = scale * v;
    dx[next] = scale * gx;
    dy[next] = scale * gy;
    dz[next] = scale * gz;
    ++next;
  }
};

double legendre_scale(int i) { return std::sqrt((2.0 * i + 1.0) / 2.0); }

void segment_modes(int p, const Eigen::Vector3d& x, PointModes& out) {
  ScaledJacobi l;
  scaled_jacobi(p, 0.0, x.x(), 1.0, l);
  for (int i = 0; i <= p; ++i) out.add(legendre_scale(i), l.value[i], l.d_dX[i], 0, 0);
}

void quadrilateral_modes(int p, const Eigen::Vector3d& x, PointModes& out) {
  ScaledJacobi lx, ly;
  scaled_jacobi(p, 0.0, x.x(), 1.0, lx);
  scaled_jacobi(p, 0.0, x.y(), 1.0, ly);
  for (int j = 0; j <= p; ++j)
    for (int i = 0; i <= p; ++i)
      out.add(legendre_scale(i) * legendre_scale(j), lx.value[i] * ly.value[j], lx.d_dX[i] * ly.value[j],
              lx.value[i] * ly.d_dX[j], 0);
}

void hexahedron_modes(int p, const Eigen::Vector3d& x, PointModes& out) {
  ScaledJacobi lx, ly, lz;
  scaled_jacobi(p, 0.0, x.x(), 1.0, lx);
  scaled_jacobi(p, 0.0, x.y(), 1.0, ly);
  scaled_jacobi(p, 0.0, x.z(), 1.0, lz);
  for (int k = 0; k <= p; ++k)
    for (int j = 0; j <= p; ++j)
      for (int i = 0; i <= p; ++i)
        out.add(legendre_scale(i) * legendre_scale(j) * legendre_scale(k), lx.value[i] * ly.value[j] * lz.value[k],
                lx.d_dX[i] * ly.value[j] * lz.value[k], lx.value[i] * ly.d_dX[j] * lz.value[k],
                lx.value[i] * ly.value[j] * lz.d_dX[k]);
}

// Triangle modes times an optional z factor (value fz, derivative dfz) for prisms.
void triangle_modes(int p, const Eigen::Vector3d& x, double fz, double dfz, double z_scale, PointModes& out) {
  ScaledJacobi a, b;
  scaled_jacobi(p, 0.0, 2.0 * x.x() + x.y() - 1.0, 1.0 - x.y(), a);
  for (int i = 0; i <= p; ++i) {
    scaled_jacobi(p - i, 2.0 * i + 1.0, 2.0 * x.y() - 1.0, 1.0, b);
    for (int j = 0; i + j <= p; ++j) {
      const double scale = z_scale * std::sqrt((2.0 * i + 1.0) / 2.0 * (2.0 * i + 2.0 * j + 2.0) / 2.0);
      const double v = a.value[i] * b.value[j];
      const double gx = 2.0 * a.d_dX[i] * b.value[j];
      const double gy = (a.d_dX[i] - a.d_dt[i]) * b.value[j] + a.value[i] * 2.0 * b.d_dX[j];
      out.add(scale, v * fz, gx * fz, gy * fz, v * dfz);
    }
  }
}

void prism_modes(int p, const Eigen::Vector3d& x, PointModes& out) {
  ScaledJacobi lz;
  scaled_jacobi(p, 0.0, x.z(), 1.0, lz);
  for (int k = 0; k <= p; ++k) triangle_modes(p, x, lz.value[k], lz.d_dX[k], legendre_scale(k), out);
}

void tetrahedron_modes(int p, const Eigen::Vector3d& x, PointModes& out) {
  ScaledJacobi a, b, c;
  scaled_jacobi(p, 0.0, 2.0 * x.x() + x.y() + x.z() - 1.0, 1.0 - x.y() - x.z(), a);
  for (int i = 0; i <= p; ++i) {
    scaled_jacobi(p - i, 2.0 * i + 1.0, 2.0 * x.y() + x.z() - 1.0, 1.0 - x.z(), b);
    for (int j = 0; i + j <= p; ++j) {
      scaled_jacobi(p - i - j, 2.0 * i + 2.0 * j + 2.0, 2.0 * x.z() - 1.0, 1.0, c);
      for (int k = 0; i + j + k <= p; ++k) {
        const double scale =
            std::sqrt((2.0 * i + 1.0) / 2.0 * (2.0 * i + 2.0 * j + 2.0) / 2.0 * (2.0 * i + 2.0 * j + 2.0 * k + 3.0) / 2.0);
        const double A = a.value[i], B = b.value[j], C = c.value[k];
        const double A_y = a.d_dX[i] - a.d_dt[i];  // d/dy and d/dz of A (X and t both move)
        out.add(scale, A * B * C, 2.0 * a.d_dX[i] * B * C, A_y * B * C + A * 2.0 * b.d_dX[j] * C,
                A_y * B * C + A * (b.d_dX[j] - b.d_dt[j]) * C + A * B * 2.0 * c.d_dX[k]);
      }
    }
  }
}

void pyramid_modes(int p, const Eigen::Vector3d& x, PointModes& out) {
  const double t = 1.0 - x.z();
  const bool apex = t == 0.0;
  const double xi = apex ? 0.0 : x.x() / t;  // apex: the limit along the axis, see the file comment
  const double eta = apex ? 0.0 : x.y() / t;
  ScaledJacobi li, lj, c;
  scaled_jacobi(p, 0.0, xi, 1.0, li);
  scaled_jacobi(p, 0.0, eta, 1.0, lj);
  for (int i = 0; i <= p; ++i) {
    for (int j = 0; j <= p; ++j) {
      const int m = std::max(i, j);
      scaled_jacobi(p - m, 2.0 * m + 2.0, 2.0 * x.z() - 1.0, 1.0, c);
      // R = t^m L_i(xi) L_j(eta); its derivatives all carry t^(m-1).
      const double t_m = std::pow(t, m);
      const double t_m1 = m == 0 ? 0.0 : std::pow(t, m - 1);
      const double Li = li.value[i], Lj = lj.value[j], dLi = li.d_dX[i], dLj = lj.d_dX[j];
      const double R = t_m * Li * Lj;
      const double R_x = t_m1 * dLi * Lj;
      const double R_y = t_m1 * Li * dLj;
      const double R_z = t_m1 * (-m * Li * Lj + xi * dLi * Lj + eta * Li * dLj);
      for (int k = 0; k <= p - m; ++k) {
        const double scale = std::sqrt((2.0 * i + 1.0) * (2.0 * j + 1.0) * (2.0 * k + 2.0 * m + 3.0) / 4.0);
        const double C = c.value[k];
        out.add(scale, R * C, R_x * C, R_y * C, R_z * C + R * 2.0 * c.d_dX[k]);
      }
    }
  }
}

}  // namespace

Eigen::MatrixXd modal_values(Shape shape, int order, const Eigen::MatrixX3d& points,
                             std::array<Eigen::MatrixXd, 3>* gradients) {
  const int n = modal_size(shape, order);
  const Eigen::Index np = points.rows();
  Eigen::MatrixXd values(np, n);
  if (gradients)
    for (auto& g : *gradients) g.resize(np, n);
  for (Eigen::Index q = 0; q < np; ++q) {
    const Eigen::Vector3d x = points.row(q).transpose();
    PointModes modes(n);
    switch (shape) {
      case Shape::Segment: segment_modes(order, x, modes); break;
      case Shape::Triangle: triangle_modes(order, x, 1.0, 0.0, 1.0, modes); break;
      case Shape::Quadrilateral: quadrilateral_modes(order, x, modes); break;
      case Shape::Tetrahedron: tetrahedron_modes(order, x, modes); break;
      case Shape::Pyramid: pyramid_modes(order, x, modes); break;
      case Shape::Prism: prism_modes(order, x, modes); break;
      case Shape::Hexahedron: hexahedron_modes(order, x, modes); break;
    }
    if (modes.next != n) {
      throw std::logic_error("modal_values: " + to_string(shape) + " of order " + std::to_string(order) + " built " +
                             std::to_string(modes.next) + " modes, expected " + std::to_string(n));
    }
    values.row(q) = modes.value.transpose();
    if (gradients) {
      (*gradients)[0].row(q) = modes.dx.transpose();
      (*gradients)[1].row(q) = modes.dy.transpose();
      (*gradients)[2].row(q) = modes.dz.transpose();
    }
  }
  return values;
}

}  // namespace semimesh::ho::detail
