#include "semimesh/pipeline/pyfr_limits.hpp"

#include <fmt/format.h>

namespace semimesh::pipeline {

std::size_t pyramids_pyfr_refuses(const mesh::Mesh& mesh) {
  constexpr double kPyfrTolerance = 1e-10;  // absolute, per coordinate (as tests/io/pyfr_rules.py)
  std::size_t count = 0;
  for (const mesh::Element& e : mesh.elements()) {
    if (e.shape != ho::Shape::Pyramid) continue;
    const auto x = [&](int k) { return mesh.node(e.vertices[k]); };
    const Eigen::Vector3d miss = x(0) + x(2) - x(1) - x(3);
    count += miss.cwiseAbs().maxCoeff() > kPyfrTolerance;
  }
  return count;
}

std::vector<std::string> pyfr_refusals(const mesh::Mesh& mesh) {
  std::vector<std::string> reasons;
  if (const std::size_t pyramids = pyramids_pyfr_refuses(mesh); pyramids > 0)
    reasons.push_back(fmt::format(
        "PyFR cannot import this mesh: {} pyramid(s) stand on quads that are not parallelograms (PyFR's "
        "importer requires parallelogram bases; the O- and C-type near fields have no pyramids)", pyramids));
  if (mesh.order() > 4)
    reasons.push_back(fmt::format("PyFR cannot import this mesh: order {} (PyFR's importer takes orders 1 to 4)",
                                  mesh.order()));
  return reasons;
}

}  // namespace semimesh::pipeline
