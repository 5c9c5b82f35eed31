#include "semimesh/pipeline/config.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
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
  Section(const Origin& origin, const toml::table& parent, const std::string& key, const std::string& name)
      : origin_(origin), name_(name) {
    const toml::node* node = parent.get(key);
    if (node && !node->is_table()) reject(origin, name, node, "a table [" + name + "]");
    table_ = node ? node->as_table() : nullptr;
  }

  std::string key(const std::string& k) const { return name_ + "." + k; }

  const toml::node* take(const std::string& k) {
    known_.insert(k);
    return table_ ? table_->get(k) : nullptr;
  }

  void real(const std::string& k, double& out) {
    if (const toml::node* n = take(k)) {
      if (auto v = n->value<double>(); v && (n->is_floating_point() || n->is_integer()) && std::isfinite(*v))
        out = *v;
      else
        reject(origin_, key(k), n, "a finite number");
    }
  }
  void real(const std::string& k, std::optional<double>& out) {
    if (take(k)) {
      double v = 0.0;
      real(k, v);
      out = v;
    }
  }
  void integer(const std::string& k, int& out) {
    if (const toml::node* n = take(k)) {
      auto v = n->as_integer();
      if (!v || v->get() < -1000000000 || v->get() > 1000000000) reject(origin_, key(k), n, "an integer");
      out = static_cast<int>(v->get());
    }
  }
  void boolean(const std::string& k, bool& out) {
    if (const toml::node* n = take(k)) {
      if (!n->is_boolean()) reject(origin_, key(k), n, "true or false");
      out = n->as_boolean()->get();
    }
  }
  void string(const std::string& k, std::string& out) {
    if (const toml::node* n = take(k)) {
      if (!n->is_string()) reject(origin_, key(k), n, "a string");
      out = n->as_string()->get();
    }
  }
  void strings(const std::string& k, std::vector<std::string>& out) {
    if (const toml::node* n = take(k)) {
      const toml::array* a = n->as_array();
      if (!a || a->empty() || !a->is_homogeneous(toml::node_type::string))
        reject(origin_, key(k), n, "a non-empty array of strings");
      out.clear();
      for (const toml::node& e : *a) out.push_back(e.as_string()->get());
    }
  }
  template <std::size_t N>
  void reals(const std::string& k, std::array<double, N>& out) {
    if (const toml::node* n = take(k)) {
      const toml::array* a = n->as_array();
      if (!a || a->size() != N) reject(origin_, key(k), n, "an array of " + std::to_string(N) + " numbers");
      for (std::size_t i = 0; i < N; ++i) {
        auto v = (*a)[i].value<double>();
        if (!v || !std::isfinite(*v)) reject(origin_, key(k), n, "an array of " + std::to_string(N) + " numbers");
        out[i] = *v;
      }
    }
  }

  /// A nested table [name.sub] read by its own Section.
  Section sub(const std::string& k) {
    known_.insert(k);
    static const toml::table empty;
    return Section(origin_, table_ ? *table_ : empty, k, key(k));
  }

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

bool one_of(const std::string& value, std::initializer_list<const char*> allowed) {
  return std::any_of(allowed.begin(), allowed.end(), [&](const char* a) { return value == a; });
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
    toml::node* next = table->get(part);
    if (!next) next = &table->insert_or_assign(part, toml::table{}).first->second;
    if (!next->is_table())
      throw ConfigError("config error: --set " + assignment + ": " + key.substr(0, dot) + " is a value, not a table");
    table = next->as_table();
  }
  table->insert_or_assign(key.substr(start), std::move(*parsed.get("value")));
  origin.overrides[key] = assignment;
}

void read_geometry(Section s, Config& c, const std::string& base_directory) {
  GeometryConfig& g = c.geometry;
  s.string("backend", g.backend);
  s.require(!g.backend.empty(), "backend", "a backend name: naca, occ or vendor");
  s.string("source", g.source);
  if (!g.source.empty() && !base_directory.empty() && std::filesystem::path(g.source).is_relative())
    g.source = (std::filesystem::path(base_directory) / g.source).lexically_normal().string();
  s.string("units", g.units);
  s.require(!g.units.empty(), "units", "a unit name, e.g. chord, m, mm");
  s.real("scale", g.scale);
  s.require(g.scale > 0.0, "scale", "> 0");

  Section n = s.sub("naca");
  NacaConfig& a = g.naca;
  n.string("code", a.code);
  n.real("chord", a.chord);
  n.require(a.chord > 0.0, "chord", "> 0");
  n.real("span", a.span);
  n.require(a.span > 0.0, "span", "> 0");
  n.real("taper", a.taper);
  n.require(a.taper > 0.0, "taper", "> 0");
  n.real("sweep", a.sweep);
  n.require(std::abs(a.sweep) < 80.0, "sweep", "a sweep angle in degrees with |sweep| < 80");
  n.string("te", a.te);
  n.require(one_of(a.te, {"blunt", "sharp"}), "te", "\"blunt\" or \"sharp\"");
  n.reals("box", a.box);
  n.require(a.box[0] < a.box[3] && a.box[1] < a.box[4] && a.box[2] < a.box[5], "box",
            "[xmin, ymin, zmin, xmax, ymax, zmax] with each min < max");
  n.reject_unknown();

  if (a.te == "sharp" && !s.has("body")) g.body.erase(std::remove(g.body.begin(), g.body.end(), "te_base"), g.body.end());
  s.strings("body", g.body);
  s.string("wall", g.wall);
  s.require(!g.wall.empty(), "wall", "the name of the wall surface");
  s.strings("farfield", g.farfield);
  s.reject_unknown();
}

