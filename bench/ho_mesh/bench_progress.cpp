// What progress reporting costs: curving (P = 4), layer splitting (N = 5, r = 2) and certification
// of the NACA 0012 O-shell, each run without a callback, with a callback that only counts, and with
// one that formats and prints a line as `semimesh run` does on a terminal (to /dev/null). Prints
// the best of 3 runs of each and the overhead relative to no callback (not a timed test).
#include "naca_o_shell.hpp"

#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/ho/mesh_validity.hpp"
#include "semimesh/ho/splitting/split_layers.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <limits>

namespace {

using namespace semimesh;

// Best wall time in seconds of 3 calls of `stage`.
double best_of_3(const std::function<void()>& stage) {
  double best = std::numeric_limits<double>::infinity();
  for (int run = 0; run < 3; ++run) {
    const auto start = std::chrono::steady_clock::now();
    stage();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

}  // namespace

int main() {
  const bench::NacaOShell shell = bench::naca_o_shell();
  const mesh::Mesh curved = ho::curve_mesh(shell.linear, *shell.model, {4, ho::NodeSet::GLL});
  std::vector<ho::LayerSplit> split(curved.elements().size());
  for (std::size_t e = 0; e < split.size(); ++e) split[e].element = e;
  const std::vector<ho::SplitFamily> families = {{{5, 2.0}, {}}};
  const mesh::Mesh split_mesh = ho::split_layers(curved, split, families, nullptr, nullptr);

  long long calls = 0;
  std::FILE* null_device = std::fopen("/dev/null", "w");
  const ProgressCallback counting = [&](double, const std::string&) { ++calls; };
  const ProgressCallback printing = [&](double fraction, const std::string& step) {
    ++calls;
    const std::string line = fmt::format("\r{:<10} {:3.0f}%  ETA {:.0f} s  ({})", "curve", 100 * fraction, 12.0, step);
    std::fputs(line.c_str(), null_device);
    std::fflush(null_device);
  };
  const std::vector<std::pair<const char*, std::function<void(const ProgressCallback&)>>> stages = {
      {"curve P=4", [&](const ProgressCallback& p) { ho::curve_mesh(shell.linear, *shell.model, {4, ho::NodeSet::GLL}, nullptr, p); }},
      {"split N=5", [&](const ProgressCallback& p) { ho::split_layers(curved, split, families, nullptr, nullptr, p); }},
      {"certify", [&](const ProgressCallback& p) { ho::certify_mesh(split_mesh, 8, 0.0, p); }},
  };
  std::printf("Progress overhead, NACA 0012 O-shell: %zu prisms -> %zu after splitting, %d threads (best of 3)\n",
              shell.linear.elements().size(), split_mesh.elements().size(), omp_get_max_threads());
  std::printf("%-10s | %9s | %9s %8s | %9s %8s | %6s\n", "stage", "none s", "count s", "over", "print s", "over",
              "calls");
  for (const auto& [name, stage] : stages) {
    const double none = best_of_3([&] { stage({}); });
    const double count = best_of_3([&] { stage(counting); });
    calls = 0;
    const double print = best_of_3([&] { stage(printing); });
    std::printf("%-10s | %9.3f | %9.3f %+7.1f%% | %9.3f %+7.1f%% | %6lld\n", name, none, count,
                100 * (count / none - 1), print, 100 * (print / none - 1), calls / 3);
  }
  std::fclose(null_device);
  return 0;
}
