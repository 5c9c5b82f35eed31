#include "semimesh/pipeline/config.hpp"

#include "semimesh/pipeline/output_formats.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace semimesh::pipeline {
namespace {

// Where each value came from, so errors can point at it.
struct Origin {
  std::string source_name;
  std::map<std::string, std::string> overrides;  // dotted key -> the --set text that set it
};

std::string location(const Origin& origin, const std::string& key, const toml::node* node) {
  auto o = origin.overrides.find(key);
  if (o != origin.overrides.end()) return "--set " + o->second;
  if (node && node->source().begin.line > 0) return origin.source_name + ":" + std::to_string(node->source().begin.line);
  return origin.source_name;
}

std::string value_text(const toml::node& node) {
  if (auto* s = node.as_string()) return '"' + s->get() + '"';
  if (auto* d = node.as_floating_point()) return fmt::format("{}", d->get());  // shortest form: 0.1, not 0.1000...01
  std::ostringstream out;
  node.visit([&](const auto& v) { out << v; });
  return out.str();
}

[[noreturn]] void reject(const Origin& origin, const std::string& key, const toml::node* node, const std::string& expected) {
  std::string text = "config error: " + location(origin, key, node) + ": " + key;
  if (node) text += " = " + value_text(*node);
  throw ConfigError(text + ": expected " + expected);
}

// One [section] of the file: typed reads that remember which keys were used, so that anything
// left over is reported as unknown.
class Section {
 public:
  /// The table `parent[key]`, called `name` in messages (its dotted path).
  Section(const Origin& origin, const toml::table& parent, const std::string& key, const std::string& name,
          bool or_value = false)
      : origin_(origin), name_(name) {
    const toml::node* node = parent.get(key);
    if (node && !node->is_table() && !or_value) reject(origin, name, node, "a table [" + name + "]");
    table_ = node ? node->as_table() : nullptr;
  }

  std::string key(const std::string& k) const { return name_ + "." + k; }
  const Origin& origin() const { return origin_; }

  const toml::node* take(const std::string& k) {
    known_.insert(k);
    return table_ ? table_->get(k) : nullptr;
  }

  /// A nested table [name.sub] read by its own Section.
  Section sub(const std::string& k, bool or_value = false) {
    known_.insert(k);
    static const toml::table empty;
    return Section(origin_, table_ ? *table_ : empty, k, key(k), or_value);
  }

  /// Whether the key holds a table (read as a section of its own).
  bool holds_table(const std::string& k) const { return table_ && table_->get(k) && table_->get(k)->is_table(); }

  /// Throws when `ok` is false, naming the key (which must have been read) and what was expected.
  void require(bool ok, const std::string& k, const std::string& expected) const {
    if (!ok) reject(origin_, key(k), table_ ? table_->get(k) : nullptr, expected);
  }

  bool has(const std::string& k) const { return table_ && table_->contains(k); }

  /// Throws on the first key (in file order) that no read asked for.
  void reject_unknown() const {
    if (!table_) return;
    const toml::node* first = nullptr;
    std::string first_key;
    for (const auto& [k, node] : *table_) {
      if (known_.count(std::string(k.str()))) continue;
      if (!first || node.source().begin.line < first->source().begin.line) {
        first = &node;
        first_key = std::string(k.str());
      }
    }
    if (!first) return;
    std::string keys;
    for (const auto& k : known_) keys += (keys.empty() ? "" : ", ") + k;
    throw ConfigError("config error: " + location(origin_, key(first_key), first) + ": unknown key " + key(first_key) +
                      " (known keys of [" + name_ + "]: " + keys + ")");
  }

