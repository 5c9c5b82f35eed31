#include "semimesh/checks/validity.hpp"

#include "semimesh/ho/mesh_validity.hpp"

#include <algorithm>

namespace semimesh::checks {

ValidityResult check_validity(const mesh::Mesh& mesh, std::size_t max_listed, double min_scaled_jacobian,
                              const ProgressCallback& progress, const std::vector<ho::InheritedBounds>* inherited) {
  const ho::MeshValidity certified = ho::certify_mesh(mesh, 8, min_scaled_jacobian, progress, inherited);
  ValidityResult result;
  result.elements = mesh.elements().size();
  result.floor = min_scaled_jacobian;
  result.invalid = certified.invalid;
  result.inherited = certified.inherited;
  result.min_scaled_jacobian = certified.min_scaled_jacobian;
  result.median_scaled_jacobian = certified.median_scaled_jacobian;
  result.scaled_jacobians.reserve(certified.bounds.size());
  result.integrals.reserve(certified.bounds.size());
  for (const ho::JacobianBounds& b : certified.bounds) {
    result.scaled_jacobians.push_back(ho::scaled_jacobian(b));
    result.integrals.push_back(b.integral);
  }
  for (std::size_t i = 0; i < certified.invalid_elements.size(); ++i) {
    const std::size_t e = certified.invalid_elements[i];
    InvalidElement bad;
    bad.element = e;
    bad.shape = mesh.elements()[e].shape;
    bad.centroid = certified.invalid_centroids[i];
    bad.scaled_jacobian = ho::scaled_jacobian(certified.bounds[e]);
    bad.proven = certified.bounds[e].proven;
    bad.below_floor = certified.bounds[e].valid;
    result.worst.push_back(bad);
  }
  std::stable_sort(result.worst.begin(), result.worst.end(),
                   [](const InvalidElement& a, const InvalidElement& b) { return a.scaled_jacobian < b.scaled_jacobian; });
  if (result.worst.size() > max_listed) result.worst.resize(max_listed);
  for (std::size_t e = 0; e < mesh.elements().size(); ++e) {
    const std::string& region = mesh.region_names()[mesh.elements()[e].region];
    const double scaled = ho::scaled_jacobian(certified.bounds[e]);
    const auto [it, added] = result.min_scaled_jacobian_by_region.try_emplace(region, scaled);
    if (!added) it->second = std::min(it->second, scaled);
  }
  return result;
}

}  // namespace semimesh::checks
