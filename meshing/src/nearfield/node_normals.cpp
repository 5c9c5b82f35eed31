#include "semimesh/nearfield/node_normals.hpp"

#include "semimesh/nearfield/error.hpp"

#include "labels.hpp"

#include <algorithm>
#include <cmath>

namespace semimesh::nearfield {
namespace {

// Below this, no direction usefully sees all the triangles of a fan (about 0.06 degrees).
constexpr double kNoVisibility = 1e-3;

Vec3 triangle_normal(const BodyMesh& body, int t) {
  const auto& v = body.triangles[t];
  return (body.points[v[1]] - body.points[v[0]]).cross(body.points[v[2]] - body.points[v[0]]).normalized();
}

Vec3 constrained(Vec3 n, const Vec3& plane_normal) {
  n -= n.dot(plane_normal) * plane_normal;
  const double length = n.norm();
  return length > 0.0 ? Vec3(n / length) : n;
}

// Angle-weighted mean of the unit normals of the triangles around each node.
std::vector<Vec3> angle_weighted_normals(const BodyMesh& body) {
  std::vector<Vec3> sum(body.num_nodes(), Vec3::Zero());
  for (int t = 0; t < static_cast<int>(body.triangles.size()); ++t) {
    const auto& v = body.triangles[t];
    const Vec3 n = triangle_normal(body, t);
    for (int i = 0; i < 3; ++i) {
      const Vec3 e1 = body.points[v[(i + 1) % 3]] - body.points[v[i]];
      const Vec3 e2 = body.points[v[(i + 2) % 3]] - body.points[v[i]];
      sum[v[i]] += std::atan2(e1.cross(e2).norm(), e1.dot(e2)) * n;
    }
  }
  return sum;
}

// Maximises the smallest n . f over the fan by steps toward the worst triangle normal f (an ascent
// on a concave function of n on the sphere, so halving the step converges to the best direction).
Vec3 widen_visibility(const BodyMesh& body, const std::vector<std::vector<int>>& fans, int node, Vec3 n,
                      const Vec3& plane_normal, double enough) {
  double best = min_visibility(body, fans, node, n);
  double step = 0.5;
  for (int iteration = 0; iteration < 400 && step > 1e-6 && best < enough; ++iteration) {
    Vec3 worst = Vec3::Zero();
    double worst_dot = 2.0;
    for (int t : fans[node]) {
      const Vec3 f = triangle_normal(body, t);
      if (f.dot(n) < worst_dot) worst_dot = f.dot(n), worst = f;
    }
    Vec3 towards = worst - worst_dot * n;
    towards -= towards.dot(plane_normal) * plane_normal;
    if (towards.norm() < 1e-14) break;
    const Vec3 candidate = constrained(n + step * towards.normalized(), plane_normal);
    const double value = min_visibility(body, fans, node, candidate);
    if (value > best) {
      n = candidate, best = value;
    } else {
      step *= 0.5;
    }
  }
  return n;
}

}  // namespace

std::vector<std::vector<int>> node_triangles(const BodyMesh& body) {
  std::vector<std::vector<int>> fans(body.num_nodes());
  for (int t = 0; t < static_cast<int>(body.triangles.size()); ++t)
    for (int v : body.triangles[t]) fans[v].push_back(t);
  return fans;
}

double min_visibility(const BodyMesh& body, const std::vector<std::vector<int>>& node_triangles, int node,
                      const Vec3& n) {
  double worst = 1.0;
  for (int t : node_triangles[node]) worst = std::min(worst, n.dot(triangle_normal(body, t)));
  return worst;
}

std::vector<Vec3> node_normals(const BodyMesh& body, const std::vector<Vec3>& plane_normal, const NormalOptions& options) {
  const int count = body.num_nodes();
  const auto fans = node_triangles(body);
  const auto neighbours = node_neighbours(body);
  std::vector<Vec3> normals = angle_weighted_normals(body);
  std::vector<double> floor(count);
  // Each node on its own, on every thread; the first node (by index) no direction sees is refused.
#pragma omp parallel for schedule(dynamic, 256)
  for (int i = 0; i < count; ++i) {
    normals[i] = constrained(normals[i].normalized(), plane_normal[i]);
    normals[i] = widen_visibility(body, fans, i, normals[i], plane_normal[i], options.min_visibility);
    floor[i] = min_visibility(body, fans, i, normals[i]);
  }
  for (int i = 0; i < count; ++i) {
    if (!(floor[i] > kNoVisibility)) {
      // Usually coarse triangles wrapped round a small nose radius (seen at a swept, tapered 0006 tip).
      double longest = 0.0;
      for (int j : neighbours[i]) longest = std::max(longest, (body.points[j] - body.points[i]).norm());
      throw NearFieldError("near field: no extrusion direction sees all the triangles around the body node at " +
                           point_label(body.points[i]) + " (surface id " + std::to_string(body.node_surface[i]) +
                           "): its edges (up to " + number_label(longest) +
                           " long) are too coarse for the body's curvature there, or the body has a cusp, or the wall "
                           "cuts its fan; mesh the surface finer there (e.g. sizing.min_size <= " +
                           number_label(0.25 * longest) + ") or fix the geometry");
    }
    floor[i] = std::min(floor[i], options.min_visibility);
  }
  for (int pass = 0; pass < options.smoothing_passes; ++pass) {
    std::vector<Vec3> next = normals;
#pragma omp parallel for schedule(dynamic, 256)
    for (int i = 0; i < count; ++i) {
      if (neighbours[i].empty()) continue;
      Vec3 mean = Vec3::Zero();
      for (int j : neighbours[i]) mean += normals[j];
      mean /= static_cast<double>(neighbours[i].size());
      const Vec3 candidate =
          constrained((normals[i] + options.smoothing_weight * (mean - normals[i])).normalized(), plane_normal[i]);
      if (min_visibility(body, fans, i, candidate) >= floor[i]) next[i] = candidate;
    }
    normals.swap(next);
  }
  return normals;
}

}  // namespace semimesh::nearfield
