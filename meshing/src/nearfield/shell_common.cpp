#include "shell_common.hpp"

#include "semimesh/nearfield/error.hpp"
#include "semimesh/nearfield/layer_checks.hpp"

#include "labels.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <queue>
#include <sstream>

namespace semimesh::nearfield::detail {
namespace {

// Why a node's thickness was reduced (bits).
enum Reason : unsigned { kFold = 1, kProximity = 2 };

// thickness[i] <= thickness[j] + gradation |x_i - x_j| over mesh edges (Dijkstra from the thinnest);
// pinned nodes keep theirs.
void limit_gradation(const BodyMesh& body, const std::vector<std::vector<int>>& neighbours, double gradation,
                     const std::vector<char>& pinned, std::vector<double>& thickness) {
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int i = 0; i < body.num_nodes(); ++i) queue.push({thickness[i], i});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > thickness[v]) continue;
    for (int w : neighbours[v]) {
      if (!pinned.empty() && pinned[w]) continue;
      const double bound = d + gradation * (body.points[w] - body.points[v]).norm();
      if (bound < thickness[w]) thickness[w] = bound, queue.push({bound, w});
    }
  }
}

std::string reason_text(unsigned reasons) {
  std::string text;
  if (reasons & kFold) text += "neighbouring prisms would fold (concave curvature)";
  if (reasons & kProximity)
    text += std::string(text.empty() ? "" : "; ") +
            "the layer would come closer than half its thickness to another part of the body";
  return text.empty() ? "graded from a reduced neighbour" : text;
}

// One warning per connected region of nodes whose thickness was reduced, at its thinnest node.
std::vector<Warning> reduction_warnings(const cad::Model& model, const BodyMesh& body,
                                        const std::vector<std::vector<int>>& neighbours,
                                        const std::vector<double>& thickness, const std::vector<unsigned>& reasons,
                                        const std::vector<char>& pinned, double requested) {
  std::vector<Warning> warnings;
  std::vector<char> seen(body.num_nodes(), 0);
  auto reduced = [&](int i) { return (pinned.empty() || !pinned[i]) && thickness[i] < requested * (1.0 - 1e-12); };
  for (int start = 0; start < body.num_nodes(); ++start) {
    if (seen[start] || !reduced(start)) continue;
    int thinnest = start, count = 0;
    unsigned why = 0;
    std::vector<int> stack{start};
    seen[start] = 1;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      ++count, why |= reasons[v];
      if (thickness[v] < thickness[thinnest]) thinnest = v;
      for (int w : neighbours[v])
        if (!seen[w] && reduced(w)) seen[w] = 1, stack.push_back(w);
    }
    std::ostringstream message;
    message << "near-field thickness reduced to " << thickness[thinnest] << " ("
            << std::lround(100.0 * thickness[thinnest] / requested) << "% of " << requested << ") on "
            << surface_label(model, body.node_surface[thinnest]) << " around " << point_label(body.points[thinnest])
            << " (" << count << " nodes): " << reason_text(why);
    warnings.push_back({message.str(), body.points[thinnest]});
  }
  return warnings;
}

}  // namespace

void check_shell_params(const cad::Model& model, const BodyRoles& roles, const ShellParams& p) {
  auto fail = [](const std::string& what) { throw NearFieldError("near field: " + what); };
  if (const auto bad = params::violation(p, shell_keys(), "nearfield")) fail(*bad);
  if (roles.body_surfaces.empty()) fail("no body surfaces given");
  if (roles.wall_surface >= model.num_surfaces())
    fail("wall surface id " + std::to_string(roles.wall_surface) + " is not a surface of the model");
  if (std::count(roles.body_surfaces.begin(), roles.body_surfaces.end(), roles.wall_surface))
    fail("the wall " + surface_label(model, roles.wall_surface) + " is also listed as a body surface");
}

bool on_wall(const cad::Model& model, const mesh::CadAttachment& cad, int wall) {
  auto curve_on_wall = [&](int c) {
    for (const auto& use : model.surfaces_of_curve(c))
      if (use.surface == wall) return true;
    return false;
  };
  if (cad.kind == mesh::CadAttachment::Curve) return curve_on_wall(cad.entity);
  if (cad.kind == mesh::CadAttachment::Vertex)
    for (int c : model.curves_of_vertex(cad.entity))
      if (curve_on_wall(c)) return true;
  return false;
}

