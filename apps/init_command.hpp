// `semimesh init [-o wing.toml]`: a commented configuration with every key at its default, written
// from the config's own key tables (so it can never list a key `run` does not read), which
// `semimesh run` accepts unchanged.
#pragma once

#include <CLI/CLI.hpp>

#include <ostream>
#include <string>

namespace semimesh::app {

struct InitOptions {
  std::string output;  ///< file to write; empty: standard output
  bool force = false;  ///< overwrite an existing file
};

CLI::App* add_init_subcommand(CLI::App& app, InitOptions& options);

/// The text: one [section] per config section, each key as `key = default` preceded by its doc and
/// range as a comment; optional keys that are unset by default are commented out.
std::string default_config_text();

/// Writes the text to options.output (atomically; an existing file only with force) or to `out`.
/// Returns the exit code: 0, or 1 with a message on `err` when the file exists or cannot be written.
int run_init_command(const InitOptions& options, std::ostream& out, std::ostream& err);

}  // namespace semimesh::app
