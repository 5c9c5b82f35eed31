#include "cad_classification.hpp"

#include "semimesh/cad/error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace semimesh::ho::detail {
namespace {

void check_entity(const cad::Model& model, const mesh::CadAttachment& a) {
  const int count = a.kind == mesh::CadAttachment::Vertex  ? model.num_vertices()
                    : a.kind == mesh::CadAttachment::Curve ? model.num_curves()
                                                           : model.num_surfaces();
  if (a.entity < 0 || a.entity >= count)
    throw cad::CadError(cad::CadError::Kind::Geometry,
                        "curve_mesh: a node is attached to CAD entity " + std::to_string(a.entity) +
                            ", which the model (" + std::to_string(count) + " of that kind) does not have");
}

std::vector<int> curves_of(const cad::Model& model, const mesh::CadAttachment& a) {
  if (a.kind == mesh::CadAttachment::Curve) return {a.entity};
  if (a.kind == mesh::CadAttachment::Vertex) return model.curves_of_vertex(a.entity);
  return {};
}

std::vector<int> surfaces_of(const cad::Model& model, const mesh::CadAttachment& a) {
  if (a.kind == mesh::CadAttachment::Surface) return {a.entity};
  std::vector<int> out;
  for (int c : curves_of(model, a))
    for (const cad::SurfaceUse& use : model.surfaces_of_curve(c)) out.push_back(use.surface);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<int> common(std::vector<int> a, std::vector<int> b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  std::vector<int> out;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

}  // namespace

CadPlace classify(const cad::Model& model, const std::vector<mesh::CadAttachment>& vertices, bool allow_curve,
                  const cad::Vec3& probe) {
  for (const auto& a : vertices) {
    if (a.kind == mesh::CadAttachment::None) return {};
    check_entity(model, a);
  }
  if (allow_curve) {
    std::vector<int> curves = curves_of(model, vertices[0]);
    for (std::size_t i = 1; i < vertices.size(); ++i) curves = common(curves, curves_of(model, vertices[i]));
    if (!curves.empty()) return {CadPlace::Curve, curves.front()};
  }
  std::vector<int> surfaces = surfaces_of(model, vertices[0]);
  for (std::size_t i = 1; i < vertices.size(); ++i) surfaces = common(surfaces, surfaces_of(model, vertices[i]));
  if (surfaces.empty()) return {};
  int best = surfaces.front();
  if (surfaces.size() > 1) {
    double best_distance = std::numeric_limits<double>::infinity();
    for (int s : surfaces) {
      const double d = model.surface(s).project(probe).distance;
      if (d < best_distance) best_distance = d, best = s;
    }
  }
  return {CadPlace::Surface, best};
}

double curve_parameter(const cad::Model& model, int curve, const mesh::CadAttachment& a, const cad::Vec3& x,
                       std::optional<double> other_end) {
  const cad::Curve& c = model.curve(curve);
  if (a.kind == mesh::CadAttachment::Curve && a.entity == curve) return a.u;
  if (a.kind == mesh::CadAttachment::Vertex) {
    const auto ends = model.curve_vertices(curve);
    const cad::Interval b = c.bounds();
    if (ends[0] == a.entity && ends[1] == a.entity)
      return other_end && *other_end - b.lo > b.hi - *other_end ? b.hi : b.lo;
    if (ends[0] == a.entity) return b.lo;
    if (ends[1] == a.entity) return b.hi;
  }
  return c.project(x).t;
}

cad::Vec2 surface_parameter(const cad::Model& model, int surface, const mesh::CadAttachment& a, const cad::Vec3& x,
                            const cad::Vec2* guess) {
  if (a.kind == mesh::CadAttachment::Surface && a.entity == surface) return {a.u, a.v};
  const cad::Surface& s = model.surface(surface);
  return guess ? s.project_near(x, *guess).uv : s.project(x).uv;
}

namespace {

/// The parameter direction along which the surface does not move at uv (a pole), or -1.
int pole_direction(const cad::Surface& surface, const cad::Vec2& uv) {
  const cad::SurfaceDerivatives d = surface.derivatives(uv);
  if (d.du.norm() <= 1e-9 * d.dv.norm()) return 0;
  if (d.dv.norm() <= 1e-9 * d.du.norm()) return 1;
  return -1;
}

}  // namespace

void continuous_parameters(const cad::Surface& surface, Eigen::Ref<Eigen::MatrixXd> uv, int count, int vertices) {
  const std::array<std::optional<double>, 2> periods{surface.period(0), surface.period(1)};
  std::vector<int> pole(vertices);
  int reference = -1;
  for (int v = 0; v < vertices; ++v) {
    pole[v] = pole_direction(surface, uv.row(v).transpose());
    if (reference < 0 && pole[v] < 0) reference = v;
  }
  if (reference < 0) return;  // every vertex at a pole: nothing to go by
  for (int d = 0; d < 2; ++d)
    if (periods[d])
      for (int j = 0; j < count; ++j)
        uv(j, d) += std::round((uv(reference, d) - uv(j, d)) / *periods[d]) * *periods[d];
  for (int v = 0; v < vertices; ++v) {
    if (pole[v] < 0) continue;
    double sum = 0.0;
    int others = 0;
    for (int w = 0; w < vertices; ++w)
      if (pole[w] < 0) {
        sum += uv(w, pole[v]);
        ++others;
      }
    uv(v, pole[v]) = sum / others;
  }
}

cad::Vec2 into_box(const cad::Surface& surface, cad::Vec2 uv) {
  const auto box = surface.bounds();
  for (int d = 0; d < 2; ++d)
    if (const std::optional<double> period = surface.period(d)) {
      const cad::Interval& b = box[d];
      const auto outside = [&](double u) { return std::max({b.lo - u, u - b.hi, 0.0}); };
      // The shift by whole periods that lands nearest the box: on a face less than a period wide (a
      // fuselage cut at its plane of symmetry) a parameter at the box's low end computed as a
      // period past it, floored by round-off to the shift before, would land a period past the box's
      // other end, the far side of the surface.
      const double shifted = uv[d] - std::floor((uv[d] - b.lo) / *period) * *period;
      double best = shifted;
      for (const double other : {shifted - *period, shifted + *period})
        if (outside(other) < outside(best)) best = other;
      uv[d] = best;
    }
  return uv;
}

}  // namespace semimesh::ho::detail
