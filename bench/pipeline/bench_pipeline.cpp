// Time per stage and peak memory of the whole pipeline on the paper's case (NACA 0012 on a wall,
// far field about ten chords away, order 1) at several sizes. Every length of the size field and of
// the far field is multiplied by one factor chosen from the target element count (and the
// curvature resolution divided by it); the element counts reached are printed next to the targets.
//
//   bench_pipeline [TARGET ...]    targets in elements, e.g. 1e4 1e5 1e6 (default: 1e4 1e5)
//
// Sizes run in increasing order in one process, so the peak resident memory printed for each is
// the peak up to and including that run (getrusage is a process-wide maximum). Prints a table.
#include "semimesh/pipeline/config.hpp"
#include "semimesh/pipeline/pipeline.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace pl = semimesh::pipeline;

// Measured (factor, elements) pairs of this case; the factor for a target is interpolated in
// log-log between them (the count does not follow one power of the factor: the leading edge sits
// at min_size and the far field is bounded by the box).
constexpr double kCalibration[][2] = {{4.44, 9.7e3}, {1.32, 1.03e5}, {0.396, 3.86e5}, {0.19, 1.27e6}};

double factor_for(double target) {
  constexpr int n = sizeof(kCalibration) / sizeof(kCalibration[0]);
  int i = 0;
  while (i < n - 2 && target > kCalibration[i + 1][1]) ++i;  // segment [i, i+1], extrapolated at the ends
  const double t = std::log(target / kCalibration[i][1]) / std::log(kCalibration[i + 1][1] / kCalibration[i][1]);
  return kCalibration[i][0] * std::pow(kCalibration[i + 1][0] / kCalibration[i][0], t);
}

pl::Config config_for(double target, const std::string& directory) {
  pl::Config c;  // defaults: the paper's case
  const double f = factor_for(target);
  c.highorder.order = 1;
  c.sizing.size.max_size *= f;
  c.sizing.size.min_size *= f * f;  // the leading edge sits at min_size: it must coarsen faster
  c.sizing.size.le_size *= f;
  c.sizing.size.te_size *= f;
  c.sizing.size.curvature_segments /= f;
  c.farfield.box_size *= f;
  c.farfield.wall_size *= f;
  c.nearfield.shell.thickness = std::min(c.nearfield.shell.thickness, 2.0 * c.sizing.size.te_size);
  c.output.formats = {"msh41"};
  c.output.directory = directory;
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<double> targets;
  for (int i = 1; i < argc; ++i) {
    char* end = nullptr;
    const double t = std::strtod(argv[i], &end);
    if (end == argv[i] || *end != '\0' || !(t >= 1e3 && t <= 1e7)) {
      fmt::print(stderr, "bench_pipeline: '{}' is not an element count in [1e3, 1e7]\n", argv[i]);
      return 1;
    }
    targets.push_back(t);
  }
  if (targets.empty()) targets = {1e4, 1e5};
  std::sort(targets.begin(), targets.end());

  const std::string directory = (std::filesystem::temp_directory_path() / "semimesh_bench_pipeline").string();
  std::vector<std::string> stage_names;
  std::vector<std::vector<std::string>> rows;
  for (double target : targets) {
    pl::Progress quiet;
    const pl::RunResult r = pl::run(config_for(target, directory), quiet);
    if (stage_names.empty())
      for (const pl::StageTiming& s : r.stages) stage_names.push_back(s.name);
    std::vector<std::string> row = {fmt::format("{:.0e}", target), std::to_string(r.mesh.elements().size()),
                                    std::to_string(r.elements_by_type.count("prism") ? r.elements_by_type.at("prism") : 0)};
    for (const pl::StageTiming& s : r.stages) row.push_back(fmt::format("{:.2f}", s.seconds));
    row.push_back(fmt::format("{:.2f}", r.total_seconds()));
    row.push_back(fmt::format("{:.0f}", r.peak_memory_mb));
    row.push_back(r.checks_passed() ? "yes" : "NO");
    rows.push_back(row);
  }
  std::filesystem::remove_all(directory);

  std::vector<std::string> header = {"target", "elements", "prisms"};
  for (const std::string& s : stage_names) header.push_back(s + " s");
  header.push_back("total s");
  header.push_back("peak MB");
  header.push_back("valid");
  for (const std::string& h : header) fmt::print("{:>15}", h);
  fmt::print("\n");
  for (const auto& row : rows) {
    for (const std::string& cell : row) fmt::print("{:>15}", cell);
    fmt::print("\n");
  }
  return 0;
}
