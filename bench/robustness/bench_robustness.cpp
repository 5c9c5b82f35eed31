// Robustness sweep: N random plausible configurations of the analytic wing (a subset on the OCC
// backend), each run through the `semimesh` command line as a user would. Prints one line per run
// (exit code, seconds, min scaled Jacobian), the pass rate, and for every run that did not end
// with exit 0 the command that reproduces it and its error lines (its files stay in DIR/run<N>; a
// passing run's are removed). Exit 1 must be a refusal that names the place and the remedy;
// exit 2 (invalid mesh produced) and 3 (internal error) are bugs.
//
//   bench_robustness [--exe PATH] [--config TOML] [--runs N] [--seed S] [--occ-every K] [--out DIR]
//
// Ranges (the issue's, issue #10): order 1-5, layers 1-8, ratio 1-3, thickness 0.02-0.2, min_size
// 0.01-0.04, le_size 0.02-0.08, te_size 0.01-0.05, NACA 0006/0012/0018/2412/4412, sweep 0-35 deg,
// taper 0.3-1, blunt or sharp trailing edge; span 1 and a coarse far field (box and wall sizes 4
// and 2) keep a run to seconds.
#include <fmt/format.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <sys/wait.h>
#include <vector>

#ifndef SEMIMESH_BINARY
#define SEMIMESH_BINARY "semimesh"
#endif
#ifndef SEMIMESH_EXAMPLE
#define SEMIMESH_EXAMPLE "examples/naca0012_wing_o.toml"
#endif

namespace {

struct Options {
  std::string exe = SEMIMESH_BINARY;
  std::string config = SEMIMESH_EXAMPLE;
  int runs = 200;
  unsigned seed = 1;
  int occ_every = 10;  // every K-th run on the OCC backend; 0: none
  std::string out = "/tmp/semimesh_robustness";
};

struct Outcome {
  int exit_code = -1;
  double seconds = 0.0;
  std::string output;
};

Outcome run(const std::string& command) {
  Outcome o;
  const auto start = std::chrono::steady_clock::now();
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return o;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe)) o.output += buffer.data();
  const int status = pclose(pipe);
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return o;
}

// The lines of `text` that start with `prefix` (after leading blanks).
std::vector<std::string> lines_with(const std::string& text, const std::string& prefix) {
  std::vector<std::string> found;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    const std::size_t first = line.find_first_not_of(' ');
    if (first != std::string::npos && line.compare(first, prefix.size(), prefix) == 0) found.push_back(line);
    start = end + 1;
  }
  return found;
}

std::string configuration(std::mt19937& rng, bool occ) {
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  auto integer = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  auto round3 = [](double x) { return fmt::format("{:.3g}", x); };
  static const std::array<const char*, 5> codes = {"0006", "0012", "0018", "2412", "4412"};
  const bool sharp = integer(0, 1) == 1;
  std::string s;
  auto set = [&](const std::string& key, const std::string& value) { s += " --set '" + key + "=" + value + "'"; };
  if (occ) set("geometry.backend", "\"occ\"");
  set("geometry.naca.code", fmt::format("\"{}\"", codes[integer(0, 4)]));
  set("geometry.naca.sweep", round3(uniform(0.0, 35.0)));
  set("geometry.naca.taper", round3(uniform(0.3, 1.0)));
  set("geometry.naca.te", sharp ? "\"sharp\"" : "\"blunt\"");
  set("geometry.body", sharp ? "[\"upper\", \"lower\", \"tip\"]" : "[\"upper\", \"lower\", \"te_base\", \"tip\"]");
  set("highorder.order", std::to_string(integer(1, 5)));
  set("boundary_layer.layers", std::to_string(integer(1, 8)));
  set("boundary_layer.ratio", round3(uniform(1.0, 3.0)));
  set("nearfield.thickness", round3(uniform(0.02, 0.2)));
  set("sizing.min_size", round3(uniform(0.01, 0.04)));
  set("sizing.le_size", round3(uniform(0.02, 0.08)));
  set("sizing.te_size", round3(uniform(0.01, 0.05)));
  set("geometry.naca.span", "1");  // a short wing keeps a run to seconds
  set("sizing.max_size", "4");
  set("farfield.box_size", "4");
  set("farfield.wall_size", "2");
  set("output.formats", "[\"msh41\"]");
  return s;
}

int parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) return fmt::print(stderr, "bench_robustness: {} needs a value\n", a), 1;
    const std::string v = argv[++i];
    if (a == "--exe") o.exe = v;
    else if (a == "--config") o.config = v;
    else if (a == "--runs") o.runs = std::stoi(v);
    else if (a == "--seed") o.seed = static_cast<unsigned>(std::stoul(v));
    else if (a == "--occ-every") o.occ_every = std::stoi(v);
    else if (a == "--out") o.out = v;
    else return fmt::print(stderr, "bench_robustness: unknown option {}\n", a), 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (parse(argc, argv, o) != 0) return 1;
  std::mt19937 rng(o.seed);
  std::map<int, int> by_exit;
  int config_errors = 0;  // runs the config refused (e.g. the OCC backend with an analytic fuselage wall)
  std::vector<std::string> reports;
  double total_seconds = 0.0;
  fmt::print("robustness sweep: {} runs, seed {}, OCC every {}\n", o.runs, o.seed, o.occ_every);
  for (int i = 0; i < o.runs; ++i) {
    const bool occ = o.occ_every > 0 && i % o.occ_every == o.occ_every - 1;
    const std::string command =
        fmt::format("{} run {} -o {}/run{}{}", o.exe, o.config, o.out, i, configuration(rng, occ));
    const Outcome r = run(command);
    total_seconds += r.seconds;
    ++by_exit[r.exit_code];
    config_errors += !lines_with(r.output, "semimesh: config error").empty();
    const auto jacobian = lines_with(r.output, "min scaled Jacobian");
    fmt::print("run {:3} {} exit {} {:6.1f} s {}\n", i, occ ? "occ " : "naca", r.exit_code, r.seconds,
               jacobian.empty() ? std::string() : jacobian.front());
    std::fflush(stdout);
    // A passing run's files are of no further use (a sweep of 200 left gigabytes in /tmp); the
    // others' stay for inspection.
    if (r.exit_code == 0) std::filesystem::remove_all(fmt::format("{}/run{}", o.out, i));
    if (r.exit_code == 0 && !std::getenv("BENCH_PRINT_ALL")) continue;
    std::string report = fmt::format("run {} exit {}:\n  {}\n", i, r.exit_code, command);
    for (const char* prefix : {"semimesh: error", "semimesh: config error", "semimesh: internal", "semimesh: validity", "element "})
      for (const std::string& line : lines_with(r.output, prefix)) report += "  " + line + "\n";
    reports.push_back(report);
  }
  fmt::print("\n");
  for (const std::string& r : reports) fmt::print("{}", r);
  fmt::print("\npassed (exit 0): {} of {} ({:.1f}%)\n", by_exit[0], o.runs, 100.0 * by_exit[0] / o.runs);
  for (const auto& [code, count] : by_exit) fmt::print("exit {}: {}\n", code, count);
  if (config_errors > 0)
    fmt::print("of which config errors: {} (the configuration refused, no mesh tried: e.g. --occ-every with a config "
               "whose wall only the analytic backend has)\n", config_errors);
  fmt::print("total {:.0f} s, mean {:.1f} s per run\n", total_seconds, total_seconds / o.runs);
  std::error_code ignored;
  if (std::filesystem::is_empty(o.out, ignored) && !ignored)
    std::filesystem::remove(o.out, ignored);
  else if (by_exit[0] < o.runs)
    fmt::print("the files of the runs that did not pass are in {}/run<N>\n", o.out);
  return 0;
}
