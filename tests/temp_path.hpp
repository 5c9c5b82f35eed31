// Scratch paths for tests: under the system's temporary folder and unique to this test process, so
// two checkouts (or two ctest jobs) running the same test at once never write over each other.
#pragma once

#include <filesystem>
#include <string>
#include <unistd.h>

namespace semimesh::test {

/// `<tmp>/semimesh_<pid>_<name>`; nothing is created or removed.
inline std::filesystem::path temp_path(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("semimesh_" + std::to_string(::getpid()) + "_" + name);
}

}  // namespace semimesh::test