void read_nearfield(Section s, NearFieldConfig& n) {
  s.string("topology", n.topology);
  s.require(one_of(n.topology, {"O", "C", "H"}), "topology", "\"O\", \"C\" or \"H\"");
  s.require(n.topology == "O", "topology",
            "\"O\": the C-type (root junction block) and H-type (trailing-edge wake block) topologies are not "
            "implemented yet");
  s.real("thickness", n.thickness);
  s.require(n.thickness > 0.0, "thickness", "> 0");
  s.integer("smoothing_passes", n.smoothing_passes);
  s.require(n.smoothing_passes >= 0, "smoothing_passes", ">= 0");
  s.real("min_thickness_fraction", n.min_thickness_fraction);
  s.require(n.min_thickness_fraction > 0.0 && n.min_thickness_fraction <= 1.0, "min_thickness_fraction", "in (0, 1]");
  s.real("reduction_factor", n.reduction_factor);
  s.require(n.reduction_factor > 0.0 && n.reduction_factor < 1.0, "reduction_factor", "in (0, 1)");
  s.real("gradation", n.gradation);
  s.require(n.gradation > 0.0, "gradation", "> 0");
  s.reject_unknown();
}

void read_boundary_layer(Section s, BoundaryLayerConfig& b, double thickness) {
  s.integer("layers", b.layers);
  s.require(b.layers >= 1 && b.layers <= 100, "layers", "an integer in [1, 100]");
  s.real("ratio", b.ratio);
  s.require(b.ratio >= 1.0, "ratio", ">= 1");
  s.real("first_cell_height", b.first_cell_height);
  if (b.first_cell_height) {
    s.require(!s.has("ratio"), "first_cell_height", "either ratio or first_cell_height, not both");
    s.require(*b.first_cell_height > 0.0, "first_cell_height", "> 0");
    s.require(*b.first_cell_height * b.layers <= thickness, "first_cell_height",
              fmt::format("<= nearfield.thickness / layers = {}", thickness / b.layers) +
                  " (the layers must fit in the shell with a ratio >= 1)");
  }
  s.real("ratio_end", b.ratio_end);
  if (s.has("ratio_line")) {
    std::array<double, 6> line{};
    s.reals("ratio_line", line);
    b.ratio_line = line;
    const double length2 = (line[3] - line[0]) * (line[3] - line[0]) + (line[4] - line[1]) * (line[4] - line[1]) +
                           (line[5] - line[2]) * (line[5] - line[2]);
    s.require(length2 > 0.0, "ratio_line", "[xa, ya, za, xb, yb, zb] with A != B");
    s.require(b.ratio_end.has_value(), "ratio_line", "together with boundary_layer.ratio_end (the ratio at B)");
  }
  if (b.ratio_end) {
    s.require(*b.ratio_end >= 1.0, "ratio_end", ">= 1");
    s.require(b.ratio_line.has_value(), "ratio_end", "together with boundary_layer.ratio_line (where it applies)");
  }
  s.reject_unknown();
}

void read_sizing(Section s, SizingConfig& z) {
  s.real("max_size", z.max_size);
  s.require(z.max_size > 0.0, "max_size", "> 0");
  s.real("min_size", z.min_size);
  s.require(z.min_size > 0.0 && z.min_size <= z.max_size, "min_size", "in (0, sizing.max_size]");
  s.real("curvature_segments", z.curvature_segments);
  s.require(z.curvature_segments >= 0.0, "curvature_segments", ">= 0 (0 disables curvature sizing)");
  s.real("gradation", z.gradation);
  s.require(z.gradation >= 1.0, "gradation", ">= 1");
  s.real("le_size", z.le_size);
  s.require(z.le_size >= 0.0, "le_size", ">= 0 (0: no leading-edge source)");
  s.real("te_size", z.te_size);
  s.require(z.te_size >= 0.0, "te_size", ">= 0 (0: no trailing-edge source)");
  s.integer("chordwise", z.chordwise);
  s.require(z.chordwise >= 0, "chordwise", ">= 0 (0: from the size field)");
  s.integer("spanwise", z.spanwise);
  s.require(z.spanwise >= 0, "spanwise", ">= 0 (0: from the size field)");
  s.reject_unknown();
}

