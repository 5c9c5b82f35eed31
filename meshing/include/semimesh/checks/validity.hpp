// The run's validity check: ho::certify_mesh (Bezier bounds of det J with subdivision, the one
// whole-mesh certification) summarised with the worst invalid elements for the user.
#pragma once

#include "semimesh/ho/mesh_validity.hpp"
#include "semimesh/mesh/mesh.hpp"
#include "semimesh/progress.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace semimesh::checks {

struct InvalidElement {
  std::size_t element = 0;
  ho::Shape shape = ho::Shape::Tetrahedron;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< mean of the vertices
  double scaled_jacobian = 0.0;
  bool proven = true;  ///< false: not proven invalid, only not proven valid
  bool below_floor = false;  ///< proven valid, but its scaled Jacobian is below the floor
};

struct ValidityResult {
  std::size_t elements = 0;
  std::size_t invalid = 0;                   ///< not proven valid (inverted or undecided) or below the floor
  double floor = 0.0;                        ///< the min_scaled_jacobian the check used
  double min_scaled_jacobian = 1.0;
  double median_scaled_jacobian = 1.0;
  std::map<std::string, double> min_scaled_jacobian_by_region;  ///< region name -> its smallest
  std::vector<InvalidElement> worst;         ///< the invalid elements, worst first, at most max_listed
  std::vector<double> scaled_jacobians;      ///< [elements] certified scaled Jacobian of each element
  std::vector<double> integrals;             ///< [elements] its volume where the certification had it
                                             ///< whole (ho::JacobianBounds::integral), NaN elsewhere:
                                             ///< what mesh_volume takes as known
  std::size_t inherited = 0;                 ///< elements whose bounds came from their coarse element
  bool ok() const { return invalid == 0; }
};

/// Certifies every element (ho::certify_mesh: OpenMP threads, the verdict independent of their
/// count); min and median scaled Jacobian as certify_mesh defines them. An element counts as invalid
/// unless proven valid with a scaled Jacobian >= min_scaled_jacobian (ho::acceptable). `progress` as
/// certify_mesh's; `inherited` as certify_mesh's (split pieces' bounds from their coarse element).
ValidityResult check_validity(const mesh::Mesh& mesh, std::size_t max_listed = 100, double min_scaled_jacobian = 0.0,
                              const ProgressCallback& progress = {},
                              const std::vector<ho::InheritedBounds>* inherited = nullptr);

}  // namespace semimesh::checks
