#include "semimesh/nearfield/layer_checks.hpp"

#include "semimesh/geometry/box_tree.hpp"

#include "semimesh/ho/closest_point.hpp"
#include "semimesh/ho/validity.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <unordered_set>

namespace semimesh::nearfield {
namespace {

// Mesh path lengths from `source`, up to `radius`: the nodes reached.
std::unordered_set<int> nodes_within(const BodyMesh& body, const std::vector<std::vector<int>>& neighbours, int source,
                                     double radius) {
  std::unordered_set<int> done;
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  queue.push({0.0, source});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (!done.insert(v).second) continue;
    for (int w : neighbours[v]) {
      const double dw = d + (body.points[w] - body.points[v]).norm();
      if (dw <= radius && !done.count(w)) queue.push({dw, w});
    }
  }
  return done;
}

// Smallest det at a body vertex relative to the product of its three edges (sine-like).
constexpr double kFlattest = 1e-9;

}  // namespace

bool prism_is_sound(const std::array<Vec3, 6>& x, double min_outer_ratio) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const Vec3 up = x[i + 3] - x[i];
    const double body_det = (x[j] - x[i]).cross(x[k] - x[i]).dot(up);
    const double outer_det = (x[j + 3] - x[i + 3]).cross(x[k + 3] - x[i + 3]).dot(up);
    // Relative to the edges: a flat body triangle (collinear nodes) has a round-off det of either sign.
    const double scale = (x[j] - x[i]).norm() * (x[k] - x[i]).norm() * up.norm();
    if (!(body_det > kFlattest * scale) || outer_det < min_outer_ratio * body_det) return false;
  }
  Eigen::MatrixX3d nodes(6, 3);
  for (int i = 0; i < 6; ++i) nodes.row(i) = x[i].transpose();
  return ho::certify_jacobian(ho::Shape::Prism, 1, ho::NodeSet::Equispaced, nodes).valid;
}

double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return (p - ho::closest_point_on_triangle(p, a, b, c).point).norm();
}

namespace {

// Bounding sphere of each triangle: a cheap lower bound of the distance to it.
struct TriangleSpheres {
  std::vector<Vec3> centre;
  std::vector<double> radius;
};

TriangleSpheres triangle_spheres(const BodyMesh& body) {
  TriangleSpheres s;
  for (const auto& v : body.triangles) {
    const Vec3 c = (body.points[v[0]] + body.points[v[1]] + body.points[v[2]]) / 3.0;
    double r = 0.0;
    for (int i : v) r = std::max(r, (body.points[i] - c).norm());
    s.centre.push_back(c);
    s.radius.push_back(r);
  }
  return s;
}

// Whether triangle t, not in the node's own neighbourhood, is closer than `limit` to p. `own` is
// filled on the first triangle that passes the sphere test (most nodes never need it).
bool crowds(const BodyMesh& body, const std::vector<std::vector<int>>& neighbours, const TriangleSpheres& spheres,
            int node, const Vec3& p, double limit, double own_radius, int t, std::unordered_set<int>& own,
            bool& own_known) {
  if ((p - spheres.centre[t]).norm() - spheres.radius[t] >= limit) return false;
  if (!own_known) own = nodes_within(body, neighbours, node, own_radius), own_known = true;
  const auto& v = body.triangles[t];
  if (own.count(v[0]) || own.count(v[1]) || own.count(v[2])) return false;
  return point_triangle_distance(p, body.points[v[0]], body.points[v[1]], body.points[v[2]]) < limit;
}

}  // namespace

std::vector<char> crowded_nodes_by_scan(const BodyMesh& body, const std::vector<std::vector<int>>& neighbours,
                                        const std::vector<Vec3>& outer, const std::vector<double>& thickness) {
  const TriangleSpheres spheres = triangle_spheres(body);
  std::vector<char> crowded(body.num_nodes(), 0);
  for (int i = 0; i < body.num_nodes(); ++i) {
    std::unordered_set<int> own;
    bool own_known = false;
    for (int t = 0; t < static_cast<int>(body.triangles.size()) && !crowded[i]; ++t)
      crowded[i] = crowds(body, neighbours, spheres, i, outer[i], 0.5 * thickness[i], 1.5 * thickness[i], t, own, own_known);
  }
  return crowded;
}

std::vector<char> crowded_nodes(const BodyMesh& body, const std::vector<std::vector<int>>& neighbours,
                                const std::vector<Vec3>& outer, const std::vector<double>& thickness) {
  const TriangleSpheres spheres = triangle_spheres(body);
  std::vector<char> crowded(body.num_nodes(), 0);
  const std::vector<geometry::Box> boxes = geometry::triangle_boxes(body.points, body.triangles);
  const geometry::BoxTree tree(boxes);
  // Each node on its own (its flag only): the nodes shared among threads, the flags the same.
#pragma omp parallel for schedule(dynamic, 256)
  for (int i = 0; i < body.num_nodes(); ++i) {
    std::unordered_set<int> own;
    bool own_known = false;
    const double limit = 0.5 * thickness[i];
    crowded[i] = tree.visit([&](const geometry::Box& box) { return box.squared_distance(outer[i]) < limit * limit; },
                            [&](int t) {
                              return crowds(body, neighbours, spheres, i, outer[i], limit, 1.5 * thickness[i], t, own,
                                            own_known);
                            });
  }
  return crowded;
}

}  // namespace semimesh::nearfield
