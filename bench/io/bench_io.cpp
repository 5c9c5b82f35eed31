// Writer bytes, seconds and memory per format, on a structured block of nx*ny*nz hexes, each split
// into two order-4 prisms (default 50 x 50 x 20 -> 100000 prisms), gently bent; on a mesh read
// from an ASCII MSH file (equispaced nodes); or on the mesh `semimesh run CASE.toml` writes (the
// paper case: examples/naca0012_wing.toml, GLL nodes, so the writers resample).
// Prints MB, seconds, MB/s and the writer's peak memory above what the process held before it
// (the kernel's peak is reset before each writer: /proc/self/clear_refs) per format, the ASCII
// trio (msh41 + vtu-ascii + nektar-xml) against the compact trio (msh41-binary + vtu + nektar),
// with --config the compact trio written as `semimesh run` writes it (its write stage), and the
// disk's own fsync'd MB/s, which bounds every writer's.
// usage: bench_io [nx ny nz] [output-directory (default /tmp)]
//        bench_io --msh FILE.msh [output-directory [format...]]      (default: every format)
//        bench_io --config CASE.toml [output-directory [format...]]
// With BENCH_IO_KEEP set in the environment the files are kept (bench_io_PID.FORMAT).
#include "semimesh/io/msh.hpp"
#include "semimesh/io/nektar.hpp"
#include "semimesh/io/vtu.hpp"
#include "semimesh/pipeline/config.hpp"
#include "semimesh/pipeline/pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <malloc.h>
#include <string>
#include <vector>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

double peak_memory_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

/// CPU seconds (user + system) of every thread of the process so far: on a loaded machine the
/// wall-clock seconds say little, the CPU seconds stay.
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

/// A /proc/self/status field in MB ("VmRSS", "VmHWM").
double status_mb(const std::string& field) {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind(field + ":", 0) == 0) return std::atof(line.c_str() + field.size() + 1) / 1024.0;
  return 0.0;
}

/// Gives freed memory back, then restarts the kernel's peak-RSS record from the current RSS;
/// returns that RSS in MB.
double reset_peak() {
  malloc_trim(0);
  std::ofstream("/proc/self/clear_refs") << "5";
  return status_mb("VmRSS");
}

namespace pl = semimesh::pipeline;

pl::RunResult run_case(const std::string& config_path, const std::string& dir) {
  pl::Config config = pl::load_config(config_path);
  config.output.formats.clear();  // the mesh only (report.json is still written)
  config.output.pictures = false;
  config.output.directory = dir + "/bench_io_" + std::to_string(::getpid());
  pl::Progress quiet;
  pl::RunResult result = pl::run(config, quiet);
  std::remove((config.output.directory + "/report.json").c_str());
  ::rmdir(config.output.directory.c_str());
  return result;
}

