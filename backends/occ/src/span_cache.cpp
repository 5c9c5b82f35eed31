#include "span_cache.hpp"

#include <atomic>
#include <memory>
#include <unordered_map>

namespace semimesh::occ {
namespace {

// Adaptors of surfaces whose model is gone stay until the map is this full, then all go (a thread
// meshing one model holds one per face; tests that load many models refill it).
constexpr std::size_t kMaxAdaptorsPerThread = 4096;

}  // namespace

std::uint64_t new_surface_serial() {
  static std::atomic<std::uint64_t> next{0};
  return next.fetch_add(1, std::memory_order_relaxed);
}

const GeomAdaptor_Surface& thread_adaptor(std::uint64_t serial, const Handle(Geom_Surface)& surface) {
  thread_local std::unordered_map<std::uint64_t, std::unique_ptr<GeomAdaptor_Surface>> adaptors;
  if (const auto it = adaptors.find(serial); it != adaptors.end()) return *it->second;
  if (adaptors.size() >= kMaxAdaptorsPerThread) adaptors.clear();
  return *adaptors.emplace(serial, std::make_unique<GeomAdaptor_Surface>(surface)).first->second;
}

const Handle(Geom_Surface)& thread_copy(std::uint64_t serial, const Handle(Geom_Surface)& surface) {
  thread_local std::unordered_map<std::uint64_t, Handle(Geom_Surface)> copies;
  if (const auto it = copies.find(serial); it != copies.end()) return it->second;
  if (copies.size() >= kMaxAdaptorsPerThread) copies.clear();
  return copies.emplace(serial, Handle(Geom_Surface)::DownCast(surface->Copy())).first->second;
}

}  // namespace semimesh::occ