void read_farfield(Section s, FarFieldConfig& f) {
  s.real("box_size", f.box_size);
  s.require(f.box_size > 0.0, "box_size", "> 0");
  s.real("wall_size", f.wall_size);
  s.require(f.wall_size > 0.0, "wall_size", "> 0");
  s.real("growth", f.growth);
  s.require(f.growth >= 1.0, "growth", ">= 1");
  s.real("radius_edge_ratio", f.radius_edge_ratio);
  s.require(f.radius_edge_ratio >= 1.0, "radius_edge_ratio", ">= 1 (TetGen's quality bound; 1.5 to 2 is usual)");
  s.real("max_volume", f.max_volume);
  s.require(f.max_volume >= 0.0, "max_volume", ">= 0 (0: no bound)");
  s.reject_unknown();
}

void read_highorder(Section s, HighOrderConfig& h) {
  s.integer("order", h.order);
  s.require(h.order >= 1 && h.order <= 8, "order", "an integer in [1, 8]");
  s.string("node_set", h.node_set);
  s.require(one_of(h.node_set, {"gll", "equispaced"}), "node_set", "\"gll\" or \"equispaced\"");
  s.string("node_placement", h.node_placement);
  s.require(one_of(h.node_placement, {"parameter", "springs"}), "node_placement", "\"parameter\" or \"springs\"");
  s.integer("spring_iterations", h.spring_iterations);
  s.require(h.spring_iterations >= 1 && h.spring_iterations <= 10000, "spring_iterations", "an integer in [1, 10000]");
  s.reject_unknown();
}

void read_checks(Section s, ChecksConfig& k) {
  s.real("min_scaled_jacobian", k.min_scaled_jacobian);
  s.require(k.min_scaled_jacobian >= 0.0 && k.min_scaled_jacobian < 1.0, "min_scaled_jacobian",
            "in [0, 1) (0: only proven validity)");
  s.reject_unknown();
}

void read_output(Section s, OutputConfig& o) {
  s.strings("formats", o.formats);
  for (const std::string& f : o.formats)
    s.require(one_of(f, {"msh41", "msh22", "vtu", "nektar"}), "formats",
              "formats among \"msh41\", \"msh22\", \"vtu\", \"nektar\" (got \"" + f + "\")");
  std::set<std::string> distinct(o.formats.begin(), o.formats.end());
  s.require(distinct.size() == o.formats.size(), "formats", "each format at most once");
  s.string("directory", o.directory);
  s.require(!o.directory.empty(), "directory", "a folder name (\".\" for the current one)");
  s.string("basename", o.basename);
  s.require(!o.basename.empty() && o.basename.find('/') == std::string::npos, "basename",
            "a file name without folder, e.g. \"wing\"");
  s.boolean("allow_invalid", o.allow_invalid);
  s.reject_unknown();
}

}  // namespace

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

  static const std::set<std::string> sections = {"geometry", "nearfield", "boundary_layer", "sizing",
                                                  "farfield", "highorder", "checks", "output"};
  for (const auto& [k, node] : root)
    if (!sections.count(std::string(k.str())))
      throw ConfigError("config error: " + location(origin, std::string(k.str()), &node) + ": unknown key " +
                        std::string(k.str()) +
                        " (sections: geometry, nearfield, boundary_layer, sizing, farfield, highorder, checks, output)");

  Config c;
  read_geometry(Section(origin, root, "geometry", "geometry"), c, base_directory);
  read_nearfield(Section(origin, root, "nearfield", "nearfield"), c.nearfield);
  read_boundary_layer(Section(origin, root, "boundary_layer", "boundary_layer"), c.boundary_layer, c.nearfield.thickness);
  read_sizing(Section(origin, root, "sizing", "sizing"), c.sizing);
  read_farfield(Section(origin, root, "farfield", "farfield"), c.farfield);
  read_highorder(Section(origin, root, "highorder", "highorder"), c.highorder);
  read_checks(Section(origin, root, "checks", "checks"), c.checks);
  read_output(Section(origin, root, "output", "output"), c.output);
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

double effective_layer_ratio(const BoundaryLayerConfig& layer, double thickness) {
  if (!layer.first_cell_height) return layer.ratio;
  const double h1 = *layer.first_cell_height;
  const int n = layer.layers;
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

}  // namespace semimesh::pipeline
