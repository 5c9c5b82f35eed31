// The configuration: parse_config reads the TOML (config_reading.hpp) section by section
// (config_keys.cpp) and checks the conditions between keys (config_checks.hpp); the boundary
// layer's figures derived from it (y+, the effective ratios).
#include "semimesh/pipeline/config.hpp"

#include "config_checks.hpp"
#include "config_reading.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace semimesh::pipeline {

using detail::Origin;
using detail::Section;

Config parse_config(const std::string& text, const std::string& source_name, const std::string& base_directory,
                    const std::vector<std::string>& overrides) {
  toml::table root;
  try {
    root = toml::parse(text, source_name);
  } catch (const toml::parse_error& e) {
    throw ConfigError("config error: " + source_name + ":" + std::to_string(e.source().begin.line) + ": " +
                      std::string(e.description()));
  }
  Origin origin{source_name, {}};
  for (const std::string& o : overrides) detail::apply_override(root, o, origin);

  std::set<std::string> top;
  for (const ConfigSection& section : config_sections())
    if (section.name.find('.') == std::string::npos) top.insert(section.name);
  for (const auto& [k, node] : root)
    if (!top.count(std::string(k.str()))) {
      std::string names;
      for (const ConfigSection& section : config_sections())
        if (top.count(section.name)) names += (names.empty() ? "" : ", ") + section.name;
      throw ConfigError("config error: " + detail::location(origin, std::string(k.str()), &node) + ": unknown key " +
                        std::string(k.str()) + " (sections: " + names + ")");
    }

  // Sections in file order; a nested one ([geometry.naca]) is read from its parent's table.
  Config c;
  std::map<std::string, std::unique_ptr<Section>> sections;
  for (const ConfigSection& section : config_sections()) {
    const auto dot = section.name.rfind('.');
    std::unique_ptr<Section> s;
    if (dot == std::string::npos)
      s = std::make_unique<Section>(origin, root, section.name, section.name);
    else
      s = std::make_unique<Section>(
          sections.at(section.name.substr(0, dot))->sub(section.name.substr(dot + 1), section.or_value));
    std::set<std::string> table_or_value;
    for (const ConfigSection& child : config_sections())
      if (child.or_value && child.name.rfind(section.name + ".", 0) == 0 &&
          child.name.find('.', section.name.size() + 1) == std::string::npos)
        table_or_value.insert(child.name.substr(section.name.size() + 1));
    detail::read_keys(*s, section.keys, c, table_or_value);
    sections[section.name] = std::move(s);
  }
  std::map<std::string, Section*> by_name;
  for (auto& [name, s] : sections) by_name[name] = s.get();
  detail::check_across_keys(c, by_name, base_directory);
  for (const ConfigSection& section : config_sections()) sections.at(section.name)->reject_unknown();
  return c;
}

Config load_config(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError("config error: cannot read " + path + " (missing file or no permission)");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string directory = std::filesystem::absolute(path).parent_path().string();
  return parse_config(text.str(), path, directory, overrides);
}

double flat_plate_skin_friction(double reynolds) { return 0.026 * std::pow(reynolds, -1.0 / 7.0); }

double y_plus_first_cell_height(double y_plus, double reynolds, double length) {
  return y_plus * length / (reynolds * std::sqrt(0.5 * flat_plate_skin_friction(reynolds)));
}

double y_plus_of_height(double height, double reynolds, double length) {
  return height / y_plus_first_cell_height(1.0, reynolds, length);
}

BoundaryLayerConfig resolve_y_plus(BoundaryLayerConfig layer, double chord) {
  if (layer.y_plus && layer.reynolds)
    layer.first_cell_height = y_plus_first_cell_height(*layer.y_plus, *layer.reynolds, layer.reference_length.value_or(chord));
  return layer;
}

double effective_layer_ratio(const BoundaryLayerConfig& layer, double thickness) {
  if (!layer.first_cell_height) return layer.split.ratio;
  const double h1 = *layer.first_cell_height;
  const int n = layer.split.layers;
  // Total height h1 (r^n - 1) / (r - 1) grows monotonically with r: bisection on [1, r_hi].
  auto total = [&](double r) { return std::abs(r - 1.0) < 1e-12 ? h1 * n : h1 * (std::pow(r, n) - 1.0) / (r - 1.0); };
  double lo = 1.0, hi = 2.0;
  while (total(hi) < thickness && hi < 1e6) hi *= 2.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (total(mid) < thickness ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double effective_wall_ratio(const WallLayerConfig& layer) {
  BoundaryLayerConfig as_layer;
  as_layer.split = layer.split;
  as_layer.first_cell_height = layer.first_cell_height;
  return effective_layer_ratio(as_layer, layer.thickness);
}

bool builds_junction(const Config& config) {
  return (config.nearfield.topology == "C" || config.nearfield.topology == "H") && config.wall_layer.thickness > 0.0;
}

}  // namespace semimesh::pipeline
