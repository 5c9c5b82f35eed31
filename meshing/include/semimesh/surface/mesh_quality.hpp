// Angles of surface triangles in 3D: the quality figure of the 2D meshes.
#pragma once

#include "semimesh/surface/surface_mesh.hpp"

#include <array>
#include <string>

namespace semimesh::surface {

/// Interior angles of a 3D triangle in degrees, at p0, p1, p2.
std::array<double, 3> triangle_angles_deg(const Vec3& p0, const Vec3& p1, const Vec3& p2);

/// Sine of the smallest interior angle (that angle is <= 60 degrees, so the sine orders triangles
/// like the angle does, without trigonometry): 2 area / (product of the two longer edges).
double min_angle_sine(const Vec3& p0, const Vec3& p1, const Vec3& p2);

struct AngleStats {
  int triangles = 0;                   ///< triangles counted
  double min_deg = 180.0;
  double max_deg = 0.0;
  std::array<int, 18> histogram{};     ///< [18] minimum angle per triangle in 10-degree bins [0,10), ..., [170,180]
  std::string to_string() const;       ///< one line: count, min, max, histogram
};

/// Minimum/maximum angles of the triangles of `mesh`. With `skip_boundary_edges`, triangles with an
/// edge on the surface boundary (a curve segment) are left out: their shape is fixed by the curve mesh.
AngleStats angle_statistics(const SurfaceMesh& mesh, bool skip_boundary_edges);

}  // namespace semimesh::surface
