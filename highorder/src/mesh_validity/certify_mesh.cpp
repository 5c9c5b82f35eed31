#include "semimesh/ho/mesh_validity.hpp"

#include "parallel_for.hpp"
#include "semimesh/ho/quality.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace semimesh::ho {

MeshValidity certify_mesh(const mesh::Mesh& mesh, int max_depth, double min_scaled_jacobian,
                          const ProgressCallback& progress) {
  if (max_depth < 0)
    throw std::invalid_argument("certify_mesh: max_depth = " + std::to_string(max_depth) + " must be >= 0");
  const std::size_t n = mesh.elements().size();
  for (std::size_t e = 0; e < n; ++e)
    if (dimension(mesh.elements()[e].shape) != 3)
      throw std::invalid_argument("certify_mesh: element " + std::to_string(e) + " is a " +
                                  to_string(mesh.elements()[e].shape) + "; only 3D elements can be certified");

  MeshValidity out;
  out.bounds.resize(n);
  detail::parallel_for(n, true, [&](std::size_t e) {
    out.bounds[e] = certify_jacobian(mesh.elements()[e].shape, mesh.order(), mesh.node_set(),
                                     mesh.element_coordinates(e), max_depth, min_scaled_jacobian);
  }, progress, "elements");

  std::vector<double> scaled(n);
  for (std::size_t e = 0; e < n; ++e) {
    const JacobianBounds& b = out.bounds[e];
    scaled[e] = scaled_jacobian(b);
    if (acceptable(b, min_scaled_jacobian)) continue;
    ++out.invalid;
    if (!b.proven) ++out.unproven;
    const mesh::Element& el = mesh.elements()[e];
    const int nv = num_vertices(el.shape);
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int v = 0; v < nv; ++v) centroid += mesh.node(el.vertices[v]);
    out.invalid_elements.push_back(e);
    out.invalid_centroids.push_back(centroid / nv);
  }
  if (n > 0) {
    out.min_scaled_jacobian = *std::min_element(scaled.begin(), scaled.end());
    const auto middle = scaled.begin() + static_cast<long>((n - 1) / 2);
    std::nth_element(scaled.begin(), middle, scaled.end());
    out.median_scaled_jacobian = *middle;
  }
  return out;
}

}  // namespace semimesh::ho
