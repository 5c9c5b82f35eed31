#include "run_command.hpp"

#include "exit_codes.hpp"

#include "semimesh/pipeline/config.hpp"
#include "semimesh/pipeline/pipeline.hpp"
#include "semimesh/pipeline/report.hpp"
#include "semimesh/io/json.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>

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

// "12 s", "3 min 05 s": a remaining time.
std::string duration_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  return s < 60 ? fmt::format("{} s", s) : fmt::format("{} min {:02} s", s / 60, s % 60);
}

// On a terminal: one line that shows the running stage, its % done and the time left (the elapsed
// time over the fraction done) or, before any progress, its elapsed time; rewritten in place on
// progress (at most ten times a second) and four times a second, and left as
// "name ..... 1.234 s" when the stage ends.
class TerminalLine : public pipeline::Progress {
 public:
  explicit TerminalLine(std::ostream& out) : out_(out), ticker_([this] { tick(); }) {}
  ~TerminalLine() override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    wake_.notify_all();
    ticker_.join();
  }
  void stage_started(const std::string& name) override {
    std::lock_guard<std::mutex> lock(mutex_);
    stage_ = name;
    start_ = std::chrono::steady_clock::now();
    fraction_ = -1.0;
    step_.clear();
    draw();
  }
  void stage_progress(double fraction, const std::string& step) override {
    std::lock_guard<std::mutex> lock(mutex_);
    const bool first = fraction_ < 0.0;
    fraction_ = fraction;
    step_ = step;
    if (first || std::chrono::steady_clock::now() - drawn_ >= std::chrono::milliseconds(100)) draw();
  }
  void stage_finished(const pipeline::StageTiming& timing) override {
    std::lock_guard<std::mutex> lock(mutex_);
    fmt::print(out_, "\r\033[K{:.<24} {:8.3f} s\n", timing.name + " ", timing.seconds);
    out_.flush();
    stage_.clear();
  }

 private:
  void draw() {
    if (stage_.empty()) return;
    drawn_ = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(drawn_ - start_).count();
    if (fraction_ < 0.0) {
      fmt::print(out_, "\r\033[K{:.<24} running, {:.0f} s", stage_ + " ", seconds);
    } else {
      const std::string eta =
          fraction_ > 0.0 ? duration_text(seconds * (1.0 - fraction_) / fraction_) : std::string("--");
      fmt::print(out_, "\r\033[K{:.<24} {:3.0f}%  ETA {}{}", stage_ + " ", 100.0 * fraction_, eta,
                 step_.empty() ? std::string() : "  (" + step_ + ")");
    }
    out_.flush();
  }
  void tick() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return done_; })) draw();
  }

  std::ostream& out_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::string stage_, step_;
  double fraction_ = -1.0;  ///< of the running stage; < 0 before its first progress report
  std::chrono::steady_clock::time_point start_, drawn_;
  std::thread ticker_;
};

// --log-json: {"event": "stage_started" | "progress" | "stage_finished", ...} per line. Progress
// events are throttled: one each time the fraction has grown by kJsonProgressStep since the last.
class JsonEvents : public pipeline::Progress {
 public:
  static constexpr double kJsonProgressStep = 0.05;

  explicit JsonEvents(std::ostream& out) : out_(out) {}
  void stage_started(const std::string& name) override {
    fmt::print(out_, "{{\"event\": \"stage_started\", \"stage\": {}}}\n", io::json_string(name));
    out_.flush();
    stage_ = name;
    last_ = -1.0;
  }
  void stage_progress(double fraction, const std::string& step) override {
    if (last_ >= 0.0 && fraction < last_ + kJsonProgressStep && !(fraction >= 1.0 && last_ < 1.0)) return;
    last_ = fraction;
    fmt::print(out_, "{{\"event\": \"progress\", \"stage\": {}, \"fraction\": {}, \"step\": {}}}\n",
               io::json_string(stage_), io::json_number(fraction), io::json_string(step));
    out_.flush();
  }
  void stage_finished(const pipeline::StageTiming& timing) override {
    fmt::print(out_, "{{\"event\": \"stage_finished\", \"stage\": {}, \"seconds\": {}}}\n", io::json_string(timing.name),
               io::json_number(timing.seconds));
    out_.flush();
  }

