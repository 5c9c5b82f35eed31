// `semimesh init [-o wing.toml]`: a commented configuration with every key at its default, written
// from the config's own key tables (so it can never list a key `run` does not read), which
// `semimesh run` accepts unchanged.
#pragma once

#include "semimesh/pipeline/config.hpp"

#include <ostream>
#include <string>

namespace CLI {
class App;  // CLI11's (CLI/CLI.hpp, which apps/subcommands.cpp and main.cpp include)
}  // namespace CLI

namespace semimesh::app {

struct InitOptions {
  std::string output;  ///< file to write; empty: standard output
  bool force = false;  ///< overwrite an existing file
  std::string cad;     ///< CAD file to configure for (init_from_cad.hpp); empty: the defaults
};

CLI::App* add_init_subcommand(CLI::App& app, InitOptions& options);

/// The text of `values`: `header` as comment lines, then one [section] per config section, each key
/// as `key = value` preceded by its doc and range as a comment; unset optional keys commented out.
std::string config_text(const pipeline::Config& values, const std::string& header);

/// The defaults' text: one [section] per config section, each key as `key = default` preceded by its doc and
/// range as a comment; optional keys that are unset by default are commented out.
std::string default_config_text();

/// Writes the text (for options.cad when given) to options.output (atomically; an existing file only
/// with force) or to `out`. Returns the exit code: 0, or 1 with a message on `err` when the file
/// exists or cannot be written, or the CAD file cannot be read or its roles found.
int run_init_command(const InitOptions& options, std::ostream& out, std::ostream& err);

}  // namespace semimesh::app
