#include "semimesh/surface/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <sstream>

namespace semimesh::surface {
namespace {

double angle_deg(const Vec3& u, const Vec3& v) { return std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / M_PI; }

}  // namespace

std::array<double, 3> triangle_angles_deg(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  return {angle_deg(p1 - p0, p2 - p0), angle_deg(p2 - p1, p0 - p1), angle_deg(p0 - p2, p1 - p2)};
}

double min_angle_sine(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  // |cross| / (l_mid l_max) written as |cross| l_min / (l0 l1 l2): no sorting.
  const double l0 = (p1 - p0).norm(), l1 = (p2 - p1).norm(), l2 = (p0 - p2).norm();
  const double product = l0 * l1 * l2;
  return product > 0.0 ? (p1 - p0).cross(p2 - p0).norm() * std::min({l0, l1, l2}) / product : 0.0;
}

std::string AngleStats::to_string() const {
  std::ostringstream out;
  out << triangles << " triangles, min angle " << min_deg << " deg, max angle " << max_deg
      << " deg, min-angle histogram (10 deg bins):";
  for (int count : histogram) out << ' ' << count;
  return out.str();
}

AngleStats angle_statistics(const SurfaceMesh& mesh, bool skip_boundary_edges) {
  // A boundary edge is used by one triangle only.
  std::set<std::pair<int, int>> once, twice;
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const auto e = std::minmax(t[i], t[(i + 1) % 3]);
      if (!once.insert(e).second) twice.insert(e);
    }
  AngleStats stats;
  for (const auto& t : mesh.triangles) {
    if (skip_boundary_edges) {
      bool on_boundary = false;
      for (int i = 0; i < 3; ++i) on_boundary = on_boundary || !twice.count(std::minmax(t[i], t[(i + 1) % 3]));
      if (on_boundary) continue;
    }
    const auto a = triangle_angles_deg(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    const double lo = std::min({a[0], a[1], a[2]}), hi = std::max({a[0], a[1], a[2]});
    stats.min_deg = std::min(stats.min_deg, lo);
    stats.max_deg = std::max(stats.max_deg, hi);
    ++stats.histogram[std::min(17, static_cast<int>(lo / 10.0))];
    ++stats.triangles;
  }
  return stats;
}

}  // namespace semimesh::surface
