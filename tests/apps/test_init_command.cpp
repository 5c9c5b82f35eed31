// `semimesh init`: the text it writes is read back by the config reader as the defaults, key by key.
#include "init_command.hpp"

#include "semimesh/pipeline/config.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

namespace semimesh::app {
namespace {

TEST(InitCommand, TheDefaultConfigReadsBackAsTheDefaults) {
  const std::string text = default_config_text();
  const pipeline::Config parsed = pipeline::parse_config(text, "init.toml");
  const pipeline::Config defaults;
  int keys = 0;
  for (const pipeline::ConfigSection& section : pipeline::config_sections())
    for (const params::Key<pipeline::Config>& key : section.keys) {
      EXPECT_EQ(params::to_text(key.get(parsed)), params::to_text(key.get(defaults))) << section.name << "." << key.name;
      EXPECT_NE(text.find("# " + key.doc), std::string::npos) << "no doc line for " << section.name << "." << key.name;
      ++keys;
    }
  EXPECT_GT(keys, 30);
}

TEST(InitCommand, KeepsAnExistingFileUnlessForced) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "semimesh_test_init.toml";
  std::filesystem::remove(path);
  std::ostringstream out, err;
  ASSERT_EQ(run_init_command({path.string(), false}, out, err), 0) << err.str();
  ASSERT_TRUE(std::filesystem::exists(path));
  std::filesystem::resize_file(path, 10);
  EXPECT_EQ(run_init_command({path.string(), false}, out, err), 1);
  EXPECT_NE(err.str().find("exists"), std::string::npos) << err.str();
  EXPECT_EQ(std::filesystem::file_size(path), 10u);  // untouched
  EXPECT_EQ(run_init_command({path.string(), true}, out, err), 0);
  EXPECT_EQ(std::filesystem::file_size(path), default_config_text().size());
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace semimesh::app
