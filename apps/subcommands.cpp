// The subcommands' options declared on CLI11's App: the only library file that includes CLI11 (a
// heavy header), so the commands' own files and their tests compile without it.
#include "check_command.hpp"
#include "init_command.hpp"
#include "run_command.hpp"

#include <CLI/CLI.hpp>

namespace semimesh::app {

CLI::App* add_check_subcommand(CLI::App& app, CheckOptions& options) {
  CLI::App* cmd = app.add_subcommand("check", "Certify every element of a mesh file and report its quality");
  cmd->add_option("mesh", options.mesh, "Mesh file (Gmsh MSH 4.1 or 2.2, ASCII)")->required();
  cmd->add_flag("--json", options.json, "Print one JSON object instead of a table");
  return cmd;
}

CLI::App* add_init_subcommand(CLI::App& app, InitOptions& options) {
  CLI::App* cmd = app.add_subcommand("init", "Write a commented configuration with every key at its default");
  cmd->add_option("-o,--output", options.output, "File to write (default: standard output)");
  cmd->add_flag("--force", options.force, "Overwrite the file if it exists");
  cmd->add_option("--cad", options.cad,
                  "CAD file to configure for: its roles found and written by name, lengths scaled by its chord");
  return cmd;
}

CLI::App* add_run_subcommand(CLI::App& app, RunOptions& options) {
  CLI::App* cmd = app.add_subcommand("run", "Mesh a wing on a wall from a TOML configuration (docs/config.md)");
  cmd->add_option("config", options.config, "Configuration file (TOML)")->required();
  cmd->add_option("-o,--output", options.output_directory, "Output folder (overrides output.directory)");
  cmd->add_option("--set", options.overrides, "Override a key: dotted.key=value, value in TOML syntax (repeatable)")
      ->allow_extra_args(false);  // one value per --set, so a following CONFIG is not swallowed
  cmd->add_flag("--allow-invalid", options.allow_invalid, "Write the mesh even when a check fails (exit code stays 2)");
  cmd->add_flag("--pictures", options.pictures, "Write SVG pictures beside the mesh (output.pictures)");
  cmd->add_flag("-q,--quiet", options.quiet, "Print errors only");
  cmd->add_flag("-v,--verbose", options.verbose, "Also print the configuration as read, key by key");
  cmd->add_flag("--log-json", options.log_json,
                "Print one JSON object per event (stage started/progress/finished, warning, result) instead of text");
  return cmd;
}

}  // namespace semimesh::app
