#include "semimesh/surface/surface_mesh.hpp"

#include "boundary_nodes.hpp"
#include "semimesh/surface/error.hpp"
#include "semimesh/surface/mesh_quality.hpp"

#include <algorithm>

namespace semimesh::surface {
namespace {

double min_angle(const SurfaceMesh& m, int a, int b, int c) { return min_angle_sine(m.points[a], m.points[b], m.points[c]); }

}  // namespace

SurfaceMesh mesh_surface_structured(const cad::Model& model, int surface, const CurveMeshes& curves,
                                    bool split_into_triangles) {
  if (surface < 0 || surface >= model.num_surfaces())
    throw SurfaceMeshError("surface id " + std::to_string(surface) + " is out of range: the model has " +
                           std::to_string(model.num_surfaces()) + " surfaces");
  const std::string label = cad::surface_label(model, surface);
  const auto& loops = model.loops(surface);
  if (loops.size() != 1 || loops[0].uses.size() != 4)
    throw SurfaceMeshError(label + " is not a structured strip: it needs one loop of four curves");
  std::array<int, 4> counts;
  for (int k = 0; k < 4; ++k) counts[k] = curves.at(loops[0].uses[k].curve).segments();
  if (counts[0] != counts[2] || counts[1] != counts[3])
    throw SurfaceMeshError(label + ": opposite curves need equal segment counts for a structured strip, got " +
                           std::to_string(counts[0]) + "/" + std::to_string(counts[2]) + " and " +
                           std::to_string(counts[1]) + "/" + std::to_string(counts[3]));

  SurfaceMesh mesh;
  mesh.surface = surface;
  const std::vector<int> chain = detail::add_boundary_nodes(model, surface, curves, mesh).front();
  const int n = counts[0], m = counts[1], total = static_cast<int>(chain.size());
  // Logical grid (i, j): side 0 is j = 0 walked with i, side 1 is i = n, side 2 is j = m walked
  // back, side 3 is i = 0 walked back; the loop is counter-clockwise around the fluid normal.
  std::vector<int> grid((n + 1) * (m + 1), -1);  // [(n + 1) * (m + 1)] node ids, i fastest
  auto at = [&](int i, int j) -> int& { return grid[j * (n + 1) + i]; };
  for (int i = 0; i <= n; ++i) {
    at(i, 0) = chain[i % total];
    at(i, m) = chain[(n + m + (n - i)) % total];
  }
  for (int j = 0; j <= m; ++j) {
    at(n, j) = chain[(n + j) % total];
    at(0, j) = chain[(2 * n + m + (m - j)) % total];
  }
  const cad::Surface& face = model.surface(surface);
  auto uv = [&](int i, int j) { return mesh.uv[at(i, j)]; };
  for (int j = 1; j < m; ++j)
    for (int i = 1; i < n; ++i) {
      // Transfinite (Coons) interpolation of the boundary parameters.
      const double xi = static_cast<double>(i) / n, eta = static_cast<double>(j) / m;
      const Vec2 p = (1 - eta) * uv(i, 0) + eta * uv(i, m) + (1 - xi) * uv(0, j) + xi * uv(n, j) -
                     ((1 - xi) * (1 - eta) * uv(0, 0) + xi * (1 - eta) * uv(n, 0) + xi * eta * uv(n, m) +
                      (1 - xi) * eta * uv(0, m));
      mesh.uv.push_back(p);
      mesh.points.push_back(face.point(p));
      mesh.origin.push_back(NodeOrigin{});
      at(i, j) = mesh.num_nodes() - 1;
    }
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const std::array<int, 4> q{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
      if (!split_into_triangles) {
        mesh.quads.push_back(q);
        continue;
      }
      const double diagonal02 = std::min(min_angle(mesh, q[0], q[1], q[2]), min_angle(mesh, q[0], q[2], q[3]));
      const double diagonal13 = std::min(min_angle(mesh, q[0], q[1], q[3]), min_angle(mesh, q[1], q[2], q[3]));
      if (diagonal02 >= diagonal13) {
        mesh.triangles.push_back({q[0], q[1], q[2]});
        mesh.triangles.push_back({q[0], q[2], q[3]});
      } else {
        mesh.triangles.push_back({q[0], q[1], q[3]});
        mesh.triangles.push_back({q[1], q[2], q[3]});
      }
    }
  return mesh;
}

}  // namespace semimesh::surface
