#include "config_reading.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

namespace semimesh::pipeline::detail {
namespace {

std::string value_text(const toml::node& node) {
  if (auto* s = node.as_string()) return '"' + s->get() + '"';
  if (auto* d = node.as_floating_point()) return fmt::format("{}", d->get());  // shortest form: 0.1, not 0.1000...01
  std::ostringstream out;
  node.visit([&](const auto& v) { out << v; });
  return out.str();
}

}  // namespace

std::string location(const Origin& origin, const std::string& key, const toml::node* node) {
  auto o = origin.overrides.find(key);
  if (o != origin.overrides.end()) return "--set " + o->second;
  if (node && node->source().begin.line > 0) return origin.source_name + ":" + std::to_string(node->source().begin.line);
  return origin.source_name;
}

[[noreturn]] void reject(const Origin& origin, const std::string& key, const toml::node* node, const std::string& expected) {
  std::string text = "config error: " + location(origin, key, node) + ": " + key;
  if (node) text += " = " + value_text(*node);
  throw ConfigError(text + ": expected " + expected);
}

namespace {

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

}  // namespace

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

}  // namespace semimesh::pipeline::detail
