#include "semimesh/nearfield/pyramid_apex.hpp"

#include "semimesh/ho/validity.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <vector>

namespace semimesh::nearfield {

constexpr double kHeightPerShortestEdge = 0.3;

std::optional<Eigen::Vector3d> pyramid_apex(const std::array<Eigen::Vector3d, 4>& quad,
                                            const std::array<double, 4>& max_slope) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
  double perimeter = 0.0;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d& p = quad[i];
    const Eigen::Vector3d& q = quad[(i + 1) % 4];
    centroid += 0.25 * p;
    normal += p.cross(q);  // Newell: twice the vector area of the (possibly warped) quad
    perimeter += (q - p).norm();
  }
  if (normal.norm() <= 1e-14 * perimeter * perimeter) return std::nullopt;
  normal.normalize();
  // The highest apex every edge's slope cap allows (its rise over the centre's distance to the edge
  // line, in the mean plane). Not a height scale from the distances: on the sheared quads of a swept
  // trailing edge's rear interfaces that apex is lower than the shortest edge's and, curved at
  // order 4 over the trailing-edge base, inverted; where a neighbour closes in, the cap says so.
  double shortest = 1e300, highest = 1e300;
  for (int i = 0; i < 4; ++i) {
    Eigen::Vector3d edge = quad[(i + 1) % 4] - quad[i], to_centre = centroid - quad[i];
    shortest = std::min(shortest, edge.norm());
    edge -= edge.dot(normal) * normal;
    to_centre -= to_centre.dot(normal) * normal;
    if (edge.norm() > 0.0) highest = std::min(highest, max_slope[i] * edge.normalized().cross(to_centre).norm());
  }

  Eigen::MatrixX3d nodes(5, 3);
  for (int i = 0; i < 4; ++i) nodes.row(i) = quad[i].transpose();
  // Two pyramids on skin quads meeting at a right-angled concave corner (the H-type's wake root and
  // the rear interfaces below it) stay apart when each rises from its base edges at less than 45
  // degrees: 2 height / edge <= 0.6 for every edge of a rectangle (sharper corners and sheared
  // quads: the slope caps).
  // Lower first (flat quads), then higher: a warped quad needs the apex above all four corner planes.
  // Last, heights from the mean edge: a twisted trapezoid with one short edge (a rear interface's
  // lowest quad, from the trailing edge down to its halo) needs an apex above the twist of its long
  // edges, which the short edge does not measure; the lowest valid one is taken.
  const double start = kHeightPerShortestEdge * shortest, mean_edge = 0.25 * perimeter;
  std::vector<double> heights;
  for (const double factor : {1.0, 0.5, 0.25, 0.125, 0.0625, 0.03125, 0.015625, 2.0, 4.0}) heights.push_back(factor * start);
  for (const double factor : {0.3, 0.4, 0.55, 0.75, 1.0})
    if (factor * mean_edge > 4.0 * start) heights.push_back(factor * mean_edge);
  for (const double height : heights) {
    if (height > highest) continue;
    const Eigen::Vector3d apex = centroid + height * normal;
    nodes.row(4) = apex.transpose();
    if (ho::certify_jacobian(ho::Shape::Pyramid, 1, ho::NodeSet::Equispaced, nodes).valid) return apex;
  }
  return std::nullopt;
}

}  // namespace semimesh::nearfield
