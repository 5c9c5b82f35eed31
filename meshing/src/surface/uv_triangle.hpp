// Small kernels on a surface mesh's parameter-plane triangles, shared by the mesh improvement and
// the flat-corner repair.
#pragma once

#include "semimesh/surface/surface_mesh.hpp"

#include <cstdint>
#include <utility>

namespace semimesh::surface::detail {

/// The key of the undirected edge (a, b): the same for (b, a).
inline std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

/// Signed area of the triangle (a, b, c) in the parameter plane: > 0 counter-clockwise.
inline double signed_area_uv(const SurfaceMesh& m, int a, int b, int c) {
  const Vec2 e1 = m.uv[b] - m.uv[a], e2 = m.uv[c] - m.uv[a];
  return 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
}

}  // namespace semimesh::surface::detail
