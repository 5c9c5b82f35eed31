#include "semimesh/ho/curving/geometric_error.hpp"

#include "curving/cad_classification.hpp"
#include "semimesh/ho/basis.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

namespace semimesh::ho {
namespace {

// Reference points of a (samples_per_edge)-interval lattice on a triangle or quadrilateral.
Eigen::MatrixX3d sample_points(Shape shape, int n) {
  std::vector<Eigen::RowVector3d> pts;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      if (shape == Shape::Triangle && i + j > n) continue;
      if (shape == Shape::Triangle)
        pts.emplace_back(double(i) / n, double(j) / n, 0.0);
      else
        pts.emplace_back(2.0 * i / n - 1.0, 2.0 * j / n - 1.0, 0.0);
    }
  Eigen::MatrixX3d out(pts.size(), 3);
  for (std::size_t k = 0; k < pts.size(); ++k) out.row(k) = pts[k];
  return out;
}

}  // namespace

GeometricError geometric_error(const mesh::Mesh& mesh, const cad::Model& model, double reference_length,
                               int samples_per_edge, const std::vector<int>& surfaces) {
  if (!(reference_length > 0.0))
    throw std::invalid_argument("geometric_error: reference_length must be > 0");
  if (samples_per_edge < 1) throw std::invalid_argument("geometric_error: samples_per_edge must be >= 1");
  GeometricError err;
  double sum_squares = 0.0;
  // The basis at the sample points, once per face shape (the same matrix for every face).
  std::map<Shape, Eigen::MatrixXd> phi_of;
  const auto sample_basis = [&](Shape shape) -> const Eigen::MatrixXd& {
    auto it = phi_of.find(shape);
    if (it == phi_of.end())
      it = phi_of.emplace(shape, LagrangeBasis(shape, mesh.order(), mesh.node_set()).values(sample_points(shape, samples_per_edge))).first;
    return it->second;
  };
  for (std::size_t b = 0; b < mesh.boundary_faces().size(); ++b) {
    const mesh::BoundaryFace& bf = mesh.boundary_faces()[b];
    const int nv = num_vertices(bf.shape);
    std::vector<mesh::CadAttachment> corners;
    for (int v = 0; v < nv; ++v) corners.push_back(mesh.cad_attachment(bf.vertices[v]));
    const std::vector<mesh::NodeId> ids = mesh.boundary_face_nodes(b);
    Eigen::MatrixX3d X(ids.size(), 3);
    for (std::size_t j = 0; j < ids.size(); ++j) X.row(j) = mesh.node(ids[j]).transpose();
    const detail::CadPlace place = detail::classify(model, corners, false, X.colwise().mean().transpose());
    if (place.kind != detail::CadPlace::Surface) continue;
    if (!surfaces.empty() && std::find(surfaces.begin(), surfaces.end(), place.id) == surfaces.end()) continue;

    const cad::Surface& surface = model.surface(place.id);
    Eigen::MatrixX2d uv(ids.size(), 2);
    for (std::size_t j = 0; j < ids.size(); ++j)
      uv.row(j) = detail::surface_parameter(model, place.id, mesh.cad_attachment(ids[j]), X.row(j).transpose())
                      .transpose();
    detail::continuous_parameters(surface, uv, static_cast<int>(uv.rows()), nv);
    const Eigen::MatrixXd& phi = sample_basis(bf.shape);
    const Eigen::MatrixX3d points = phi * X;
    const Eigen::MatrixX2d guesses = phi * uv;
    for (Eigen::Index k = 0; k < points.rows(); ++k) {
      // Interpolated across a seam cut, a guess may lie a little outside the parameter box.
      const cad::Vec2 guess = detail::into_box(surface, guesses.row(k).transpose());
      const double d = surface.project_near(points.row(k).transpose(), guess).distance / reference_length;
      err.max_rel = std::max(err.max_rel, d);
      sum_squares += d * d;
      ++err.samples;
    }
  }
  if (err.samples > 0) err.rms_rel = std::sqrt(sum_squares / err.samples);
  return err;
}

}  // namespace semimesh::ho
