// `semimesh run` when the mesh fails its checks: exit 2, nothing written (and nothing already in the
// folder lost), or everything written with --allow-invalid. The failure is real: a floor on the
// scaled Jacobian (checks.min_scaled_jacobian = 0.99) that curved prisms cannot meet.
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include "temp_path.hpp"

namespace semimesh::app {
namespace {

namespace fs = std::filesystem;

RunOptions failing_run(const fs::path& directory) {
  RunOptions options;
  options.config = std::string(SEMIMESH_SOURCE_DIR) + "/tests/pipeline/coarse_wing.toml";
  options.output_directory = directory.string();
  options.overrides = {"highorder.order=2", "boundary_layer.layers=2", "checks.min_scaled_jacobian=0.99",
                       "output.formats=[\"msh41\", \"vtu\"]"};
  options.quiet = true;
  return options;
}

fs::path folder_with_a_file(const std::string& name) {
  const fs::path dir = semimesh::test::temp_path(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "keep.txt") << "an earlier result\n";
  return dir;
}

std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(RunCommand, AFailedCheckExitsWith2AndWritesNothing) {
  const fs::path dir = folder_with_a_file("semimesh_test_run_failed_check");
  std::ostringstream out, err;
  EXPECT_EQ(run_pipeline_command(failing_run(dir), out, err), 2) << err.str();
  EXPECT_NE(err.str().find("validity:"), std::string::npos) << err.str();
  EXPECT_NE(err.str().find("no file written"), std::string::npos) << err.str();
  EXPECT_EQ(files_in(dir), std::vector<std::string>{"keep.txt"});
  fs::remove_all(dir);
}

TEST(RunCommand, AllowInvalidWritesEverythingAndStillExitsWith2) {
  const fs::path dir = folder_with_a_file("semimesh_test_run_allow_invalid");
  RunOptions options = failing_run(dir);
  options.allow_invalid = true;
  std::ostringstream out, err;
  EXPECT_EQ(run_pipeline_command(options, out, err), 2) << err.str();
  EXPECT_NE(err.str().find("written anyway"), std::string::npos) << err.str();
  EXPECT_EQ(files_in(dir), (std::vector<std::string>{"coarse.msh", "coarse.vtu", "keep.txt", "report.json"}));
  std::ifstream report(dir / "report.json");
  std::stringstream text;
  text << report.rdbuf();
  EXPECT_NE(text.str().find("\"checks_passed\": false"), std::string::npos);
  fs::remove_all(dir);
}

// A tapered sharp NACA 0006 whose trailing edge leans forward over the wall: the point the wall
// layer's thickness up from the root is farther from the body than the shell's thickness. The
// refusal names both keys with a value to use (it once said only "too sharp or too open an
// angle"), and the run with either value, parsed from the message, meshes.
TEST(RunCommand, ABodyLeaningAwayAtTheRootIsRefusedWithThicknessesThatRun) {
  const fs::path dir = semimesh::test::temp_path("leaning_root");
  RunOptions options;
  options.config = std::string(SEMIMESH_SOURCE_DIR) + "/examples/naca0012_wing.toml";
  options.output_directory = dir.string();
  options.overrides = {"geometry.naca.code=\"0006\"", "geometry.naca.sweep=9.09", "geometry.naca.taper=0.51",
                       "geometry.naca.te=\"sharp\"", "geometry.body=[\"upper\", \"lower\", \"tip\"]",
                       "geometry.naca.span=1", "highorder.order=1", "boundary_layer.layers=2",
                       "nearfield.thickness=0.028", "wall_layer.thickness=0.1", "sizing.min_size=0.0223",
                       "sizing.le_size=0.0236", "sizing.te_size=0.0423", "sizing.max_size=4", "farfield.box_size=4",
                       "farfield.wall_size=2", "output.formats=[\"msh41\"]"};
  options.quiet = true;
  std::ostringstream out, err;
  ASSERT_EQ(run_pipeline_command(options, out, err), 1) << err.str();
  const std::string message = err.str();
  EXPECT_NE(message.find("leans away from the wall"), std::string::npos) << message;
  for (const std::string key : {"wall_layer.thickness", "nearfield.thickness"}) {
    const std::size_t at = message.find("(" + key + "; e.g. ");
    ASSERT_NE(at, std::string::npos) << key << ": " << message;
    const std::string value = message.substr(at + key.size() + 8, message.find(')', at) - (at + key.size() + 8));
    RunOptions fixed = options;
    fixed.overrides.push_back(key + "=" + value);
    std::ostringstream fixed_out, fixed_err;
    EXPECT_EQ(run_pipeline_command(fixed, fixed_out, fixed_err), 0) << key << "=" << value << ": " << fixed_err.str();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace semimesh::app
