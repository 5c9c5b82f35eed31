// The point of a triangle closest to a given point (Ericson, "Real-Time Collision Detection", 2005,
// section 5.1.5: the Voronoi regions of the vertices, then of the edges, then the face).
#pragma once

#include <Eigen/Core>

namespace semimesh::ho {

struct TriangleFoot {
  Eigen::Vector3d point;        ///< the closest point of the triangle
  Eigen::Vector3d barycentric;  ///< its coordinates on (a, b, c), each in [0, 1], summing to 1
};

/// The point of triangle (a, b, c) closest to p.
TriangleFoot closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       const Eigen::Vector3d& c);

}  // namespace semimesh::ho
