#include "run_command.hpp"

#include "exit_codes.hpp"

#include "semimesh/pipeline/config.hpp"
#include "semimesh/pipeline/pipeline.hpp"
#include "semimesh/pipeline/report.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>

namespace semimesh::app {
namespace {

constexpr std::size_t kOffendersShown = 10;

// "name ........ 1.234 s" per stage: the name when it starts, the time when it ends.
class StageLines : public pipeline::Progress {
 public:
  explicit StageLines(std::ostream& out) : out_(out) {}
  void stage_started(const std::string& name) override {
    fmt::print(out_, "{:.<24} ", name + " ");
    out_.flush();
  }
  void stage_finished(const pipeline::StageTiming& timing) override {
    fmt::print(out_, "{:8.3f} s\n", timing.seconds);
    out_.flush();
  }

 private:
  std::ostream& out_;
};

void print_failed_checks(const pipeline::RunResult& r, std::ostream& err) {
  if (!r.conformity.ok()) {
    fmt::print(err, "semimesh: conformity: {} problem(s)\n", r.conformity.problems.size());
    for (std::size_t i = 0; i < std::min(kOffendersShown, r.conformity.problems.size()); ++i)
      fmt::print(err, "  {}\n", r.conformity.problems[i].describe(r.mesh));
  }
  if (!r.validity.ok()) {
    fmt::print(err, "semimesh: validity: {} invalid element(s), worst first\n", r.validity.invalid);
    for (std::size_t i = 0; i < std::min(kOffendersShown, r.validity.worst.size()); ++i) {
      const checks::InvalidElement& e = r.validity.worst[i];
      const std::string why = e.below_floor ? fmt::format(" (valid, but below checks.min_scaled_jacobian = {})",
                                                          r.validity.floor)
                              : e.proven ? std::string()
                                         : std::string(" (not proven either way)");
      fmt::print(err, "  element {} ({}) at ({:.6g}, {:.6g}, {:.6g}): scaled Jacobian {:.4g}{}\n", e.element,
                 ho::to_string(e.shape), e.centroid.x(), e.centroid.y(), e.centroid.z(), e.scaled_jacobian, why);
    }
  }
  if (!r.volume_ok())
    fmt::print(err,
               "semimesh: volume: elements {:.12g}, boundary flux {:.12g} (relative error {:.3e}, limit {:.0e}), "
               "box - body {:.12g} (relative error {:.3e}, limit {:.0e})\n",
               r.volume.mesh.element_volume, r.volume.mesh.boundary_volume, r.volume.mesh.boundary_relative_error(),
               pipeline::kBoundaryVolumeTolerance, r.volume.expected_volume(), r.volume.expected_relative_error(),
               pipeline::kExpectedVolumeTolerance);
}

}  // namespace

CLI::App* add_run_subcommand(CLI::App& app, RunOptions& options) {
  CLI::App* cmd = app.add_subcommand("run", "Mesh a wing on a wall from a TOML configuration (docs/config.md)");
  cmd->add_option("config", options.config, "Configuration file (TOML)")->required();
  cmd->add_option("-o,--output", options.output_directory, "Output folder (overrides output.directory)");
  cmd->add_option("--set", options.overrides, "Override a key: dotted.key=value, value in TOML syntax (repeatable)")
      ->allow_extra_args(false);  // one value per --set, so a following CONFIG is not swallowed
  cmd->add_flag("--allow-invalid", options.allow_invalid, "Write the mesh even when a check fails (exit code stays 2)");
  return cmd;
}

int run_pipeline_command(const RunOptions& options, std::ostream& out, std::ostream& err) {
  pipeline::Config config;
  try {
    config = pipeline::load_config(options.config, options.overrides);
  } catch (const pipeline::ConfigError& e) {
    fmt::print(err, "semimesh: {}\n", e.what());
    return kExitBadInput;
  }
  if (!options.output_directory.empty()) config.output.directory = options.output_directory;
  if (options.allow_invalid) config.output.allow_invalid = true;

  StageLines progress(out);
  try {
    const pipeline::RunResult result = pipeline::run(config, progress);
    for (const std::string& w : result.warnings) fmt::print(err, "semimesh: warning: {}\n", w);
    fmt::print(out, "\n{}", pipeline::summary_table(result));
    if (result.checks_passed()) return kExitOk;
    print_failed_checks(result, err);
    fmt::print(err, "semimesh: the mesh failed its checks; {}\n",
               result.written_files.empty() ? "no file written (use --allow-invalid to write it anyway)"
                                            : "written anyway (--allow-invalid)");
    return kExitInvalidMesh;
  } catch (const pipeline::RunError& e) {
    fmt::print(out, "failed\n");
    const bool input = e.cause() == Error::Cause::BadInput;
    fmt::print(err, "semimesh: {}{}\n", input ? "error: " : "internal error: ", e.what());
    return exit_code(e.cause());
  }
}

}  // namespace semimesh::app
