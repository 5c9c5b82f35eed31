#include "semimesh/farfield/detail/pyramid_apex.hpp"

#include "semimesh/farfield/far_field.hpp"
#include "semimesh/nearfield/pyramid_apex.hpp"

#include <sstream>

namespace semimesh::farfield {

Eigen::Vector3d pyramid_apex(const std::array<Eigen::Vector3d, 4>& quad, const std::array<double, 4>& max_slope) {
  if (const auto apex = nearfield::pyramid_apex(quad, max_slope)) return *apex;
  // A warped quad in a tight corner (the bare triangles round a sharp trailing edge's tip) may need
  // more height than the caps allow: the uncapped apex, which TetGen checks against its neighbours.
  if (const auto apex = nearfield::pyramid_apex(quad)) return *apex;
  const Eigen::Vector3d centroid = 0.25 * (quad[0] + quad[1] + quad[2] + quad[3]);
  std::ostringstream where;
  where << "(" << centroid.x() << ", " << centroid.y() << ", " << centroid.z() << ")";
  double perimeter = 0.0;
  for (int i = 0; i < 4; ++i) perimeter += (quad[(i + 1) % 4] - quad[i]).norm();
  // Twice the vector area (Newell), as nearfield::pyramid_apex measures it.
  if ((quad[2] - quad[0]).cross(quad[3] - quad[1]).norm() <= 1e-14 * perimeter * perimeter)
    throw FarFieldError("pyramid on the skin quad at " + where.str() + ": the quad has zero area");
  throw FarFieldError("pyramid on the skin quad at " + where.str() +
                      ": no apex height gives a valid pyramid (is the quad folded or far from planar?)");
}

}  // namespace semimesh::farfield
