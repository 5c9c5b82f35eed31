#include "semimesh/checks/validity.hpp"

#include "semimesh/ho/quality.hpp"

#include <algorithm>
#include <thread>

namespace semimesh::checks {

ValidityResult check_validity(const mesh::Mesh& mesh, int threads, std::size_t max_listed,
                              double min_scaled_jacobian) {
  const std::size_t n = mesh.elements().size();
  std::vector<double> scaled(n);
  std::vector<char> valid(n), proven(n), acceptable(n);

  // Strided, not blocked: elements of one kind (curved prisms, straight tets) come in long runs of
  // very different cost, so contiguous blocks would leave one worker with most of the work.
  const std::size_t workers =
      std::max<std::size_t>(1, std::min<std::size_t>(threads > 0 ? threads : std::thread::hardware_concurrency(), n / 1000 + 1));
  auto certify_stride = [&](std::size_t first) {
    for (std::size_t e = first; e < n; e += workers) {
      const ho::ElementQuality q =
          ho::element_quality(mesh.elements()[e].shape, mesh.order(), mesh.node_set(), mesh.element_coordinates(e),
                              8, min_scaled_jacobian);
      scaled[e] = q.scaled_jacobian;
      acceptable[e] = ho::acceptable(q.bounds, min_scaled_jacobian);
      valid[e] = q.bounds.valid;
      proven[e] = q.bounds.proven;
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(certify_stride, w);
  certify_stride(0);
  for (std::thread& t : pool) t.join();

  ValidityResult result;
  result.elements = n;
  result.floor = min_scaled_jacobian;
  for (std::size_t e = 0; e < n; ++e) {
    if (acceptable[e]) continue;
    ++result.invalid;
    InvalidElement bad;
    bad.element = e;
    bad.shape = mesh.elements()[e].shape;
    const int nv = ho::num_vertices(bad.shape);
    for (int v = 0; v < nv; ++v) bad.centroid += mesh.node(mesh.elements()[e].vertices[v]);
    bad.centroid /= nv;
    bad.scaled_jacobian = scaled[e];
    bad.proven = proven[e];
    bad.below_floor = valid[e];
    result.worst.push_back(bad);
  }
  std::stable_sort(result.worst.begin(), result.worst.end(),
                   [](const InvalidElement& a, const InvalidElement& b) { return a.scaled_jacobian < b.scaled_jacobian; });
  if (result.worst.size() > max_listed) result.worst.resize(max_listed);

  if (n > 0) {
    result.min_scaled_jacobian = *std::min_element(scaled.begin(), scaled.end());
    std::nth_element(scaled.begin(), scaled.begin() + n / 2, scaled.end());
    result.median_scaled_jacobian = scaled[n / 2];
  }
  return result;
}

}  // namespace semimesh::checks
