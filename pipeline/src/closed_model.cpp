#include "semimesh/pipeline/closed_model.hpp"

#include "semimesh/cad/labels.hpp"
#include "semimesh/pipeline/config.hpp"

#include <fmt/format.h>

namespace semimesh::pipeline {

std::vector<int> free_curves(const cad::Model& model) {
  std::vector<int> curves;
  for (int c = 0; c < model.num_curves(); ++c) {
    const auto& uses = model.surfaces_of_curve(c);
    const bool bounded = uses.size() == 2 || (uses.size() == 1 && model.curve(c).is_degenerate());
    if (!bounded) curves.push_back(c);
  }
  return curves;
}

std::string free_curves_text(const cad::Model& model, const std::vector<int>& curves, std::size_t shown) {
  std::string text;
  for (std::size_t i = 0; i < curves.size() && i < shown; ++i) {
    const int c = curves[i];
    const auto ends = model.curve_vertices(c);
    const cad::Vec3 &a = model.vertex(ends[0]).point, &b = model.vertex(ends[1]).point;
    std::string faces;
    for (const cad::SurfaceUse& u : model.surfaces_of_curve(c)) faces += (faces.empty() ? "" : ", ") + cad::surface_label(model, u.surface);
    text += fmt::format("{}{} of {} from ({:.6g}, {:.6g}, {:.6g}) to ({:.6g}, {:.6g}, {:.6g})", i ? "; " : "",
                        cad::curve_label(model, c), faces.empty() ? "no surface" : faces, a.x(), a.y(), a.z(), b.x(), b.y(),
                        b.z());
  }
  if (curves.size() > shown) text += fmt::format("; and {} more", curves.size() - shown);
  return text;
}

void require_closed(const cad::Model& model, std::optional<double> sew_tolerance) {
  const std::vector<int> curves = free_curves(model);
  if (curves.empty()) return;
  const std::string tolerance = sew_tolerance ? fmt::format("geometry.sew_tolerance = {}", *sew_tolerance)
                                              : std::string("the default sewing tolerance (1e-6 of the model's diagonal)");
  throw ConfigError(fmt::format("the CAD model is not closed: {} free curve(s), each bounding one face only (faces "
                                "not sewn at {}, or a face missing): {}. Set a larger geometry.sew_tolerance, or "
                                "repair the file",
                                curves.size(), tolerance, free_curves_text(model, curves)));
}

}  // namespace semimesh::pipeline
