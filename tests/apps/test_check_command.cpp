// `semimesh check`: exit codes, and the figures it reports against closed-form values.
#include "check_command.hpp"

#include "semimesh/io/msh.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include "temp_path.hpp"

namespace semimesh::app {
namespace {

// Straight prisms over the unit right triangle whose top vertices stand at heights h[0..2] above
// their bottom vertices. The map is x = (xi, eta, (1 + zeta) / 2 * h(xi, eta)) with h linear, so
// det J = h(xi, eta) / 2 and the scaled Jacobian (min det J / max det J) is min(h) / max(h).
mesh::Mesh prisms(const std::vector<std::array<double, 3>>& heights) {
  mesh::Mesh m(1);
  double offset = 0.0;
  for (const auto& h : heights) {
    const mesh::NodeId a = m.add_node({offset, 0, 0}), b = m.add_node({offset + 1, 0, 0}), c = m.add_node({offset, 1, 0});
    const mesh::NodeId d = m.add_node({offset, 0, h[0]}), e = m.add_node({offset + 1, 0, h[1]}),
                       f = m.add_node({offset, 1, h[2]});
    m.add_element(ho::Shape::Prism, {a, b, c, d, e, f});
    offset += 2.0;
  }
  return m;
}

std::string scratch(const std::string& name) {
  const std::filesystem::path dir = semimesh::test::temp_path("check_command");
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

double json_value(const std::string& json, const std::string& key) {
  std::smatch m;
  const std::regex pattern("\"" + key + "\": ([-0-9.e+]+)");
  if (!std::regex_search(json, m, pattern)) ADD_FAILURE() << "no " << key << " in " << json;
  return std::strtod(m[1].str().c_str(), nullptr);
}

TEST(CheckCommand, ReportsTheClosedFormScaledJacobians) {
  const std::string path = scratch("three_prisms.msh");
  io::write_msh(prisms({{{1, 2, 4}}, {{1, 1, 2}}, {{3, 3, 3}}}), path);  // scaled J 0.25, 0.5, 1
  std::ostringstream out, err;
  ASSERT_EQ(run_check_command({path, true}, out, err), 0) << err.str();
  EXPECT_NEAR(json_value(out.str(), "min_scaled_jacobian"), 0.25, 1e-9) << out.str();
  EXPECT_NEAR(json_value(out.str(), "median_scaled_jacobian"), 0.5, 1e-9) << out.str();
  EXPECT_NE(out.str().find("\"elements\": {\"prism\": {\"1\": 3}"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("\"invalid\": []"), std::string::npos) << out.str();
}

// What `semimesh run` writes by default (binary MSH 4.1) is checked as the ASCII file is.
TEST(CheckCommand, ReadsTheBinaryMshRunWritesByDefault) {
  const std::string path = scratch("three_prisms_binary.msh");
  io::write_msh(prisms({{{1, 2, 4}}, {{1, 1, 2}}, {{3, 3, 3}}}), path, io::MshVersion::V41, io::MshEncoding::Binary);
  std::ostringstream out, err;
  ASSERT_EQ(run_check_command({path, true}, out, err), 0) << err.str();
  EXPECT_NEAR(json_value(out.str(), "min_scaled_jacobian"), 0.25, 1e-9) << out.str();
  EXPECT_NE(out.str().find("\"elements\": {\"prism\": {\"1\": 3}"), std::string::npos) << out.str();
}

TEST(CheckCommand, NamesTheInvalidElementAndExitsWith2) {
  const std::string path = scratch("folded.msh");
  io::write_msh(prisms({{{1, 1, 1}}, {{1, 1, -0.5}}}), path);  // the second one's top crosses its bottom
  std::ostringstream out, err;
  EXPECT_EQ(run_check_command({path, false}, out, err), 2);
  EXPECT_NE(out.str().find("invalid elements: 1"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("element 1 (prism)"), std::string::npos) << out.str();
}

TEST(CheckCommand, MissingFileIsBadInputNamingIt) {
  const std::string path = scratch("missing.msh");
  std::ostringstream out, err;
  EXPECT_EQ(run_check_command({path, false}, out, err), 1);
  EXPECT_NE(err.str().find(path), std::string::npos) << err.str();
}

}  // namespace
}  // namespace semimesh::app
