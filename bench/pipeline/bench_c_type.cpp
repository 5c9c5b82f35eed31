// C-type and H-type against O-type near field on the same case: time per stage and peak memory of
// the whole pipeline (the C-type adds the junction hexes, the wall layer and the second split
// direction; the H-type the wake block, its pyramids and the weld). Each topology runs in its own
// process (this program run with "O", "C" or "H"), so each peak resident memory is its own.
//
//   bench_c_type [ORDER [LAYERS [SIZE]]]   defaults: order 2, 5 layers, size factor 1 (the coarse
//                                          CLI case: ~18k linear elements; 0.5 about doubles it)
// Prints one row per topology and the C- and H-type's overheads in percent of the O-type's total and
// per element (the wall layer and the wake are new blocks of elements: their cost grows with them).
#include "semimesh/pipeline/config.hpp"
#include "semimesh/pipeline/pipeline.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace pl = semimesh::pipeline;

pl::Config config_for(const std::string& topology, int order, int layers, double size, const std::string& directory) {
  pl::Config c;
  c.geometry.naca.span = 1.0;
  c.geometry.naca.box = {-3.0, -3.0, 0.0, 4.0, 3.0, 3.0};
  c.nearfield.topology = topology;
  c.nearfield.shell.thickness = 0.05;
  c.wall_layer.thickness = 0.05;
  c.wall_layer.split.layers = layers;
  c.wake.length = 1.5;
  c.boundary_layer.split.layers = layers;
  c.sizing.size.max_size = 1.0 * size;
  c.sizing.size.min_size = 0.02 * size;
  c.sizing.size.curvature_segments = 2.0 / size;
  c.sizing.size.le_size = 0.06 * size;
  c.sizing.size.te_size = 0.03 * size;
  c.farfield.box_size = 1.0 * size;
  c.farfield.wall_size = 0.6 * size;
  c.highorder.order = order;
  c.output.formats = {"msh41"};
  c.output.directory = directory;
  return c;
}

// One run; prints "stage:seconds ..." then "total elements peak valid" on one line.
int run_one(const std::string& topology, int order, int layers, double size) {
  const std::string directory =
      (std::filesystem::temp_directory_path() / ("semimesh_bench_c_type_" + topology)).string();
  pl::Progress quiet;
  const pl::RunResult r = pl::run(config_for(topology, order, layers, size, directory), quiet);
  std::filesystem::remove_all(directory);
  for (const pl::StageTiming& s : r.stages) fmt::print("{}={:.3f};", s.name, s.seconds);
  fmt::print("|{:.3f}|{}|{:.0f}|{}\n", r.total_seconds(), r.mesh.elements().size(), r.peak_memory_mb,
             r.checks_passed() ? "yes" : "NO");
  return 0;
}

std::string capture(const std::string& command) {
  std::string out;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[4096];
    while (fgets(buffer, sizeof buffer, pipe)) out += buffer;
    pclose(pipe);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 5) return run_one(argv[1], std::atoi(argv[2]), std::atoi(argv[3]), std::atof(argv[4]));
  const int order = argc > 1 ? std::atoi(argv[1]) : 2;
  const int layers = argc > 2 ? std::atoi(argv[2]) : 5;
  const double size = argc > 3 ? std::atof(argv[3]) : 1.0;
  if (order < 1 || order > 8 || layers < 1 || !(size > 0)) {
    fmt::print(stderr, "usage: bench_c_type [ORDER 1..8 [LAYERS >= 1 [SIZE > 0]]]\n");
    return 1;
  }
  double totals[3] = {0, 0, 0}, elements[3] = {0, 0, 0};
  const char* topologies[3] = {"O", "C", "H"};
  for (int k = 0; k < 3; ++k) {
    const std::string line = capture(fmt::format("'{}' {} {} {} {}", argv[0], topologies[k], order, layers, size));
    const auto bar = line.find('|');
    if (bar == std::string::npos) {
      fmt::print(stderr, "bench_c_type: the {} run failed: {}\n", topologies[k], line);
      return 1;
    }
    std::string stages = line.substr(0, bar), rest = line.substr(bar + 1);
    for (char& c : stages)
      if (c == ';') c = ' ';
    std::vector<std::string> fields;
    for (std::size_t start = 0, end; start <= rest.size(); start = end + 1) {
      end = rest.find('|', start);
      if (end == std::string::npos) end = rest.size();
      fields.push_back(rest.substr(start, end - start));
    }
    totals[k] = std::atof(fields[0].c_str());
    elements[k] = std::atof(fields[1].c_str());
    fmt::print("{}-type: total {} s, {} elements, peak {} MB, checks passed {}\n  stages (s): {}\n", topologies[k],
               fields[0], fields[1], fields[2], fields.size() > 3 ? fields[3] : "?", stages);
  }
  for (int k = 1; k < 3; ++k)
    fmt::print("{}-type over O-type total: {:+.1f} %; per element: {:+.1f} % ({:+.0f} % elements)\n", topologies[k],
               100.0 * (totals[k] - totals[0]) / totals[0],
               100.0 * (totals[k] / elements[k] - totals[0] / elements[0]) / (totals[0] / elements[0]),
               100.0 * (elements[k] - elements[0]) / elements[0]);
  return 0;
}
