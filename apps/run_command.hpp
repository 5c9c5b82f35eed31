// `semimesh run CONFIG [-o DIR] [--set key=value]... [--allow-invalid]`: the whole pipeline with a
// line per stage, a summary table, the mesh files and report.json.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace CLI {
class App;  // CLI11's (CLI/CLI.hpp, which apps/subcommands.cpp and main.cpp include)
}  // namespace CLI

namespace semimesh::app {

struct RunOptions {
  std::string config;                  ///< TOML file
  std::string output_directory;        ///< -o: overrides output.directory when set
  std::vector<std::string> overrides;  ///< --set key=value
  bool allow_invalid = false;
  bool pictures = false;
  bool quiet = false;      ///< errors only
  bool verbose = false;    ///< also the configuration as read, key by key
  bool log_json = false;   ///< one JSON object per event on standard output, nothing else there
  bool terminal = false;   ///< standard output is a terminal: one updating progress line
};

/// Declares the `run` subcommand and its options on `app`; `options` receives them when parsed.
CLI::App* add_run_subcommand(CLI::App& app, RunOptions& options);

/// Runs the pipeline. Progress and the summary go to `out`, errors and offenders to `err`.
/// Returns the exit code: 0 ok, 1 bad input, 2 invalid mesh produced, 3 internal error.
int run_pipeline_command(const RunOptions& options, std::ostream& out, std::ostream& err);

}  // namespace semimesh::app
