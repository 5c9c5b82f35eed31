// Throughput of the high-order stages on the NACA 0012 O-shell: curving, splitting (N = 5, r = 2)
// and certification at P = 2, 4, 6 (GLL), with all OpenMP threads, and the share of the curving
// time spent in CAD queries (curving run again on one thread through a timing copy of the model).
#include "naca_o_shell.hpp"
#include "timed_model.hpp"

#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/ho/mesh_validity.hpp"
#include "semimesh/ho/splitting/split_layers.hpp"

#include <omp.h>

#include <chrono>
#include <cstdio>
#include <numeric>

namespace {

using namespace semimesh;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main() {
  const bench::NacaOShell shell = bench::naca_o_shell();
  const cad::Model* model = shell.model.get();
  const mesh::Mesh& linear = shell.linear;
  std::vector<std::size_t> all(linear.elements().size());
  std::iota(all.begin(), all.end(), std::size_t{0});

  std::printf("NACA 0012 O-shell: %zu prisms, %d threads; elements/s (input elements for curving and splitting, "
              "output prisms for certification)\n",
              linear.elements().size(), omp_get_max_threads());
  std::printf("%3s | %12s | %12s | %12s | %8s | %12s | %10s\n", "P", "curve el/s", "split el/s", "certify el/s",
              "invalid", "CAD share 1t", "CAD calls");
  for (int P : {2, 4, 6}) {
    const ho::CurvingParams params{P, ho::NodeSet::GLL};
    auto start = std::chrono::steady_clock::now();
    const mesh::Mesh curved = ho::curve_mesh(linear, *model, params);
    const double t_curve = seconds_since(start);
    start = std::chrono::steady_clock::now();
    const mesh::Mesh split = ho::split_layers(curved, all, {5, 2.0});
    const double t_split = seconds_since(start);
    start = std::chrono::steady_clock::now();
    const ho::MeshValidity validity = ho::certify_mesh(split);
    const double t_certify = seconds_since(start);

    bench::CadClock clock;
    const std::unique_ptr<cad::Model> timed = bench::timed_model(*model, clock);
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    start = std::chrono::steady_clock::now();
    ho::curve_mesh(linear, *timed, params);
    const double t_serial = seconds_since(start);
    omp_set_num_threads(threads);

    const double n = static_cast<double>(linear.elements().size());
    std::printf("%3d | %12.0f | %12.0f | %12.0f | %8zu | %11.1f%% | %10lld\n", P, n / t_curve, n / t_split,
                static_cast<double>(split.elements().size()) / t_certify, validity.invalid,
                100.0 * static_cast<double>(clock.nanoseconds.load()) * 1e-9 / t_serial, clock.calls.load());
  }
  return 0;
}
