#include "init_command.hpp"

#include "exit_codes.hpp"
#include "init_from_cad.hpp"
#include "semimesh/backends/builtin.hpp"
#include "semimesh/io/atomic_file.hpp"
#include "semimesh/pipeline/config.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <filesystem>

namespace semimesh::app {

namespace {

// A section that stands for a key of its parent (geometry.farfield: a table instead of surface
// names), or a section inside one: that section, else null.
const pipeline::ConfigSection* table_or_value_owner(const pipeline::ConfigSection& section) {
  for (const pipeline::ConfigSection& s : pipeline::config_sections())
    if (s.or_value && (section.name == s.name || section.name.rfind(s.name + ".", 0) == 0)) return &s;
  return nullptr;
}

// Whether any key of the section `owner` or of the sections inside it is set.
bool table_given(const pipeline::ConfigSection& owner, const pipeline::Config& values) {
  for (const pipeline::ConfigSection& s : pipeline::config_sections())
    if (table_or_value_owner(s) == &owner)
      for (const params::Key<pipeline::Config>& key : s.keys)
        if (!std::holds_alternative<std::monostate>(key.get(values))) return true;
  return false;
}

}  // namespace

std::string config_text(const pipeline::Config& values, const std::string& header) {
  std::string text;
  std::size_t start = 0;
  for (std::size_t end; (end = header.find('\n', start)) != std::string::npos; start = end + 1)
    text += "# " + header.substr(start, end - start) + "\n";
  text += "# Each key: its meaning and range as a comment; docs/config.md explains them in full.\n";
  for (const pipeline::ConfigSection& section : pipeline::config_sections()) {
    // A table standing for a key of its parent (geometry.farfield) is written when set, and then its
    // parent's key of the same name is not; unset, its header is a comment (TOML: a key and a table
    // of one name cannot both be there).
    const pipeline::ConfigSection* owner = table_or_value_owner(section);
    const bool commented = owner && !table_given(*owner, values);
    text += std::string(commented ? "\n# [" : "\n[") + section.name + "]\n";
    for (const params::Key<pipeline::Config>& key : section.keys) {
      const bool replaced = std::any_of(pipeline::config_sections().begin(), pipeline::config_sections().end(),
                                        [&](const pipeline::ConfigSection& s) {
                                          return s.or_value && s.name == section.name + "." + key.name &&
                                                 table_given(s, values);
                                        });
      if (replaced) continue;
      text += "# " + key.doc + (key.range.empty() ? "" : " (range: " + key.range + ")") + "\n";
      const params::Value value = key.get(values);
      if (std::holds_alternative<std::monostate>(value))
        text += "# " + key.name + " = (unset)\n";
      else
        text += key.name + " = " + params::to_text(value) + "\n";
    }
  }
  return text;
}

std::string default_config_text() {
  const pipeline::Config defaults;
  return config_text(defaults, "semimesh run configuration: every key at its default (the paper's NACA 0012 wing case).\n");
}

namespace {

// geometry.source as the config must say it: relative to the config file's folder, absolute when
// the text goes to standard output.
std::string source_for(const std::string& cad, const std::string& output) {
  const std::filesystem::path file = std::filesystem::absolute(cad);
  if (output.empty()) return file.lexically_normal().string();
  return file.lexically_relative(std::filesystem::absolute(output).parent_path()).string();
}

std::string init_text(const InitOptions& options, std::ostream& err) {
  if (options.cad.empty()) return default_config_text();
  const CadConfig c = config_for_cad(backends::default_registry(), options.cad, source_for(options.cad, options.output));
  for (const std::string& warning : c.warnings) fmt::print(err, "semimesh init: warning: {}\n", warning);
  return config_text(c.config, c.summary);
}

}  // namespace

int run_init_command(const InitOptions& options, std::ostream& out, std::ostream& err) {
  std::string text;
  try {
    text = init_text(options, err);
  } catch (const Error& e) {
    fmt::print(err, "semimesh init: {}\n", e.what());
    return exit_code(e.cause());
  }
  if (options.output.empty()) {
    out << text;
    return kExitOk;
  }
  if (std::filesystem::exists(options.output) && !options.force) {
    fmt::print(err, "semimesh init: {} exists; use --force to overwrite it\n", options.output);
    return kExitBadInput;
  }
  try {
    io::AtomicFile file(options.output);
    file.write(text);
    file.commit();
  } catch (const std::exception& e) {
    fmt::print(err, "semimesh init: {}\n", e.what());
    return kExitBadInput;
  }
  fmt::print(out, "wrote {}\n", options.output);
  return kExitOk;
}

}  // namespace semimesh::app
