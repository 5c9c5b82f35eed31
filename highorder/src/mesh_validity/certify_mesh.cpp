#include "semimesh/ho/mesh_validity.hpp"

#include "parallel_for.hpp"
#include "semimesh/ho/quality.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>

namespace semimesh::ho {
namespace {

// An inherited certificate stands for the element's own when it is the same element (fingerprint)
// and certify_jacobian would have stopped at its first expansion: above the floor (and so valid).
bool usable(const InheritedBounds& inherited, const mesh::Mesh& mesh, double floor) {
  const JacobianBounds& b = inherited.bounds;
  if (!b.valid || !(b.min_lower > floor * b.max_upper)) return false;
  return element_fingerprint(mesh, inherited.element) == inherited.fingerprint;
}

/// The entry of element e in `inherited` (ascending elements), or nullptr.
const InheritedBounds* entry_of(const std::vector<InheritedBounds>& inherited, std::size_t e) {
  const auto it = std::lower_bound(inherited.begin(), inherited.end(), e,
                                   [](const InheritedBounds& b, std::size_t element) { return b.element < element; });
  return it != inherited.end() && it->element == e ? &*it : nullptr;
}

void check_inherited(const std::vector<InheritedBounds>& inherited, std::size_t elements) {
  for (std::size_t i = 0; i < inherited.size(); ++i) {
    if (inherited[i].element >= elements)
      throw std::invalid_argument("certify_mesh: inherited bounds for element " + std::to_string(inherited[i].element) +
                                  " of a mesh of " + std::to_string(elements) + " elements");
    if (i > 0 && inherited[i].element <= inherited[i - 1].element)
      throw std::invalid_argument("certify_mesh: inherited bounds not in ascending element order at element " +
                                  std::to_string(inherited[i].element));
  }
}

}  // namespace

std::uint64_t element_fingerprint(const mesh::Mesh& mesh, std::size_t e) {
  // FNV-1a on 64-bit words instead of bytes (an eighth of the multiplications): each step is a
  // bijection of the hash, so elements that differ in one word always get different fingerprints.
  std::uint64_t hash = 14695981039346656037ull;
  const auto mix = [&](std::uint64_t word) {
    hash ^= word;
    hash *= 1099511628211ull;
  };
  mix(static_cast<std::uint64_t>(mesh.elements()[e].shape));
  mix(static_cast<std::uint64_t>(mesh.order()));
  mix(static_cast<std::uint64_t>(mesh.node_set()));
  thread_local std::vector<mesh::NodeId> ids;  // a buffer per thread: no allocation per element
  mesh.element_nodes(e, ids);
  for (mesh::NodeId id : ids) {
    const Eigen::Vector3d& x = mesh.node(id);
    for (int c = 0; c < 3; ++c) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &x[c], sizeof bits);
      mix(bits);
    }
  }
  return hash;
}

MeshValidity certify_mesh(const mesh::Mesh& mesh, int max_depth, double min_scaled_jacobian,
                          const ProgressCallback& progress, const std::vector<InheritedBounds>* inherited) {
  if (max_depth < 0)
    throw std::invalid_argument("certify_mesh: max_depth = " + std::to_string(max_depth) + " must be >= 0");
  const std::size_t n = mesh.elements().size();
  for (std::size_t e = 0; e < n; ++e)
    if (dimension(mesh.elements()[e].shape) != 3)
      throw std::invalid_argument("certify_mesh: element " + std::to_string(e) + " is a " +
                                  to_string(mesh.elements()[e].shape) + "; only 3D elements can be certified");

  if (inherited) check_inherited(*inherited, n);

  MeshValidity out;
  out.bounds.resize(n);
  std::atomic<std::size_t> from_parent{0}, certified_before{0};
  detail::parallel_for(n, true, [&](std::size_t e) {
    const InheritedBounds* entry = inherited ? entry_of(*inherited, e) : nullptr;
    if (entry && usable(*entry, mesh, min_scaled_jacobian)) {
      out.bounds[e] = entry->bounds;
      (entry->from_parent ? from_parent : certified_before).fetch_add(1, std::memory_order_relaxed);
      return;
    }
    thread_local Eigen::MatrixX3d x;  // this thread's: no allocation per element
    mesh.element_coordinates(e, x);
    out.bounds[e] = certify_jacobian(mesh.elements()[e].shape, mesh.order(), mesh.node_set(), x, max_depth,
                                     min_scaled_jacobian);
  }, progress, "elements");
  out.inherited = from_parent.load();
  out.certified_before = certified_before.load();

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

namespace {

void check_depth(const char* who, int max_depth) {
  if (max_depth < 0)
    throw std::invalid_argument(std::string(who) + ": max_depth = " + std::to_string(max_depth) + " must be >= 0");
}

// Element e's certificate as certify_mesh computes it, with its fingerprint.
InheritedBounds certificate(const char* who, const mesh::Mesh& mesh, std::size_t e, int max_depth,
                            double min_scaled_jacobian) {
  const ho::Shape shape = mesh.elements()[e].shape;
  if (dimension(shape) != 3)
    throw std::invalid_argument(std::string(who) + ": element " + std::to_string(e) + " is a " + to_string(shape) +
                                "; only 3D elements can be certified");
  thread_local Eigen::MatrixX3d x;  // this thread's: no allocation per element
  mesh.element_coordinates(e, x);
  return {e, element_fingerprint(mesh, e),
          certify_jacobian(shape, mesh.order(), mesh.node_set(), x, max_depth, min_scaled_jacobian),
          /*from_parent=*/false};
}

}  // namespace

std::vector<InheritedBounds> certify_ahead(const mesh::Mesh& mesh, int max_depth, double min_scaled_jacobian,
                                           const std::atomic<bool>& stop) {
  check_depth("certify_ahead", max_depth);
  const detail::OneThreadScope one_thread;  // beside TetGen's process, not over both cores
  std::vector<InheritedBounds> out;
  out.reserve(mesh.elements().size());
  for (std::size_t e = 0; e < mesh.elements().size() && !stop.load(std::memory_order_relaxed); ++e)
    out.push_back(certificate("certify_ahead", mesh, e, max_depth, min_scaled_jacobian));
  return out;
}

std::vector<InheritedBounds> certify_behind(const mesh::Mesh& mesh, const std::vector<std::size_t>& wanted,
                                            const std::atomic<std::size_t>& built, int max_depth,
                                            double min_scaled_jacobian, const std::atomic<bool>& stop) {
  check_depth("certify_behind", max_depth);
  const detail::OneThreadScope one_thread;  // on the core the builder leaves idle, not over both
  std::vector<InheritedBounds> out;
  out.reserve(wanted.size());
  for (std::size_t e : wanted) {
    // A short sleep, not a spin: the builder's core is the one that must not be slowed.
    while (built.load(std::memory_order_acquire) <= e) {
      if (stop.load(std::memory_order_relaxed)) return out;
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    if (stop.load(std::memory_order_relaxed)) return out;
    out.push_back(certificate("certify_behind", mesh, e, max_depth, min_scaled_jacobian));
  }
  return out;
}

}  // namespace semimesh::ho