semimesh::mesh::Mesh prism_block(int nx, int ny, int nz, int p) {
  using semimesh::ho::Shape;
  semimesh::mesh::Mesh mesh(p);
  const long lx = long(nx) * p + 1, ly = long(ny) * p + 1, lz = long(nz) * p + 1;
  for (long k = 0; k < lz; ++k)
    for (long j = 0; j < ly; ++j)
      for (long i = 0; i < lx; ++i) {
        const double x = double(i) / p, y = double(j) / p, z = double(k) / p;
        mesh.add_node({x + 0.05 * std::sin(0.3 * y), y + 0.05 * std::sin(0.2 * z), z});
      }
  mesh.reserve(Shape::Prism, std::size_t(2) * nx * ny * nz);
  const Eigen::MatrixX3d ref = semimesh::ho::reference_nodes(Shape::Prism, p);
  std::vector<semimesh::mesh::NodeId> ids(ref.rows());
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (int half = 0; half < 2; ++half) {
          for (int n = 0; n < ref.rows(); ++n) {
            long a = std::lround(ref(n, 0) * p), b = std::lround(ref(n, 1) * p);
            const long c = std::lround((ref(n, 2) + 1) * 0.5 * p);
            if (half) a = p - a, b = p - b;  // second prism: the cell's other triangle, turned 180 degrees
            ids[n] = static_cast<semimesh::mesh::NodeId>((long(k) * p + c) * ly * lx + (long(j) * p + b) * lx +
                                                         long(i) * p + a);
          }
          mesh.add_element(Shape::Prism, ids);
        }
  return mesh;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace semimesh::io;
  const std::string mode = argc >= 3 ? argv[1] : "";
  const bool from_case = mode == "--config";
  const bool from_file = mode == "--msh" || from_case;
  int nx = 50, ny = 50, nz = 20;
  if (!from_file && argc >= 4) nx = std::atoi(argv[1]), ny = std::atoi(argv[2]), nz = std::atoi(argv[3]);
  std::string dir = "/tmp";
  if (from_file && argc >= 4) dir = argv[3];
  std::vector<std::string> only;
  for (int i = 4; from_file && i < argc; ++i) only.push_back(argv[i]);
  if (!from_file && (argc == 5 || argc == 2)) dir = argv[argc - 1];

  const auto t0 = Clock::now();
  pl::RunResult result;
  if (from_case) result = run_case(argv[2], dir);
  auto mesh = from_case ? std::move(result.mesh) : from_file ? read_msh(argv[2]) : prism_block(nx, ny, nz, 4);
  const double build = seconds_since(t0);
  std::printf("mesh: %zu order-%d elements, %zu nodes (%s), %s in %.2f s, %.0f bytes/element, %.0f MB in memory\n",
              mesh.elements().size(), mesh.order(), mesh.num_nodes(),
              mesh.node_set() == semimesh::ho::NodeSet::GLL ? "GLL" : "equispaced",
              from_case ? "meshed" : from_file ? "read" : "built", build,
              double(mesh.memory_bytes()) / mesh.elements().size(), mesh.memory_bytes() / 1e6);
  const double memory_before = peak_memory_mb();
  {  // what every writer does first on a GLL mesh (the write stage does it once for all formats)
    const double rss = reset_peak();
    const auto t = Clock::now();
    const double cpu = cpu_seconds();
    const EquispacedNodes nodes(mesh);
    std::printf("equispaced positions: %.2f s (CPU %.2f s), peak memory +%.0f MB\n", seconds_since(t),
                cpu_seconds() - cpu, status_mb("VmHWM") - rss);
  }

  const std::pair<const char*, std::function<void(const std::string&)>> writers[] = {
      {"msh41", [&](const std::string& p) { write_msh(mesh, p); }},
      {"msh41-binary", [&](const std::string& p) { write_msh(mesh, p, MshVersion::V41, MshEncoding::Binary); }},
      {"msh22", [&](const std::string& p) { write_msh(mesh, p, MshVersion::V22); }},
      {"vtu-ascii", [&](const std::string& p) { write_vtu(mesh, p, VtuEncoding::Ascii); }},
      {"vtu", [&](const std::string& p) { write_vtu(mesh, p, VtuEncoding::CompressedBinary); }},
      {"nektar-xml", [&](const std::string& p) { write_nektar_xml(mesh, p, NektarEncoding::Plain); }},
      {"nektar", [&](const std::string& p) { write_nektar_xml(mesh, p, NektarEncoding::Compressed); }},
  };
  double ascii_mb = 0, ascii_s = 0, compact_mb = 0, compact_s = 0;
  for (const auto& [name, write] : writers) {
    if (!only.empty() && std::find(only.begin(), only.end(), name) == only.end()) continue;
    const std::string path = dir + "/bench_io_" + std::to_string(::getpid()) + "." + name;
    const double rss = reset_peak();
    const auto t = Clock::now();
    const double cpu = cpu_seconds();
    try {
      write(path);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_io: %s: %s\n", name, e.what());
      return 1;
    }
    const double s = seconds_since(t);
    struct stat st {};
    ::stat(path.c_str(), &st);
    const double mb = st.st_size / 1e6;
    std::printf("%-13s %9.1f MB in %6.2f s (CPU %6.2f s): %7.1f MB/s, peak memory +%.0f MB\n", name, mb, s,
                cpu_seconds() - cpu, mb / s, status_mb("VmHWM") - rss);
    const std::string n = name;
    if (n == "msh41" || n == "vtu-ascii" || n == "nektar-xml") ascii_mb += mb, ascii_s += s;
    if (n == "msh41-binary" || n == "vtu" || n == "nektar") compact_mb += mb, compact_s += s;
    if (!std::getenv("BENCH_IO_KEEP")) std::remove(path.c_str());
  }
  if (ascii_mb > 0) std::printf("ASCII   (msh41 + vtu-ascii + nektar-xml):  %9.1f MB in %6.2f s\n", ascii_mb, ascii_s);
  if (compact_mb > 0) std::printf("compact (msh41-binary + vtu + nektar):     %9.1f MB in %6.2f s\n", compact_mb, compact_s);
  if (ascii_mb > 0 && compact_mb > 0) std::printf("compact / ASCII bytes: %.3f\n", compact_mb / ascii_mb);
  if (from_case) {  // the compact trio as `semimesh run` writes it: its write stage
    pl::Config config = pl::load_config(argv[2]);
    config.output.formats = {"msh41-binary", "vtu", "nektar"};
    config.output.pictures = false;
    config.output.directory = dir + "/bench_io_" + std::to_string(::getpid());
    config.output.basename = "trio";
    result.mesh = std::move(mesh);
    const double rss = reset_peak();
    const auto t = Clock::now();
    const double cpu = cpu_seconds();
    pl::Progress quiet;
    pl::write_outputs(config, quiet, result);
    const double s = seconds_since(t);
    double mb = 0;
    for (const std::string& path : result.written_files) {
      struct stat st {};
      ::stat(path.c_str(), &st);
      if (path.find("report.json") == std::string::npos) mb += st.st_size / 1e6;
      std::remove(path.c_str());
    }
    ::rmdir(config.output.directory.c_str());
    std::printf("write stage (msh41-binary + vtu + nektar): %9.1f MB in %6.2f s (CPU %6.2f s), peak memory +%.0f MB\n",
                mb, s, cpu_seconds() - cpu, status_mb("VmHWM") - rss);
  }
  {  // what the disk takes at most: the writers fsync each file before it replaces an older one
    const std::string path = dir + "/bench_io_" + std::to_string(::getpid()) + ".disk";
    const std::vector<char> block(std::size_t{1} << 20, 1);
    const auto t = Clock::now();
    std::FILE* f = std::fopen(path.c_str(), "wb");
    const int blocks = 256;
    for (int i = 0; f && i < blocks; ++i) std::fwrite(block.data(), 1, block.size(), f);
    if (f) std::fflush(f), ::fsync(::fileno(f)), std::fclose(f);
    std::remove(path.c_str());
    std::printf("disk: %d MB written and fsync'd at %.0f MB/s (a bound on any writer's MB/s)\n", blocks,
                blocks * 1.048576 / seconds_since(t));
  }
  std::printf("peak memory of the process before writing: %.0f MB (%s the mesh included)\n", memory_before,
              from_case ? "meshing" : from_file ? "reading" : "building");
  return 0;
}
