#include "semimesh/pipeline/roles.hpp"

#include "semimesh/surface/cad_roles.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace semimesh::pipeline {
namespace {

bool is_auto(const std::vector<std::string>& entries) { return entries.size() == 1 && entries.front() == kAutoRole; }

std::optional<int> id_of(const std::string& entry) {
  if (entry.size() < 2 || entry.front() != '#' ||
      !std::all_of(entry.begin() + 1, entry.end(), [](unsigned char c) { return std::isdigit(c) != 0; }))
    return std::nullopt;
  return std::stoi(entry.substr(1));
}

std::vector<int> surface_refs(const cad::Model& model, const std::string& key, const std::vector<std::string>& entries) {
  std::vector<int> ids;
  for (const std::string& e : entries) ids.push_back(surface_ref(model, key, e));
  return ids;
}

}  // namespace

int surface_ref(const cad::Model& model, const std::string& key, const std::string& entry) {
  if (auto id = model.find_surface(entry)) return *id;
  if (auto id = id_of(entry); id && *id < model.num_surfaces()) return *id;
  std::string names;
  for (int s = 0; s < model.num_surfaces(); ++s) names += fmt::format("{}#{} '{}'", s ? ", " : "", s, model.surface(s).name());
  throw ConfigError("config error: " + key + ": the CAD model has no surface named '" + entry + "' (its surfaces: " +
                    names + "; \"" + kAutoRole + "\" finds the roles from the model)");
}

Roles resolve_roles(const cad::Model& model, const Config& config) {
  const GeometryConfig& g = config.geometry;
  const bool base_needed = config.nearfield.topology == "H";
  const bool detect = is_auto(g.body) || g.wall == kAutoRole || is_auto(g.farfield) ||
                      (base_needed && config.wake.te_base == kAutoRole);
  Roles roles;
  std::optional<surface::CadRoles> found;
  if (g.wall != kAutoRole) roles.wall = surface_ref(model, "geometry.wall", g.wall);
  if (detect) found = surface::detect_cad_roles(model, g.wall != kAutoRole ? std::optional<int>(roles.wall) : std::nullopt);
  if (found) roles.wall = found->wall;
  roles.body = is_auto(g.body) ? found->body : surface_refs(model, "geometry.body", g.body);
  roles.farfield = is_auto(g.farfield) ? found->farfield : surface_refs(model, "geometry.farfield", g.farfield);
  if (base_needed && config.wake.te_base != kAutoRole) roles.te_base = surface_ref(model, "wake.te_base", config.wake.te_base);
  if (base_needed && config.wake.te_base == kAutoRole) roles.te_base = found->te_base;
  return roles;
}

}  // namespace semimesh::pipeline
