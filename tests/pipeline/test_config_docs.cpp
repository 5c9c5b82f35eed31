// docs/config.md lists every key of every section, with the default of the params struct and the
// range of its table row (the rows are the only declaration of a key).
#include "semimesh/pipeline/config.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

namespace semimesh::pipeline {
namespace {

struct DocRow {
  std::string type, default_text, range;
};

// Cells of a markdown table row: split at '|' not preceded by '\', "\|" read as "|", code spans'
// backticks and surrounding blanks removed.
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
      cell += '|';
      ++i;
    } else if (line[i] == '|') {
      out.push_back(cell);
      cell.clear();
    } else if (line[i] != '`') {
      cell += line[i];
    }
  }
  for (std::string& c : out) {
    const auto b = c.find_first_not_of(' '), e = c.find_last_not_of(' ');
    c = b == std::string::npos ? "" : c.substr(b, e - b + 1);
  }
  return out;
}

// section -> key -> row, from the "## [section]" / "### [section]" tables of docs/config.md.
std::map<std::string, std::map<std::string, DocRow>> documented_keys(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << "cannot read " << path;
  std::map<std::string, std::map<std::string, DocRow>> docs;
  std::string line, section;
  while (std::getline(in, line)) {
    const auto open = line.find("# ["), close = line.find(']');
    if (line.rfind("#", 0) == 0 && open != std::string::npos && close != std::string::npos) {
      section = line.substr(open + 3, close - open - 3);
      continue;
    }
    if (section.empty() || line.rfind("| `", 0) != 0) continue;
    const std::vector<std::string> c = cells(line);
    if (c.size() >= 5) docs[section][c[0]] = {c[1], c[2], c[3]};
  }
  return docs;
}

TEST(ConfigDocs, EveryKeyIsDocumentedWithItsDefaultAndRange) {
  const auto docs = documented_keys(std::string(SEMIMESH_SOURCE_DIR) + "/docs/config.md");
  const Config defaults;
  for (const ConfigSection& section : config_sections()) {
    ASSERT_TRUE(docs.count(section.name)) << "docs/config.md has no table for [" << section.name << "]";
    const auto& rows = docs.at(section.name);
    for (const params::Key<Config>& key : section.keys) {
      const std::string expected_default = params::to_text(key.get(defaults));
      const auto row = rows.find(key.name);
      if (row == rows.end()) {
        ADD_FAILURE() << "[" << section.name << "] " << key.name << " is not documented; its row would start: | `"
                      << key.name << "` | ... | `" << expected_default << "` | `" << key.range << "` |";
        continue;
      }
      EXPECT_EQ(row->second.default_text, expected_default) << "default of " << section.name << "." << key.name;
      EXPECT_EQ(row->second.range, key.range) << "range of " << section.name << "." << key.name;
    }
    for (const auto& [name, row] : rows) {
      const bool declared = std::any_of(section.keys.begin(), section.keys.end(),
                                        [&](const params::Key<Config>& k) { return k.name == name; });
      EXPECT_TRUE(declared) << "docs/config.md documents [" << section.name << "] " << name
                            << ", which the config does not read";
    }
  }
}

// The same tables check the defaults: a default out of its own range is a bug in a row or a struct.
TEST(ConfigDocs, EveryDefaultIsInItsRange) {
  const Config defaults;
  for (const ConfigSection& section : config_sections())
    for (const params::Key<Config>& key : section.keys) {
      const params::Value v = key.get(defaults);
      if (std::holds_alternative<std::monostate>(v)) continue;
      EXPECT_TRUE(params::in_range(v, key.range)) << section.name << "." << key.name << " = " << params::to_text(v);
    }
}

}  // namespace
}  // namespace semimesh::pipeline
