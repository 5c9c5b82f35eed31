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

}  // namespace
}  // namespace semimesh::app
