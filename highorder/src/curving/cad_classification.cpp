#include "cad_classification.hpp"

#include "semimesh/cad/error.hpp"

#include <algorithm>
#include <iterator>
#include <limits>
#include <string>

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
                       bool prefer_end) {
  const cad::Curve& c = model.curve(curve);
  if (a.kind == mesh::CadAttachment::Curve && a.entity == curve) return a.u;
  if (a.kind == mesh::CadAttachment::Vertex) {
    const auto ends = model.curve_vertices(curve);
    const cad::Interval b = c.bounds();
    if (ends[0] == a.entity && ends[1] == a.entity) return prefer_end ? b.hi : b.lo;
    if (ends[0] == a.entity) return b.lo;
    if (ends[1] == a.entity) return b.hi;
  }
  return c.project(x).t;
}

cad::Vec2 surface_parameter(const cad::Model& model, int surface, const mesh::CadAttachment& a, const cad::Vec3& x,
                            const cad::Vec2* guess) {
  if (a.kind == mesh::CadAttachment::Surface && a.entity == surface) return {a.u, a.v};
  const cad::Surface& s = model.surface(surface);
  return guess ? s.project(x, *guess).uv : s.project(x).uv;
}

}  // namespace semimesh::ho::detail
