// Time of the size field stage's two parts on a CAD file: the shell's size limits on the curved
// body faces (order > 1 only; most of the stage) and the size field itself.
//
//   bench_size_field [FILE.stp [THICKNESS [MAX_SIZE [MIN_SIZE]]]]
//     default: the NekMesh test wing with examples/nekmesh_wing.toml's 20, 500 and 2 (mm)
#include "semimesh/backends/builtin.hpp"
#include "semimesh/surface/cad_roles.hpp"
#include "semimesh/surface/shell_size_limit.hpp"
#include "semimesh/surface/size_field.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdlib>
#include <string>

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace semimesh;
  const std::string path =
      argc > 1 ? argv[1] : std::string(SEMIMESH_TESTDATA_DIR) + "/cad/nektar_3d_bl_wing_naca0012.stp";
  const double thickness = argc > 2 ? std::atof(argv[2]) : 20.0;
  surface::SizeParams sizing;
  sizing.max_size = argc > 3 ? std::atof(argv[3]) : 500.0;
  sizing.min_size = argc > 4 ? std::atof(argv[4]) : 2.0;
  sizing.le_size = sizing.te_size = 0.0;
  const auto& registry = backends::default_registry();
  const auto model = registry.load(registry.backend_for_path(path), cad::Source{path, {}});
  const surface::CadRoles roles = surface::detect_cad_roles(*model);
  const surface::ShellSizing shell{thickness, roles.body};

  auto start = std::chrono::steady_clock::now();
  const double smallest = surface::smallest_shell_size(*model, shell, sizing.max_size);
  const double limits_seconds = seconds_since(start);
  start = std::chrono::steady_clock::now();
  const surface::SizeField field(*model, sizing);
  const double field_seconds = seconds_since(start);
  fmt::print("{}: shell {:.4g}, max_size {:.4g}\n", path, thickness, sizing.max_size);
  fmt::print("  shell limits      {:8.2f} s  (smallest size asked {:.4g})\n", limits_seconds, smallest);
  fmt::print("  size field        {:8.2f} s\n", field_seconds);
  return 0;
}