LayerOffsets offset_body_nodes(const cad::Model& model, const BodyMesh& body,
                               const std::vector<std::vector<int>>& neighbours, const std::vector<Vec3>& normals,
                               const OffsetConstraints& constraints, const ShellParams& params) {
  const int count = body.num_nodes();
  const std::vector<char>& root = constraints.root;
  const std::vector<char>& pinned = constraints.pinned;
  auto is_pinned = [&](int i) { return !pinned.empty() && pinned[i]; };
  LayerOffsets result;
  std::vector<double>& thickness = result.thickness;
  thickness.assign(count, params.thickness);
  for (int i = 0; i < count; ++i)
    if (is_pinned(i)) thickness[i] = (constraints.pinned_outer[i] - body.points[i]).norm();
  std::vector<unsigned> reasons(count, 0);
  std::vector<Vec3>& outer = result.outer;
  outer.resize(count);
  result.outer_wall_uv = constraints.wall_uv;
  auto place_outer = [&] {
    for (int i = 0; i < count; ++i) {
      if (is_pinned(i)) {
        outer[i] = constraints.pinned_outer[i];
        continue;
      }
      outer[i] = body.points[i] + thickness[i] * normals[i];
      if (!root.empty() && root[i]) {
        const auto projection = model.surface(constraints.wall_surface).project(outer[i], constraints.wall_uv[i]);
        outer[i] = projection.point, result.outer_wall_uv[i] = projection.uv;
      }
    }
  };
  const double thinnest_allowed = params.min_thickness_fraction * params.thickness;
  const int max_rounds = 1000;
  for (int round = 0;; ++round) {
    place_outer();
    std::vector<unsigned> bad(count, 0);
    // Each triangle's prism on its own (threads share the triangles), then its nodes flagged in order.
    const int triangles = static_cast<int>(body.triangles.size());
    std::vector<char> folded(triangles, 0);
#pragma omp parallel for schedule(static)
    for (int k = 0; k < triangles; ++k) {
      const auto& t = body.triangles[k];
      const std::array<Vec3, 6> x{body.points[t[0]], body.points[t[1]], body.points[t[2]],
                                  outer[t[0]],       outer[t[1]],       outer[t[2]]};
      folded[k] = !prism_is_sound(x);
    }
    for (int k = 0; k < triangles; ++k)
      if (folded[k])
        for (int v : body.triangles[k]) bad[v] |= kFold;
    const auto crowded = crowded_nodes(body, neighbours, outer, thickness);
    for (int i = 0; i < count; ++i) bad[i] |= crowded[i] ? kProximity : 0u;
    if (std::none_of(bad.begin(), bad.end(), [](unsigned b) { return b != 0; })) break;
    bool reducible = false;
    for (int i = 0; i < count; ++i) {
      if (!bad[i] || is_pinned(i)) continue;
      reasons[i] |= bad[i];
      reducible = true;
      if (thickness[i] <= thinnest_allowed * (1.0 + 1e-12) || round == max_rounds)
        throw LayerFoldError(
            "near field: cannot build the prism layer on " + surface_label(model, body.node_surface[i]) + " at " +
            point_label(body.points[i]) + ": " + reason_text(bad[i]) + " even at min_thickness_fraction (" +
            number_label(params.min_thickness_fraction) + ") x thickness (" + number_label(params.thickness) +
            "); use a smaller 'thickness' or a finer surface mesh there",
            i, reason_text(bad[i]));
      thickness[i] = std::max(thickness[i] * params.reduction_factor, thinnest_allowed);
    }
    if (!reducible) {
      const int i =
          static_cast<int>(std::find_if(bad.begin(), bad.end(), [](unsigned b) { return b != 0; }) - bad.begin());
      throw LayerFoldError("near field: the prism layer above the root strip on " +
                           surface_label(model, body.node_surface[i]) + " at " + point_label(body.points[i]) +
                           " is not sound: " + reason_text(bad[i]) +
                           "; use a smaller 'wall_layer.thickness' or 'thickness', or a finer surface mesh there",
                           i, reason_text(bad[i]));
    }
    limit_gradation(body, neighbours, params.gradation, pinned, thickness);
  }
  result.warnings = reduction_warnings(model, body, neighbours, thickness, reasons, pinned, params.thickness);
  return result;
}

std::vector<mesh::NodeId> footprint_loop(const BodyMesh& body, const std::vector<std::pair<int, int>>& open,
                                         mesh::NodeId outer_offset) {
  if (open.empty()) return {};
  std::map<int, int> next;
  for (const auto& [a, b] : open)
    if (!next.emplace(a, b).second)
      throw NearFieldError("near field: the body's root passes twice through the node at " +
                           point_label(body.points[a]) + "; the wall footprint must be one simple loop");
  std::vector<mesh::NodeId> loop;
  int v = open.front().first;
  do {
    loop.push_back(static_cast<mesh::NodeId>(v) + outer_offset);
    const auto it = next.find(v);
    if (it == next.end() || loop.size() > open.size())
      throw NearFieldError("near field: the body's root edges near " + point_label(body.points[v]) +
                           " do not form a closed loop on the wall");
    v = it->second;
  } while (v != open.front().first);
  if (loop.size() != open.size())
    throw NearFieldError("near field: the body meets the wall in more than one loop (" + std::to_string(open.size()) +
                         " root edges, first loop " + std::to_string(loop.size()) +
                         "); one wing per wall is supported");
  return loop;
}

}  // namespace semimesh::nearfield::detail
