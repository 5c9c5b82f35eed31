#include "init_from_cad.hpp"

#include "model_as_run.hpp"
#include "unit_doubt.hpp"

#include "semimesh/cad/labels.hpp"
#include "semimesh/nearfield/detail/trailing_edge.hpp"
#include "semimesh/pipeline/pipeline.hpp"
#include "semimesh/surface/cad_roles.hpp"
#include "semimesh/surface/shell_size_limit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>
#include <string>

namespace semimesh::app {
namespace {

// A role entry: the surface's name, or "#id" when another surface has the same name.
std::string surface_entry(const cad::Model& model, int s) {
  const std::string& name = model.surface(s).name();
  return !name.empty() && name != "auto" && model.find_surface(name) == s ? name : fmt::format("#{}", s);
}

std::vector<std::string> surface_entries(const cad::Model& model, const std::vector<int>& surfaces) {
  std::vector<std::string> entries;
  for (int s : surfaces) entries.push_back(surface_entry(model, s));
  return entries;
}

// Four significant digits: what a user would write, and plenty for a size.
double round_to_4_digits(double x) { return std::stod(fmt::format("{:.4g}", x)); }

// The body's largest edge where no curve names its leading or trailing edge: the paper's sizes
// (chord-scaled) resolve the chord through le_size and te_size on those curves; without them only
// the curvature refines, and the flat mid-chord would get two edges.
constexpr double kUnnamedMaxSizeChords = 0.125;

// Whether the model names the curves le_size and te_size act on (a generated wing's do).
bool names_its_edges(const cad::Model& model) {
  for (int c = 0; c < model.num_curves(); ++c)
    for (const char* name : {"leading_edge", "trailing_edge", "te_upper", "te_lower"})
      if (model.curve(c).name() == name) return true;
  return false;
}

void scale_lengths(pipeline::Config& config, double factor) {
  for (const pipeline::ConfigSection& section : pipeline::config_sections())
    for (const params::Key<pipeline::Config>& key : section.keys)
      for (const std::string& length : length_keys())
        if (section.name + "." + key.name == length)
          key.set(config, round_to_4_digits(std::get<double>(key.get(config)) * factor));
}

// The trailing edge an H-type wake block can stand on: the base, or a sharp trailing edge (a curve
// between two body surfaces leaving the wall in the root's downstream half; the leading edge of a
// two-face skin is the other such curve, in the upstream half). {base, crack}, -1 for what is not
// there. The near field finds these the same way (h_shell.hpp).
std::pair<int, int> trailing_edge(const cad::Model& model, const surface::CadRoles& roles) {
  if (roles.te_base) return {*roles.te_base, -1};
  const cad::Vec3 n = roles.span_direction, x = cad::Vec3::UnitX();
  const cad::Vec3 streamwise = (x - x.dot(n) * n).normalized();
  auto is_body = [&](int s) { return std::binary_search(roles.body.begin(), roles.body.end(), s); };
  auto on_wall = [&](int vertex) {
    for (int c : model.curves_of_vertex(vertex))
      for (const cad::SurfaceUse& u : model.surfaces_of_curve(c))
        if (u.surface == roles.wall) return true;
    return false;
  };
  double lo = 1e300, hi = -1e300, sharp = -1e300;
  int sharp_curve = -1;
  for (int c = 0; c < model.num_curves(); ++c) {
    const auto& uses = model.surfaces_of_curve(c);
    if (uses.size() != 2) continue;
    const int a = uses[0].surface, b = uses[1].surface;
    const bool root = (a == roles.wall && is_body(b)) || (b == roles.wall && is_body(a));
    const bool body_body = a != b && is_body(a) && is_body(b);
    for (int v : model.curve_vertices(c)) {
      const double along = model.vertex(v).point.dot(streamwise);
      if (root) lo = std::min(lo, along), hi = std::max(hi, along);
      if (body_body && on_wall(v) && along > sharp) sharp = along, sharp_curve = c;
    }
  }
  return {-1, sharp_curve >= 0 && sharp > 0.5 * (lo + hi) ? sharp_curve : -1};
}

std::string surface_labels(const cad::Model& model, const std::vector<int>& surfaces) {
  std::string text;
  for (int s : surfaces) text += (text.empty() ? "" : ", ") + cad::surface_label(model, s);
  return text;
}

// The near field init writes, and the summary line saying why: H where the body's trailing edge
// (a base of one or several faces, or a sharp edge) runs from the root to the tip, C where it goes
// on past its base or root curve (the run's own check, detail::trailing_edge_continuation, would
// refuse H), else O.
std::pair<std::string, std::string> near_field_topology(const cad::Model& model, const surface::CadRoles& roles) {
  const auto [base, crack] = trailing_edge(model, roles);
  if (base < 0 && crack < 0)
    return {"O", "nearfield.topology = \"O\": no trailing-edge base nor sharp trailing edge for an H-type wake block.\n"};
  const nearfield::BodyRoles body{roles.body, roles.wall};
  const std::vector<int> faces = base >= 0 ? nearfield::detail::trailing_edge_base(model, body, base) : std::vector<int>{};
  const int past = nearfield::detail::trailing_edge_continuation(model, body, faces, crack);
  if (past < 0 && faces.size() > 1)
    return {"H", fmt::format("nearfield.topology = \"H\": the body's trailing-edge base, of {} faces forming one strip "
                             "from the root to the tip ({}), carries the wake block.\n",
                             faces.size(), surface_labels(model, faces))};
  if (past < 0)
    return {"H", "nearfield.topology = \"H\": the body has a trailing-edge base or a sharp trailing edge for the wake block.\n"};
  if (base >= 0)
    return {"C", fmt::format("nearfield.topology = \"C\": the trailing edge goes on past its base ({}) into {}, which "
                             "does not face the way the base does and goes on along the span; the H-type's wake block "
                             "stands on base faces forming one strip from the root to the tip.\n",
                             surface_labels(model, faces), cad::surface_label(model, past))};
  return {"C", fmt::format("nearfield.topology = \"C\": the sharp trailing edge goes on past its root curve into {}, "
                           "which does not touch the root and goes on along the span (several spanwise faces, a crank); "
                           "the H-type's wake block stands on one sharp trailing-edge curve from the root to the tip.\n",
                           cad::curve_label(model, past))};
}

}  // namespace

const std::vector<std::string>& length_keys() {
  static const std::vector<std::string> keys = {
      "nearfield.thickness", "wall_layer.thickness", "wake.length",       "wake.gap",           "sizing.max_size",
      "sizing.min_size",     "sizing.le_size",       "sizing.te_size",    "farfield.box_size",  "farfield.wall_size"};
  return keys;
}

CadConfig config_for_cad(const cad::Registry& registry, const std::string& cad_path, const std::string& source_text) {
  const std::string backend = registry.backend_for_path(cad_path);
  ModelAsRun loaded = load_model_as_run(registry, backend, cad_path);
  const std::unique_ptr<cad::Model>& model = loaded.model;
  CadConfig out;
  pipeline::Config& c = out.config;
  c.geometry.backend = backend;
  c.geometry.source = source_text;
  std::string domain;
  if (loaded.root) {
    // The body alone (no wall sewn to it): its root plane is geometry.wall_plane and a box around
    // it the far field, both built at load as `run` will (and as the model was loaded here).
    c.geometry.wall_plane.point = rounded(loaded.root->point);
    c.geometry.wall_plane.normal = rounded(loaded.root->normal);
    c.geometry.farfield_shape.box_chords = kBoxChords;
    domain = fmt::format("geometry.wall_plane: {}; geometry.farfield = {{box_chords = {}}}: the file holds the body "
                         "only, so the wall and a box around the body are built at load.\n",
                         loaded.root->why, kBoxChords);
  }
  if (loaded.join) {
    // Two overlapping parts (a wing sunk into a fuselage, not joined): joined at load as `run` will.
    c.geometry.join.body = loaded.join->body;
    c.geometry.join.wall = loaded.join->wall;
    c.geometry.farfield_shape.box = loaded.join->box;
    c.farfield.symmetry = loaded.join->symmetry;
    domain = "geometry.join, geometry.farfield = {box}: " + loaded.join->why + ".\n";
  }
  const surface::CadRoles roles = surface::detect_cad_roles(*model);
  c.geometry.units = model->units();
  const std::optional<UnitDoubt> doubt = doubt_unit(roles.chord, model->units());
  if (doubt) {
    c.geometry.units = doubt->likelier;
    out.warnings.push_back(fmt::format("the file's unit '{}' ({}) looks wrong: {}; geometry.units = \"{}\" written "
                                       "(a label: the numbers are kept), check it",
                                       model->units(), model->units_origin(), doubt->why, doubt->likelier));
  }
  c.geometry.body = surface_entries(*model, roles.body);
  c.geometry.wall = surface_entry(*model, roles.wall);
  c.geometry.farfield = surface_entries(*model, roles.farfield);
  if (roles.te_base) c.wake.te_base = surface_entry(*model, *roles.te_base);
  scale_lengths(c, roles.chord);
  // The wake leaves streamwise (x) in the wall's plane: a wall found from a root sewn across gaps
  // leans by the gap's width, and x would point into it.
  const cad::Vec3 x = cad::Vec3::UnitX(), n = roles.span_direction;
  c.wake.direction = rounded((x - x.dot(n) * n).normalized());
  if (!names_its_edges(*model)) {
    c.sizing.size.max_size = round_to_4_digits(kUnnamedMaxSizeChords * roles.chord);
    c.sizing.size.le_size = c.sizing.size.te_size = 0.0;
  }
  // The paper's near field where the body allows it; its wall layer and wake keys are the defaults
  // scaled by the chord (as every length here).
  const auto [topology, topology_why] = near_field_topology(*model, roles);
  c.nearfield.topology = topology;
  out.summary = fmt::format("Written by `semimesh init --cad {}`: the roles found in the file, and the lengths of the\n"
                            "paper's case (chord 1) times the body's root chord {:.6g} {}.\n",
                            cad_path, roles.chord, model->units());
  // A curved body under the shell's straight outer face: where the body turns faster than the
  // scaled sizes allow (a small trailing-edge or tip radius), `run` refuses min_size. Take what
  // its shell limit asks for there, with 5% to spare (the same computation `run` makes).
  if (c.highorder.order > 1) {
    const double smallest = surface::smallest_shell_size(
        *model, {c.nearfield.shell.thickness, roles.body}, c.sizing.size.max_size);
    if (smallest < c.sizing.size.min_size) {
      c.sizing.size.min_size = round_to_4_digits(0.95 * smallest);
      out.summary += fmt::format("sizing.min_size = {:.4g}: what the shell of thickness {:.4g} needs where the body "
                                 "turns fastest (the chord-scaled default would be refused).\n",
                                 c.sizing.size.min_size, c.nearfield.shell.thickness);
    }
  }
  if (!names_its_edges(*model))
    out.summary += fmt::format("sizing.max_size = {:.4g} (chord / 8), le_size = te_size = 0: no curve of the file is named "
                               "leading_edge or trailing_edge, so only the body's curvature and this size resolve the "
                               "chord.\n",
                               c.sizing.size.max_size);
  out.summary += topology_why;
  if (!model->surface(roles.wall).is_planar())
    out.summary += "The wall is curved (a fuselage, a hub): the junction, the wall layer and the wake's gap follow it.\n";
  if (doubt) out.summary += fmt::format("geometry.units = \"{}\", not the file's '{}': {}.\n", doubt->likelier, model->units(), doubt->why);
  out.summary += domain;
  for (const std::string& repair : model->repairs()) out.summary += "The file as loaded: " + repair + ".\n";
  out.summary += surface::describe_cad_roles(*model, roles);
  return out;
}

}  // namespace semimesh::app
