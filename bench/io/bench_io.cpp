// Writer throughput: a structured block of nx*ny*nz hexes, each split into two order-4 prisms
// (default 50 x 50 x 20 -> 100000 prisms), gently bent; prints MB/s per format.
// usage: bench_io [nx ny nz] [output-directory (default /tmp)]
#include "semimesh/io/msh.hpp"
#include "semimesh/io/nektar.hpp"
#include "semimesh/io/vtu.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

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
  int nx = 50, ny = 50, nz = 20;
  if (argc >= 4) nx = std::atoi(argv[1]), ny = std::atoi(argv[2]), nz = std::atoi(argv[3]);
  const std::string dir = argc == 5 ? argv[4] : (argc == 2 ? argv[1] : "/tmp");
  const int order = 4;

  const auto t0 = Clock::now();
  const auto mesh = prism_block(nx, ny, nz, order);
  const double build = seconds_since(t0);
  std::printf("mesh: %zu order-%d prisms, %zu nodes, built in %.2f s, %.0f bytes/element\n", mesh.elements().size(),
              order, mesh.num_nodes(), build, double(mesh.memory_bytes()) / mesh.elements().size());

  const std::pair<const char*, std::function<void(const std::string&)>> writers[] = {
      {"msh41", [&](const std::string& p) { semimesh::io::write_msh(mesh, p); }},
      {"msh22", [&](const std::string& p) { semimesh::io::write_msh(mesh, p, semimesh::io::MshVersion::V22); }},
      {"vtu", [&](const std::string& p) { semimesh::io::write_vtu(mesh, p); }},
      {"xml", [&](const std::string& p) { semimesh::io::write_nektar_xml(mesh, p); }},
  };
  for (const auto& [name, write] : writers) {
    const std::string path = dir + "/bench_io_" + std::to_string(::getpid()) + "." + name;
    const auto t = Clock::now();
    try {
      write(path);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_io: %s: %s\n", name, e.what());
      return 1;
    }
    const double s = seconds_since(t);
    struct stat st {};
    ::stat(path.c_str(), &st);
    std::printf("%-6s %8.1f MB in %6.2f s: %7.1f MB/s\n", name, st.st_size / 1e6, s, st.st_size / 1e6 / s);
    std::remove(path.c_str());
  }
  return 0;
}