 private:
  const Origin& origin_;
  std::string name_;
  const toml::table* table_ = nullptr;
  std::set<std::string> known_;
};

const ConfigSection* find_section(const std::string& name) {
  for (const ConfigSection& s : config_sections())
    if (s.name == name) return &s;
  return nullptr;
}

// In the table of a section of alternatives, drops every alternative but `chosen` when it is one.
void keep_alternative(toml::table& table, const ConfigSection& section, const std::string& chosen) {
  std::set<std::string> names;
  for (const auto& k : section.keys) names.insert(k.name);
  for (const ConfigSection& s : config_sections())
    if (s.name.rfind(section.name + ".", 0) == 0 && s.name.find('.', section.name.size() + 1) == std::string::npos)
      names.insert(s.name.substr(section.name.size() + 1));
  if (!names.count(chosen)) return;
  for (const std::string& other : names)
    if (other != chosen) table.erase(other);
}

// Sets `dotted.key` in `root` to the TOML value of `value_text` (a bare word becomes a string).
void apply_override(toml::table& root, const std::string& assignment, Origin& origin) {
  const auto eq = assignment.find('=');
  auto trim = [](std::string s) {
    const auto b = s.find_first_not_of(" \t");
    const auto e = s.find_last_not_of(" \t");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
  };
  const std::string key = eq == std::string::npos ? std::string() : trim(assignment.substr(0, eq));
  if (key.empty() || key.front() == '.' || key.back() == '.' || key.find("..") != std::string::npos)
    throw ConfigError("config error: --set " + assignment + ": expected key=value with a dotted key, e.g. "
                      "boundary_layer.ratio=1.5");
  const std::string text = trim(assignment.substr(eq + 1));

  toml::table parsed;
  try {
    parsed = toml::parse("value = " + text);
  } catch (const toml::parse_error&) {
    parsed = toml::table{{"value", text}};
  }

  toml::table* table = &root;
  std::string::size_type start = 0;
  for (auto dot = key.find('.'); dot != std::string::npos; start = dot + 1, dot = key.find('.', start)) {
    const std::string part = key.substr(start, dot - start);
    const ConfigSection* section = find_section(key.substr(0, dot));
    toml::node* next = table->get(part);
    // A key that holds a value or a table (geometry.farfield: surface names, or the far field to
    // build): a --set inside the table replaces the file's value.
    if (next && !next->is_table() && section && section->or_value) next = nullptr;
    if (!next) next = &table->insert_or_assign(part, toml::table{}).first->second;
    if (!next->is_table())
      throw ConfigError("config error: --set " + assignment + ": " + key.substr(0, dot) + " is a value, not a table");
    table = next->as_table();
    if (section && section->alternatives)
      keep_alternative(*table, *section, key.substr(dot + 1, key.find('.', dot + 1) - dot - 1));
  }
  table->insert_or_assign(key.substr(start), std::move(*parsed.get("value")));
  origin.overrides[key] = assignment;
}

// The TOML node as a params::Value of the key's type, or a rejection naming what was expected.
params::Value value_of(const Origin& origin, const std::string& key, const toml::node& n, params::Type type,
                       std::size_t count) {
  const std::string expected = params::type_text(type, count);
  switch (type) {
    case params::Type::Real:
      if (auto v = n.value<double>(); v && (n.is_floating_point() || n.is_integer()) && std::isfinite(*v)) return *v;
      break;
    case params::Type::Integer:
      if (auto* v = n.as_integer(); v && v->get() >= -1000000000 && v->get() <= 1000000000)
        return static_cast<long long>(v->get());
      break;
    case params::Type::Boolean:
      if (n.is_boolean()) return n.as_boolean()->get();
      break;
    case params::Type::String:
      if (n.is_string()) return n.as_string()->get();
      break;
    case params::Type::Strings:
      if (n.is_string()) return std::vector<std::string>{n.as_string()->get()};  // a list of one, e.g. body = "auto"
      if (const toml::array* a = n.as_array(); a && !a->empty() && a->is_homogeneous(toml::node_type::string)) {
        std::vector<std::string> out;
        for (const toml::node& e : *a) out.push_back(e.as_string()->get());
        return out;
      }
      break;
    case params::Type::Reals:
      if (const toml::array* a = n.as_array(); a && (count == 0 || a->size() == count)) {
        std::vector<double> out;
        for (const toml::node& e : *a) {
          auto v = e.value<double>();
          if (!v || !std::isfinite(*v)) reject(origin, key, &n, expected);
          out.push_back(*v);
        }
        return out;
      }
      break;
  }
  reject(origin, key, &n, expected);
}

// Reads every key of a table that the section holds: type, then range (as the table writes it).
template <class P>
void read_keys(Section& s, const params::Table<P>& table, P& target, const std::set<std::string>& table_or_value = {}) {
  for (const params::Key<P>& k : table) {
    if (table_or_value.count(k.name) && s.holds_table(k.name)) continue;  // its own section reads it
    const toml::node* n = s.take(k.name);
    if (!n) continue;
    const params::Value v = value_of(s.origin(), s.key(k.name), *n, k.type, k.count);
    if (!params::in_range(v, k.range)) reject(s.origin(), s.key(k.name), n, params::expected_text(k.range, k.type));
    k.set(target, v);
  }
}

template <class Outer, class Inner>
void append(params::Table<Outer>& table, Inner Outer::*member, const params::Table<Inner>& inner) {
  for (auto& k : params::nested(member, inner)) table.push_back(std::move(k));
}

params::Table<Config> geometry_keys() {
  params::Table<GeometryConfig> g = {
      params::string("backend", &GeometryConfig::backend, "non-empty",
                     "CAD kernel from the registry: naca (analytic wing), occ (OpenCASCADE), vendor"),
      params::string("source", &GeometryConfig::source, "",
                     "CAD file, relative to the config file's folder; empty: the generated wing"),
      params::string("units", &GeometryConfig::units,
                     "\"auto\" | \"mm\" | \"cm\" | \"m\" | \"km\" | \"um\" | \"in\" | \"ft\" | \"chord\"",
                     "the unit of the model's numbers (a CAD file's after scale), overriding the one the file declares; "
                     "\"auto\": the declared one (chord for a generated wing). Sizes in this config are in it"),
      params::real("scale", &GeometryConfig::scale, "> 0", "factor applied to a CAD file's coordinates at load"),
      params::real("sew_tolerance", &GeometryConfig::sew_tolerance, "> 0",
                   "CAD file: faces whose edges lie closer than this (model units) are sewn together; unset: 1e-6 "
                   "of the model's diagonal"),
      params::strings("body", &GeometryConfig::body, "non-empty",
                      "surfaces wrapped by the near-field shell: names, ids (\"#7\") or \"auto\" (found from the model)"),
      params::string("wall", &GeometryConfig::wall, "non-empty",
                     "the planar wall the body stands on: a name, an id or \"auto\" (the face holding the root loop)"),
      params::strings("farfield", &GeometryConfig::farfield, "non-empty",
                      "the outer boundary's surfaces: names, ids or \"auto\" (every face neither body nor wall); or "
                      "a table: the far field to build around a body-only file ([geometry.farfield])"),
  };
  params::Table<Config> table;
  append(table, &Config::geometry, g);
  return table;
}

params::Table<Config> wall_plane_keys() {
  params::Table<WallPlaneConfig> w = {
      params::reals("point", &WallPlaneConfig::point, "", "a point of the wall plane (model units)"),
      params::reals("normal", &WallPlaneConfig::normal, "", "the plane's normal, pointing into the fluid"),
  };
  params::Table<GeometryConfig> g;
  append(g, &GeometryConfig::wall_plane, w);
  params::Table<Config> table;
  append(table, &Config::geometry, g);
  return table;
}

params::Table<Config> farfield_shape_keys() {
  params::Table<FarFieldShapeConfig> f = {
      params::reals("box", &FarFieldShapeConfig::box, "", "[xmin, ymin, zmin, xmax, ymax, zmax], each min < max"),
      params::real("box_chords", &FarFieldShapeConfig::box_chords, "> 0",
                   "a box this many root chords around the body's bounding box"),
  };
  params::Table<GeometryConfig> g;
  append(g, &GeometryConfig::farfield_shape, f);
  params::Table<Config> table;
  append(table, &Config::geometry, g);
  return table;
}

params::Table<Config> farfield_sphere_keys() {
  params::Table<FarFieldSphereConfig> s = {
      params::reals("centre", &FarFieldSphereConfig::centre, "", "the sphere's centre"),
      params::real("radius", &FarFieldSphereConfig::radius, "> 0", "the sphere's radius"),
  };
  params::Table<FarFieldShapeConfig> f;
  append(f, &FarFieldShapeConfig::sphere, s);
  params::Table<GeometryConfig> g;
  append(g, &GeometryConfig::farfield_shape, f);
  params::Table<Config> table;
  append(table, &Config::geometry, g);
  return table;
}

params::Table<Config> naca_keys() {
  params::Table<NacaConfig> n = {
      params::string("code", &NacaConfig::code, "", "NACA 4-digit section MPTT"),
      params::real("chord", &NacaConfig::chord, "> 0", "root chord"),
      params::real("span", &NacaConfig::span, "> 0", "wing height above the wall z = 0"),
      params::real("taper", &NacaConfig::taper, "> 0", "tip chord / root chord"),
      params::real("sweep", &NacaConfig::sweep, "(-80, 80)", "leading-edge sweep, degrees"),
      params::string("te", &NacaConfig::te, "\"blunt\" | \"sharp\"",
                     "squared-off trailing edge (with a te_base face) or closed"),
      params::string("tip", &NacaConfig::tip, "\"flat\" | \"round\"",
                     "flat tip cap, or round: the tip section revolved about its camber line (backend naca)"),
      params::reals("box", &NacaConfig::box, "",
                    "far-field box [xmin, ymin, zmin, xmax, ymax, zmax], each min < max, zmin = 0"),
  };
  params::Table<GeometryConfig> g;
  append(g, &GeometryConfig::naca, n);
  params::Table<Config> table;
  append(table, &Config::geometry, g);
  return table;
}

params::Table<Config> nearfield_keys() {
  params::Table<NearFieldConfig> n = {
      params::string("topology", &NearFieldConfig::topology, "\"O\" | \"C\" | \"H\"",
                     "near-field partition: O one prism layer, C plus the root junction and the wall layer, H plus the wake block"),
  };
  append(n, &NearFieldConfig::shell, nearfield::shell_keys());
  append(n, &NearFieldConfig::junction, nearfield::junction_keys());
  params::Table<Config> table;
  append(table, &Config::nearfield, n);
  return table;
}

params::Table<Config> boundary_layer_keys() {
  params::Table<BoundaryLayerConfig> b;
  append(b, &BoundaryLayerConfig::split, ho::layer_keys());
  b.push_back(params::real("first_cell_height", &BoundaryLayerConfig::first_cell_height, "> 0",
                           "instead of ratio: height of the first layer"));
  b.push_back(params::reals("ratio_line", &BoundaryLayerConfig::ratio_line, "",
                            "[xa, ya, za, xb, yb, zb]: the ratio varies linearly from A to B (with ratio_end)"));
  b.push_back(params::real("ratio_end", &BoundaryLayerConfig::ratio_end, ">= 1", "the ratio at B of ratio_line"));
  b.push_back(params::real("y_plus", &BoundaryLayerConfig::y_plus, "> 0",
                           "instead of ratio or first_cell_height: the first cell's y+ (with reynolds)"));
  b.push_back(params::real("reynolds", &BoundaryLayerConfig::reynolds, "> 0",
                           "Reynolds number based on reference_length, for y_plus"));
  b.push_back(params::real("reference_length", &BoundaryLayerConfig::reference_length, "> 0",
                           "length the Reynolds number is based on; unset: the chord"));
  params::Table<Config> table;
  append(table, &Config::boundary_layer, b);
  return table;
}

params::Table<Config> wall_layer_keys() {
  params::Table<WallLayerConfig> w = {
      params::real("thickness", &WallLayerConfig::thickness, ">= 0",
                   "C: the wall layer's thickness δ_wall, model units; 0: a slip wall (no wall layer, the O-type root)"),
  };
  append(w, &WallLayerConfig::split, ho::layer_keys());
  w.push_back(params::real("first_cell_height", &WallLayerConfig::first_cell_height, "> 0",
                           "instead of ratio: height of the first wall layer"));
  w.push_back(params::reals("ratio_line", &WallLayerConfig::ratio_line, "",
                            "[xa, ya, za, xb, yb, zb]: the wall ratio varies linearly from A to B (with ratio_end)"));
  w.push_back(params::real("ratio_end", &WallLayerConfig::ratio_end, ">= 1", "the wall ratio at B of ratio_line"));
  params::Table<Config> table;
  append(table, &Config::wall_layer, w);
  return table;
}

params::Table<Config> sizing_keys() {
  params::Table<SizingConfig> z;
  append(z, &SizingConfig::size, surface::size_keys());
  z.push_back(params::integer("chordwise", &SizingConfig::chordwise, ">= 0",
                              "segments on each root/tip section curve (NACA curve names); 0: from the size field"));
  z.push_back(params::integer("spanwise", &SizingConfig::spanwise, ">= 0",
                              "segments on each spanwise edge (NACA curve names); 0: from the size field"));
  params::Table<Config> table;
  append(table, &Config::sizing, z);
  return table;
}

params::Table<Config> output_keys() {
  std::vector<std::string> names;
  for (const OutputFormat& f : output_formats()) names.push_back(f.name);
  params::Table<OutputConfig> o = {
      params::strings("formats", &OutputConfig::formats, "each of " + params::choice_range(names),
                      "mesh files to write, each format at most once"),
      params::choice("target", &OutputConfig::target, {{"any", OutputTarget::Any}, {"pyfr", OutputTarget::Pyfr}},
                     "\"pyfr\": meet PyFR's importer (pyramids only on parallelogram bases: the hex columns under "
                     "the others split into prisms, their end pyramids into tetrahedra; order <= 4; an ASCII MSH "
                     "format); \"any\": the near field's hexes as built"),
      params::string("directory", &OutputConfig::directory, "non-empty", "where the files go (created if needed)"),
      params::string("basename", &OutputConfig::basename, "non-empty", "mesh file names, without folder"),
      params::boolean("allow_invalid", &OutputConfig::allow_invalid, "write the mesh even when a check fails"),
      params::boolean("pictures", &OutputConfig::pictures,
                      "SVG pictures beside the mesh: spanwise cuts, the body's surface mesh, a quality histogram"),
      params::real("picture_station", &OutputConfig::picture_station, "(0, 1)",
                   "where the spanwise cut of the pictures is, as a fraction of the span"),
  };
  params::Table<Config> table;
  append(table, &Config::output, o);
  return table;
}

params::Table<Config> checks_keys() {
  params::Table<ChecksConfig> k = {
      params::real("min_scaled_jacobian", &ChecksConfig::min_scaled_jacobian, "[0, 1)",
                   "an element counts as invalid unless proven valid with a certified scaled Jacobian of at "
                   "least this; 0: proven validity only"),
  };
  params::Table<Config> table;
  append(table, &Config::checks, k);
  return table;
}

template <class P>
params::Table<Config> stage_keys(P Config::*member, const params::Table<P>& keys) {
  params::Table<Config> table;
  append(table, member, keys);
  return table;
}

// ratio_line and ratio_end of `section` (boundary_layer or wall_layer): both or neither, A != B.
void check_ratio_line(Section& s, const std::string& section, const std::optional<std::array<double, 6>>& line,
                      const std::optional<double>& end) {
  if (line) {
    const auto& l = *line;
    const double length2 = (l[3] - l[0]) * (l[3] - l[0]) + (l[4] - l[1]) * (l[4] - l[1]) + (l[5] - l[2]) * (l[5] - l[2]);
    s.require(length2 > 0.0, "ratio_line", "[xa, ya, za, xb, yb, zb] with A != B");
    s.require(end.has_value(), "ratio_line", "together with " + section + ".ratio_end (the ratio at B)");
  }
  if (end) s.require(line.has_value(), "ratio_end", "together with " + section + ".ratio_line (where it applies)");
}

// geometry.wall_plane and geometry.farfield = {box | sphere | box_chords}: complete, together, and
// for a generated wing (which stands on z = 0 and has a box) the plane z = 0 and a box.
void check_generated_domain(const GeometryConfig& geo, Section& plane, Section& far, Section& sphere) {
  const WallPlaneConfig& w = geo.wall_plane;
  const FarFieldShapeConfig& f = geo.farfield_shape;
  if (w.given()) {
    plane.require(w.point.has_value(), "normal", "together with geometry.wall_plane.point");
    plane.require(w.normal.has_value(), "point", "together with geometry.wall_plane.normal (into the fluid)");
    const auto& n = *w.normal;
    plane.require(n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0, "normal", "a non-zero vector (into the fluid)");
  }
  if (f.sphere.centre || f.sphere.radius) {
    sphere.require(f.sphere.centre.has_value(), "radius", "together with geometry.farfield.sphere.centre");
    sphere.require(f.sphere.radius.has_value(), "centre", "together with geometry.farfield.sphere.radius");
  }
  const int shapes = (f.box ? 1 : 0) + (f.sphere.centre ? 1 : 0) + (f.box_chords ? 1 : 0);
  if (f.box) {
    const auto& b = *f.box;
    far.require(b[0] < b[3] && b[1] < b[4] && b[2] < b[5], "box", "[xmin, ymin, zmin, xmax, ymax, zmax] with each min < max");
    far.require(shapes == 1, "box", "one of box, sphere or box_chords");
  }
  if (f.box_chords) far.require(shapes == 1, "box_chords", "one of box, sphere or box_chords");
  if (!w.given() && !f.given()) return;
  if (f.given())
    plane.require(w.given(), "point",
                  "geometry.wall_plane = {point, normal} together with geometry.farfield = {...}: a body-only file "
                  "gets both its wall and its far field");
  else
    plane.require(false, "point",
                  "together with geometry.farfield = {box = [...]} | {sphere = {centre, radius}} | {box_chords = k}: "
                  "a body-only file gets both its wall and its far field");
  if (!geo.source.empty()) return;
  // The generated wing stands on z = 0 in a box of its own.
  const auto& p = *w.point;
  const auto& n = *w.normal;
  plane.require(p[2] == 0.0 && n[0] == 0.0 && n[1] == 0.0 && n[2] > 0.0, "normal",
                "the plane z = 0 with normal +z for a generated wing (it stands on z = 0; give a CAD file with "
                "backend = \"occ\" for another plane)");
  if (f.sphere.centre)
    sphere.require(false, "centre",
                   "a box for a generated wing (its far field is a box; a sphere needs a CAD file with backend = "
                   "\"occ\")");
}

// What the rows cannot say: conditions between keys.
void check_across_keys(Config& c, const std::map<std::string, Section*>& sections, const std::string& base_directory) {
  GeometryConfig& geo = c.geometry;
  if (!geo.source.empty() && !base_directory.empty() && std::filesystem::path(geo.source).is_relative())
    geo.source = (std::filesystem::path(base_directory) / geo.source).lexically_normal().string();
  Section& g = *sections.at("geometry");
  g.require(geo.source.empty() || geo.units != "chord", "units",
            "a length unit for a CAD file (mm, cm, m, km, um, in, ft), or \"auto\" for the one it declares");
  g.require(!geo.source.empty() || !geo.sew_tolerance, "sew_tolerance", "unset for a generated wing (no file to sew)");
  const auto& box = geo.naca.box;
  sections.at("geometry.naca")
      ->require(box[0] < box[3] && box[1] < box[4] && box[2] < box[5], "box",
                "[xmin, ymin, zmin, xmax, ymax, zmax] with each min < max");

  sections.at("geometry.naca")
      ->require(geo.naca.tip == "flat" || !geo.source.empty() || geo.backend == "naca", "tip",
                "\"flat\" for backend \"" + geo.backend + "\" (the rounded tip is the analytic backend's: backend = \"naca\")");
  // A sharp trailing edge closes the rounded tip to a cone's apex (half angle ~8 degrees for 0012):
  // at order 1 its prisms are valid, curved they fold there (4 invalid at order 4 on the coarse
  // case, at every shell thickness and surface size tried: the apex is self-similar).
  sections.at("geometry.naca")
      ->require(geo.naca.tip == "flat" || geo.naca.te == "blunt" || c.highorder.order == 1, "tip",
                "\"flat\" with te = \"sharp\" at highorder.order > 1 (a sharp trailing edge closes the rounded tip "
                "to a conical point where curved prisms fold), or te = \"blunt\", or highorder.order = 1");

  check_generated_domain(geo, *sections.at("geometry.wall_plane"), *sections.at("geometry.farfield"),
                         *sections.at("geometry.farfield.sphere"));

  Section& n = *sections.at("nearfield");
  n.require(c.nearfield.topology != "H" || c.wall_layer.thickness > 0.0, "topology",
            "\"O\" or \"C\" with wall_layer.thickness = 0: the H-type wake block stands a gap above the wall layer");
  const nearfield::JunctionParams& junction = c.nearfield.junction;
  n.require(junction.min_angle_deg < junction.max_angle_deg, "junction_min_angle", "< nearfield.junction_max_angle");
  n.require(junction.max_angle_deg <= junction.concave_below_deg, "junction_max_angle", "<= nearfield.concave_angle");

  Section& w = *sections.at("wall_layer");
  const WallLayerConfig& wall = c.wall_layer;
  if (wall.first_cell_height) {
    w.require(!w.has("ratio"), "first_cell_height", "either ratio or first_cell_height, not both");
    w.require(*wall.first_cell_height * wall.split.layers <= wall.thickness, "first_cell_height",
              fmt::format("<= wall_layer.thickness / layers = {}", wall.thickness / wall.split.layers) +
                  " (the layers must fit in the wall layer with a ratio >= 1)");
  }

  Section& b = *sections.at("boundary_layer");
  const BoundaryLayerConfig& layer = c.boundary_layer;
  const double thickness = c.nearfield.shell.thickness;
  if (layer.first_cell_height) {
    b.require(!b.has("ratio"), "first_cell_height", "either ratio or first_cell_height, not both");
    b.require(*layer.first_cell_height * layer.split.layers <= thickness, "first_cell_height",
              fmt::format("<= nearfield.thickness / layers = {}", thickness / layer.split.layers) +
                  " (the layers must fit in the shell with a ratio >= 1)");
  }
  check_ratio_line(b, "boundary_layer", layer.ratio_line, layer.ratio_end);
  check_ratio_line(w, "wall_layer", wall.ratio_line, wall.ratio_end);
  if (layer.y_plus) {
    b.require(layer.reynolds.has_value(), "y_plus", "together with boundary_layer.reynolds");
    b.require(!b.has("ratio") && !layer.first_cell_height, "y_plus",
              "either y_plus, ratio or first_cell_height, one of them");
  }
  if (layer.reynolds) b.require(layer.y_plus.has_value(), "reynolds", "together with boundary_layer.y_plus");

  sections.at("sizing")->require(c.sizing.size.min_size <= c.sizing.size.max_size, "min_size",
                                 "in (0, sizing.max_size]");

  Section& o = *sections.at("output");
  const std::set<std::string> distinct(c.output.formats.begin(), c.output.formats.end());
  o.require(distinct.size() == c.output.formats.size(), "formats", "each format at most once");
  o.require(c.output.basename.find('/') == std::string::npos, "basename", "a file name without folder, e.g. \"wing\"");
  if (c.output.target == OutputTarget::Pyfr) {
    // PyFR's gmsh reader takes ASCII MSH only, and element types up to order 4.
    o.require(distinct.count("msh41") + distinct.count("msh22") > 0, "formats",
              "with target = \"pyfr\": \"msh41\" or \"msh22\" among them (PyFR reads ASCII MSH only)");
    sections.at("highorder")->require(c.highorder.order <= 4, "order", "at most 4 with output.target = \"pyfr\" (PyFR's importer)");
  }
}

}  // namespace

