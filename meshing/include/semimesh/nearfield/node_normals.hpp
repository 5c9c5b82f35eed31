// Extrusion directions of the body nodes.
//
// Each node gets the angle-weighted average of its triangles' unit normals (Thuermer & Wuethrich
// 1998: independent of how the fan is triangulated), is then corrected so that it sees every
// adjacent triangle (positive dot product with each triangle normal: the prism built on that
// triangle then has a positive Jacobian at that body vertex), and finally smoothed by Laplacian
// passes that are kept only where they do not make the worst adjacent angle worse than allowed.
// A node may be constrained to a plane (root nodes on the wall: the wall normal is removed), so that
// its offset stays in the wall.
#pragma once

#include "semimesh/nearfield/body_mesh.hpp"

#include <vector>

namespace semimesh::nearfield {

struct NormalOptions {
  int smoothing_passes = 10;
  double smoothing_weight = 0.5;   ///< move toward the neighbours' mean by this fraction per pass
  double min_visibility = 0.5;     ///< smoothing may not push n . (triangle normal) below this
                                   ///< (or below what the unsmoothed normal achieved, if less)
};

/// Unit normals [nodes]. `plane_normal[i]` (unit, or zero for a free node) is removed from node i's
/// direction. Throws NearFieldError naming the node's surface and position when no direction sees
/// all its triangles (a cusp, or a constraint plane that cuts the fan).
std::vector<Vec3> node_normals(const BodyMesh& body, const std::vector<Vec3>& plane_normal,
                               const NormalOptions& options = {});

/// Smallest n . (unit normal) over the triangles around `node` (1 when it has none).
double min_visibility(const BodyMesh& body, const std::vector<std::vector<int>>& node_triangles, int node,
                      const Vec3& n);

/// Triangles around each node: [nodes][triangles].
std::vector<std::vector<int>> node_triangles(const BodyMesh& body);

}  // namespace semimesh::nearfield
