#include "init_command.hpp"

#include "exit_codes.hpp"
#include "semimesh/io/atomic_file.hpp"
#include "semimesh/pipeline/config.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <filesystem>

namespace semimesh::app {

CLI::App* add_init_subcommand(CLI::App& app, InitOptions& options) {
  CLI::App* cmd = app.add_subcommand("init", "Write a commented configuration with every key at its default");
  cmd->add_option("-o,--output", options.output, "File to write (default: standard output)");
  cmd->add_flag("--force", options.force, "Overwrite the file if it exists");
  return cmd;
}

std::string default_config_text() {
  const pipeline::Config defaults;
  std::string text =
      "# semimesh run configuration: every key at its default (the paper's NACA 0012 wing case).\n"
      "# Each key: its meaning and range as a comment; docs/config.md explains them in full.\n";
  for (const pipeline::ConfigSection& section : pipeline::config_sections()) {
    text += "\n[" + section.name + "]\n";
    for (const params::Key<pipeline::Config>& key : section.keys) {
      text += "# " + key.doc + (key.range.empty() ? "" : " (range: " + key.range + ")") + "\n";
      const params::Value value = key.get(defaults);
      if (std::holds_alternative<std::monostate>(value))
        text += "# " + key.name + " = (unset)\n";
      else
        text += key.name + " = " + params::to_text(value) + "\n";
    }
  }
  return text;
}

int run_init_command(const InitOptions& options, std::ostream& out, std::ostream& err) {
  const std::string text = default_config_text();
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
