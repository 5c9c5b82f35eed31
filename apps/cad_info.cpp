#include "cad_info.hpp"

#include "model_as_run.hpp"

#include "semimesh/cad/error.hpp"
#include "semimesh/cad/trimmed_area.hpp"
#include "semimesh/error.hpp"
#include "semimesh/cad/labels.hpp"
#include "semimesh/nearfield/detail/trailing_edge.hpp"
#include "semimesh/pipeline/closed_model.hpp"
#include "semimesh/surface/cad_roles.hpp"

#include "semimesh/io/json.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>

namespace semimesh::app {
namespace {

using io::json_number;
using io::json_string;

struct SurfaceRow {
  int id;
  std::string name;
  std::string kind;
  cad::TrimmedArea area;
  int loops;
};

std::vector<SurfaceRow> surface_rows(const cad::Model& model) {
  std::vector<SurfaceRow> rows;
  for (int s = 0; s < model.num_surfaces(); ++s) {
    const cad::Surface& surface = model.surface(s);
    rows.push_back(SurfaceRow{s, surface.name(), cad::to_string(surface.kind()), cad::face_area(surface),
                              static_cast<int>(model.loops(s).size())});
  }
  return rows;
}

// The roles the pipeline's "auto" would find, or why there are none; the trailing-edge base's faces
// the H-type's wake block stands on (the root's base and those going on with it to the tip).
struct DetectedRoles {
  std::optional<surface::CadRoles> roles;
  std::string why_not;
  std::vector<int> te_base_faces;
};

DetectedRoles detect_roles(const cad::Model& model) {
  try {
    DetectedRoles d{surface::detect_cad_roles(model), {}, {}};
    if (d.roles->te_base)
      d.te_base_faces = nearfield::detail::trailing_edge_base(model, {d.roles->body, d.roles->wall}, *d.roles->te_base);
    return d;
  } catch (const surface::CadRoleError& e) {
    return {std::nullopt, e.what(), {}};
  }
}

std::string ids_json(const std::vector<int>& ids) {
  std::string text;
  for (int id : ids) text += (text.empty() ? "" : ",") + std::to_string(id);
  return "[" + text + "]";
}

std::string roles_json(const DetectedRoles& d) {
  if (!d.roles) return "{\"found\":false,\"why_not\":" + json_string(d.why_not) + "}";
  const surface::CadRoles& r = *d.roles;
  return fmt::format("{{\"found\":true,\"wall\":{},\"body\":{},\"farfield\":{},\"te_base\":{},\"te_base_faces\":{},"
                     "\"tip\":{},\"span\":{},\"chord\":{}}}",
                     r.wall, ids_json(r.body), ids_json(r.farfield), r.te_base ? std::to_string(*r.te_base) : "null",
                     ids_json(d.te_base_faces), ids_json(r.tip), json_number(r.span), json_number(r.chord));
}

std::string roles_table(const cad::Model& model, const DetectedRoles& d) {
  if (!d.roles) return "roles     not found: " + d.why_not + "\n";
  std::string text = "roles (found from the model, as geometry.body/wall/farfield = \"auto\" would)\n";
  text += surface::describe_cad_roles(model, *d.roles);
  if (d.te_base_faces.size() > 1) {
    std::string faces;
    for (int s : d.te_base_faces) faces += (faces.empty() ? "" : ", ") + cad::surface_label(model, s);
    text += "te faces  " + faces + ": the base's faces from the root to the tip, the H-type's wake block on all\n";
  }
  return text;
}

std::string bbox_json(const cad::BBox& b) {
  if (b.empty()) return "null";
  return fmt::format("[{},{},{},{},{},{}]", json_number(b.lo.x()), json_number(b.lo.y()), json_number(b.lo.z()),
                     json_number(b.hi.x()), json_number(b.hi.y()), json_number(b.hi.z()));
}

std::string report_json(const std::string& backend, const cad::Model& model, const std::vector<SurfaceRow>& rows,
                        const DetectedRoles& roles, bool built_at_load) {
  std::string repairs;
  for (const std::string& r : model.repairs()) repairs += (repairs.empty() ? "" : ",") + json_string(r);
  std::string list;
  for (const SurfaceRow& r : rows)
    list += fmt::format("{}{{\"id\":{},\"name\":{},\"kind\":{},\"area\":{}}}", list.empty() ? "" : ",", r.id,
                        json_string(r.name), json_string(r.kind), json_number(r.area.area));
  return fmt::format(
      "{{\"backend\":{},\"vertices\":{},\"curves\":{},\"surfaces\":{},\"bbox\":{},\"closed\":{},\"units\":{},"
      "\"units_origin\":{},\"repairs\":[{}],\"wall_and_box_built\":{},"
      "\"surface_list\":[{}],\"roles\":{}}}\n",
      json_string(backend), model.num_vertices(), model.num_curves(), model.num_surfaces(), bbox_json(model.bbox()),
      model.is_closed() ? "true" : "false", json_string(model.units()), json_string(model.units_origin()), repairs,
      built_at_load ? "true" : "false", list, roles_json(roles));
}

std::string report_table(const std::string& backend, const std::string& source, const ModelAsRun& loaded,
                         const std::vector<SurfaceRow>& rows, const DetectedRoles& roles) {
  const cad::Model& model = *loaded.model;
  std::string out;
  out += fmt::format("source    {}\n", source.empty() ? "(generated)" : source);
  out += fmt::format("backend   {}\n", backend);
  if (loaded.root)
    out += fmt::format("built     the file holds the body only: the wall plane at its root and a box of {} chords "
                       "around it built at load, as `init --cad` configures `run` (the ids below are the run's); "
                       "the plane: {}\n",
                       kBoxChords, loaded.root->why);
  if (loaded.join)
    out += fmt::format("built     {}, as `init --cad` configures `run` (the ids below are the run's)\n", loaded.join->why);
  out += fmt::format("units     {}: {} (scale applied at load: {})\n", model.units(),
                     model.units_origin().empty() ? "as the backend says" : model.units_origin(), model.scale_applied());
  for (const std::string& repair : model.repairs()) out += fmt::format("repaired  {}\n", repair);
  const std::vector<int> free = pipeline::free_curves(model);
  out += fmt::format("closed    {}\n", free.empty() ? std::string("yes (every curve bounds two surfaces)")
                                                    : fmt::format("no: {} free curve(s): {}", free.size(),
                                                                  pipeline::free_curves_text(model, free)));
  const cad::BBox& b = model.bbox();
  if (b.empty()) out += "bbox      (empty)\n";
  else
    out += fmt::format("bbox      [{:.6g}, {:.6g}, {:.6g}] .. [{:.6g}, {:.6g}, {:.6g}]\n", b.lo.x(), b.lo.y(), b.lo.z(),
                       b.hi.x(), b.hi.y(), b.hi.z());
  out += fmt::format("counts    {} vertices, {} curves, {} surfaces\n\n", model.num_vertices(), model.num_curves(),
                     model.num_surfaces());
  out += roles_table(model, roles) + "\n";

  out += fmt::format("{:>4}  {:<16} {:<10} {:>14} {:>10} {:>5}\n", "id", "surface", "kind", "area", "+/-", "loops");
  for (const SurfaceRow& r : rows)
    out += fmt::format("{:>4}  {:<16} {:<10} {:>14.8g} {:>10.2g} {:>5}\n", r.id, r.name, r.kind, r.area.area,
                       r.area.error_estimate, r.loops);

  out += fmt::format("\n{:>4}  {:<16} {:<10} {:>14} {:>9}  {}\n", "id", "curve", "kind", "length", "vertices", "surfaces");
  for (int c = 0; c < model.num_curves(); ++c) {
    const cad::Curve& curve = model.curve(c);
    auto ends = model.curve_vertices(c);
    std::string users;
    for (const cad::SurfaceUse& u : model.surfaces_of_curve(c)) users += fmt::format("{}{}{}", users.empty() ? "" : " ", u.surface, u.forward ? "+" : "-");
    out += fmt::format("{:>4}  {:<16} {:<10} {:>14.8g} {:>4}-{:<4}  {}\n", c, curve.name(), cad::to_string(curve.kind()),
                       curve.length(), ends[0], ends[1], users);
  }
  return out;
}

// A file: the model `run` loads for it (a body-only file with its wall and box), so the ids are the
// run's. The file as it is when that cannot be built (the roles' row then says why), and for a
// generator's parameters.
ModelAsRun model_for_info(const cad::Registry& registry, const std::string& backend, const std::string& path,
                          const cad::Params& params) {
  if (!path.empty()) {
    try {
      return load_model_as_run(registry, backend, path, params);
    } catch (const InputError&) {
    } catch (const cad::CadError&) {
    }
  }
  return {registry.load(backend, cad::Source{path, params}), std::nullopt, std::nullopt};
}

}  // namespace

cad::Params parse_params(const std::vector<std::string>& key_values) {
  cad::Params params;
  for (const std::string& kv : key_values) {
    auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0)
      throw cad::CadError(cad::CadError::Kind::BadParameter, "--param '" + kv + "': expected key=value, e.g. naca.code=0012");
    params.set(kv.substr(0, eq), kv.substr(eq + 1));
  }
  return params;
}

std::string choose_backend(const cad::Registry& registry, const CadInfoOptions& options) {
  if (!options.backend.empty()) return options.backend;
  if (!options.source.empty()) return registry.backend_for_path(options.source);
  return "naca";
}

void run_cad_info(const cad::Registry& registry, const CadInfoOptions& options, std::ostream& out) {
  const std::string backend = choose_backend(registry, options);
  const cad::Params params = parse_params(options.params);
  ModelAsRun loaded = model_for_info(registry, backend, options.source, params);
  std::vector<SurfaceRow> rows = surface_rows(*loaded.model);
  const DetectedRoles roles = detect_roles(*loaded.model);
  out << (options.json ? report_json(backend, *loaded.model, rows, roles, loaded.root.has_value() || loaded.join.has_value())
                       : report_table(backend, options.source, loaded, rows, roles));
}

}  // namespace semimesh::app
