// `semimesh check MESH.msh [--json]`: element counts by type and order, invalid elements and the
// scaled Jacobian of every element, certified by ho::certify_mesh (the same certification as the
// checks stage of `semimesh run`, so both report the same figures for one mesh).
#pragma once

#include <ostream>
#include <string>

namespace CLI {
class App;  // CLI11's (CLI/CLI.hpp, which apps/subcommands.cpp and main.cpp include)
}  // namespace CLI

namespace semimesh::app {

struct CheckOptions {
  std::string mesh;   ///< MSH file (4.1 or 2.2, ASCII)
  bool json = false;  ///< one JSON object instead of the table
};

/// Declares the `check` subcommand and its options on `app`; `options` receives them when parsed.
CLI::App* add_check_subcommand(CLI::App& app, CheckOptions& options);

/// Prints a summary (or a JSON object with keys "file", "elements" {type: {order: count}},
/// "invalid" [{"index", "type", "centroid"}], "min_scaled_jacobian", "median_scaled_jacobian")
/// to `out`; "index" is the 0-based position among the volume elements in file order. Returns the
/// exit code: 0 every element valid, 2 some invalid, 1 the file cannot be read (the message, with
/// the file name and line, goes to `err`).
int run_check_command(const CheckOptions& options, std::ostream& out, std::ostream& err);

}  // namespace semimesh::app