const std::vector<ConfigSection>& config_sections() {
  static const std::vector<ConfigSection> sections = {
      {"geometry", geometry_keys()},
      {"geometry.naca", naca_keys()},
      {"geometry.wall_plane", wall_plane_keys()},
      {"geometry.farfield", farfield_shape_keys(), true, true},
      {"geometry.farfield.sphere", farfield_sphere_keys()},
      {"nearfield", nearfield_keys()},
      {"boundary_layer", boundary_layer_keys()},
      {"wall_layer", wall_layer_keys()},
      {"wake", stage_keys(&Config::wake, nearfield::wake_keys())},
      {"sizing", sizing_keys()},
      {"farfield", stage_keys(&Config::farfield, farfield::far_field_keys())},
      {"highorder", stage_keys(&Config::highorder, ho::curving_keys())},
      {"checks", checks_keys()},
      {"output", output_keys()},
  };
  return sections;
}

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
  for (const std::string& o : overrides) apply_override(root, o, origin);

  std::set<std::string> top;
  for (const ConfigSection& section : config_sections())
    if (section.name.find('.') == std::string::npos) top.insert(section.name);
  for (const auto& [k, node] : root)
    if (!top.count(std::string(k.str()))) {
      std::string names;
      for (const ConfigSection& section : config_sections())
        if (top.count(section.name)) names += (names.empty() ? "" : ", ") + section.name;
      throw ConfigError("config error: " + location(origin, std::string(k.str()), &node) + ": unknown key " +
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
    read_keys(*s, section.keys, c, table_or_value);
    sections[section.name] = std::move(s);
  }
  std::map<std::string, Section*> by_name;
  for (auto& [name, s] : sections) by_name[name] = s.get();
  check_across_keys(c, by_name, base_directory);
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
