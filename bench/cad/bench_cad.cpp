// Throughput of the CAD queries the mesher calls most: surface and curve projections (with and
// without an initial guess) of points near the entities, and the trim test. Single thread.
// Prints a table; not a test.
#include "semimesh/backends/builtin.hpp"
#include "semimesh/cad/model.hpp"
#include "semimesh/cad/trimmed_area.hpp"
#ifdef SEMIMESH_HAVE_VENDOR_FAKE
#include "semimesh/vendor/vendor_backend.hpp"
#endif

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace {

namespace cad = semimesh::cad;
using Clock = std::chrono::steady_clock;

// Points at a small offset from random parameters of each surface (inside its trim, when the
// trim test accepts one of a few tries), with those parameters as the guess for warm starts.
struct SurfaceQuery {
  int surface;
  cad::Vec3 x;
  cad::Vec2 guess;
};
struct CurveQuery {
  int curve;
  cad::Vec3 x;
  double guess;
};

std::vector<SurfaceQuery> surface_queries(const cad::Model& m, int per_surface, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double offset = 1e-3 * m.bbox().diagonal();
  std::vector<SurfaceQuery> out;
  for (int s = 0; s < m.num_surfaces(); ++s) {
    const cad::Surface& surface = m.surface(s);
    const auto box = surface.bounds();
    for (int k = 0; k < per_surface; ++k) {
      cad::Vec2 uv;
      for (int attempt = 0; attempt < 20; ++attempt) {
        uv = {box[0].lo + box[0].length() * unit(rng), box[1].lo + box[1].length() * unit(rng)};
        if (surface.contains(uv)) break;
      }
      out.push_back({s, surface.point(uv) + offset * (unit(rng) - 0.5) * surface.normal(uv), uv});
    }
  }
  std::shuffle(out.begin(), out.end(), rng);
  return out;
}

std::vector<CurveQuery> curve_queries(const cad::Model& m, int per_curve, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double offset = 1e-3 * m.bbox().diagonal();
  std::vector<CurveQuery> out;
  for (int c = 0; c < m.num_curves(); ++c) {
    const auto range = m.curve(c).bounds();
    for (int k = 0; k < per_curve; ++k) {
      double t = range.lo + range.length() * unit(rng);
      cad::Vec3 jitter(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
      out.push_back({c, m.curve(c).point(t) + offset * jitter, t});
    }
  }
  std::shuffle(out.begin(), out.end(), rng);
  return out;
}

// Calls per second of `one(i)` over i = 0..n-1, repeated until at least `min_seconds` elapsed.
double rate(size_t n, const std::function<double(size_t)>& one, double min_seconds = 0.3) {
  size_t calls = 0;
  double sink = 0.0;
  auto start = Clock::now();
  double elapsed = 0.0;
  do {
    for (size_t i = 0; i < n; ++i) sink += one(i);
    calls += n;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  } while (elapsed < min_seconds);
  if (sink == 1.2345) fmt::print("");  // keeps the results alive
  return calls / elapsed;
}

void bench_model(const std::string& label, const cad::Model& m, int per_entity) {
  std::mt19937 rng(42);
  auto sq = surface_queries(m, per_entity, rng);
  auto cq = curve_queries(m, per_entity, rng);
  double s_free = rate(sq.size(), [&](size_t i) { return m.surface(sq[i].surface).project(sq[i].x).distance; });
  double s_guess = rate(sq.size(), [&](size_t i) { return m.surface(sq[i].surface).project(sq[i].x, sq[i].guess).distance; });
  double s_contains = rate(sq.size(), [&](size_t i) { return m.surface(sq[i].surface).contains(sq[i].guess) ? 1.0 : 0.0; });
  double c_free = rate(cq.size(), [&](size_t i) { return m.curve(cq[i].curve).project(cq[i].x).distance; });
  double c_guess = rate(cq.size(), [&](size_t i) { return m.curve(cq[i].curve).project(cq[i].x, cq[i].guess).distance; });
  fmt::print("{:<28} {:>14.3g} {:>14.3g} {:>14.3g} {:>14.3g} {:>14.3g}\n", label, s_free, s_guess, s_contains, c_free, c_guess);
}

// What `semimesh cad-info` spends on a file: loading it and every face's area (the backend's
// exact integrator where it has one, else the generic quadrature). Target: under 2 s per file.
void bench_cad_info(const cad::Registry& registry, const std::string& file) {
  const std::string path = std::string(SEMIMESH_TESTDATA_DIR) + "/cad/" + file;
  const auto start = Clock::now();
  std::unique_ptr<cad::Model> model;
  try {
    model = registry.load("occ", cad::Source{path, {}});
  } catch (const std::exception& e) {
    fmt::print("{:<40} not measured: {}\n", file, e.what());
    return;
  }
  const double load = std::chrono::duration<double>(Clock::now() - start).count();
  int exact = 0;
  for (int s = 0; s < model->num_surfaces(); ++s) exact += cad::face_area(model->surface(s)).exact ? 1 : 0;
  const double total = std::chrono::duration<double>(Clock::now() - start).count();
  fmt::print("{:<40} load {:6.2f} s, load + {} face areas ({} exact) {:6.2f} s\n", file, load, model->num_surfaces(),
             exact, total);
}

}  // namespace

int main() {
  const cad::Registry registry = semimesh::backends::default_registry();
  fmt::print("CAD query throughput, single thread, points within 1e-3 of the model size of the entities\n");
  fmt::print("{:<28} {:>14} {:>14} {:>14} {:>14} {:>14}\n", "model (calls per second)", "surf proj", "surf proj+guess",
             "surf contains", "curve proj", "curve proj+guess");
  auto analytic = registry.load("naca", cad::Source{});
  bench_model("naca (analytic)", *analytic, 200);
  if (registry.available("occ")) bench_model("occ (B-spline NACA wing)", *registry.load("occ", cad::Source{}), 20);
  else fmt::print("{:<28} {}\n", "occ", "not built");
#ifdef SEMIMESH_HAVE_VENDOR_FAKE
  bench_model("vendor (over the fake)", *semimesh::vendor::load_vendor(cad::Source{"naca:naca.code=0012", {}}), 50);
#else
  fmt::print("{:<28} {}\n", "vendor", "fake kernel not built");
#endif

  std::mt19937 rng(7);
  auto sq = surface_queries(*analytic, 1000, rng);
  double r = rate(sq.size(), [&](size_t i) { return analytic->surface(sq[i].surface).project(sq[i].x, sq[i].guess).distance; }, 1.0);
  fmt::print("\nanalytic surface projections/s: {:.3g} (with guess; target >= 1e6 per core)\n", r);

  fmt::print("\ncad-info work per shared STEP file (target: under 2 s each)\n");
  if (registry.available("occ"))
    for (const char* file : {"nektar_3d_bl_wing_naca0012.stp", "onera_m6_sharp_te.stp"}) bench_cad_info(registry, file);
  return 0;
}