 private:
  std::ostream& out_;
  std::string stage_;
  double last_ = -1.0;  ///< fraction of the last progress event of the stage; < 0 before the first
};

std::unique_ptr<pipeline::Progress> progress_for(const RunOptions& options, std::ostream& out) {
  if (options.log_json) return std::make_unique<JsonEvents>(out);
  if (options.quiet) return std::make_unique<pipeline::Progress>();
  if (options.terminal) return std::make_unique<TerminalLine>(out);
  return std::make_unique<StageLines>(out);
}

// --verbose: every key as the run reads it.
void print_configuration(const pipeline::Config& config, std::ostream& out) {
  for (const pipeline::ConfigSection& section : pipeline::config_sections()) {
    fmt::print(out, "[{}]\n", section.name);
    for (const params::Key<pipeline::Config>& key : section.keys)
      fmt::print(out, "  {} = {}\n", key.name, params::to_text(key.get(config)));
  }
  fmt::print(out, "\n");
}

// The end of a --log-json run: warnings, then the report and the exit code on one line each.
void print_json_result(const pipeline::RunResult& result, const pipeline::Config& config, int code, std::ostream& out) {
  for (const std::string& w : result.warnings)
    fmt::print(out, "{{\"event\": \"warning\", \"message\": {}}}\n", io::json_string(w));
  std::string report = pipeline::report_json(result, config);
  report.erase(std::remove(report.begin(), report.end(), '\n'), report.end());
  fmt::print(out, "{{\"event\": \"result\", \"exit_code\": {}, \"report\": {}}}\n", code, report);
}

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
               "box - body {:.12g} (relative error {:.3e}, limit {:.3g})\n",
               r.volume.mesh.element_volume, r.volume.mesh.boundary_volume, r.volume.mesh.boundary_relative_error(),
               pipeline::kBoundaryVolumeTolerance, r.volume.expected_volume(), r.volume.expected_relative_error(),
               r.expected_volume_tolerance);
}

}  // namespace

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
  if (options.pictures) config.output.pictures = true;

  if (options.verbose && !options.quiet && !options.log_json) print_configuration(config, out);
  std::unique_ptr<pipeline::Progress> progress = progress_for(options, out);
  try {
    // The summary reads counts and the checks' figures only: the mesh may stay as written.
    const pipeline::RunResult result = pipeline::run(config, *progress, pipeline::MeshAfterWrite::AsWritten);
    progress.reset();  // a terminal line stops drawing before the summary
    const int code = result.checks_passed() ? kExitOk : kExitInvalidMesh;
    if (options.log_json) {
      print_json_result(result, config, code, out);
      return code;
    }
    if (!options.quiet) {
      for (const std::string& w : result.warnings) fmt::print(err, "semimesh: warning: {}\n", w);
      fmt::print(out, "\n{}", pipeline::summary_table(result));
    }
    if (result.checks_passed()) return kExitOk;
    print_failed_checks(result, err);
    fmt::print(err, "semimesh: the mesh failed its checks; {}\n",
               result.written_files.empty() ? "no file written (use --allow-invalid to write it anyway)"
                                            : "written anyway (--allow-invalid)");
    return kExitInvalidMesh;
  } catch (const pipeline::RunError& e) {
    progress.reset();
    if (!options.quiet && !options.log_json) fmt::print(out, "failed\n");
    const bool input = e.cause() == Error::Cause::BadInput;
    if (options.log_json)
      fmt::print(out, "{{\"event\": \"error\", \"stage\": {}, \"cause\": \"{}\", \"message\": {}, \"exit_code\": {}}}\n",
                 io::json_string(e.stage()), input ? "bad input" : "internal", io::json_string(e.what()),
                 exit_code(e.cause()));
    fmt::print(err, "semimesh: {}{}\n", input ? "error: " : "internal error: ", e.what());
    return exit_code(e.cause());
  }
}

}  // namespace semimesh::app
