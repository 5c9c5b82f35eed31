#include "semimesh/pipeline/pyfr_limits.hpp"

#include "semimesh/ho/splitting/pyramid_columns.hpp"

#include <fmt/format.h>

namespace semimesh::pipeline {

std::size_t pyramids_pyfr_refuses(const mesh::Mesh& mesh) {
  std::size_t count = 0;
  for (std::size_t e = 0; e < mesh.elements().size(); ++e)
    count += mesh.elements()[e].shape == ho::Shape::Pyramid &&
             !ho::has_parallelogram_base(mesh, e, kPyfrParallelogramTolerance);
  return count;
}

std::vector<std::string> pyfr_refusals(const mesh::Mesh& mesh) {
  std::vector<std::string> reasons;
  if (const std::size_t pyramids = pyramids_pyfr_refuses(mesh); pyramids > 0)
    reasons.push_back(fmt::format(
        "PyFR cannot import this mesh: {} pyramid(s) stand on quads that are not parallelograms (PyFR's "
        "importer requires parallelogram bases): for PyFR use the O- or C-type near field (no pyramids); "
        "docs/solvers.md says what output.target = \"pyfr\" can split", pyramids));
  if (mesh.order() > 4)
    reasons.push_back(fmt::format("PyFR cannot import this mesh: order {} (PyFR's importer takes orders 1 to 4)",
                                  mesh.order()));
  return reasons;
}

}  // namespace semimesh::pipeline
