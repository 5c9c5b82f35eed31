#include "semimesh/farfield/detail/flat_tet.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace semimesh::farfield {

std::optional<FlatTet> find_flat_tet(const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<std::array<int, 4>>& tets, double relative_tolerance) {
  std::optional<FlatTet> flattest;
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const std::array<int, 4>& v = tets[t];
    double longest = 0.0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) longest = std::max(longest, (points[v[a]] - points[v[b]]).norm());
    const Eigen::Vector3d& p0 = points[v[0]];
    const double volume6 = std::abs((points[v[1]] - p0).cross(points[v[2]] - p0).dot(points[v[3]] - p0));
    const double relative = volume6 / (longest * longest * longest);
    if (!(relative > relative_tolerance) && (!flattest || relative < flattest->relative)) flattest = FlatTet{t, relative};
  }
  return flattest;
}

}  // namespace semimesh::farfield
