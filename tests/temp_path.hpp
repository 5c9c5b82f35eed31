// Scratch paths for tests: in a folder of the system's temporary folder that belongs to this test
// process, so two checkouts (or two ctest jobs) running the same test at once never write over each
// other, and removed with everything in it when the process exits normally (the suite wrote ~8 GB of
// meshes into /tmp over a few dozen runs when each test was left to clean up after itself).
#pragma once

#include <filesystem>
#include <string>
#include <system_error>
#include <unistd.h>

namespace semimesh::test {

/// `<tmp>/semimesh_<pid>`, made on first use and removed at normal exit.
inline const std::filesystem::path& process_scratch_folder() {
  struct Folder {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("semimesh_" + std::to_string(::getpid()));
    Folder() { std::filesystem::create_directories(path); }
    ~Folder() {
      std::error_code ignored;  // a test's file still open elsewhere must not turn exit into a crash
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  return folder.path;
}

/// `<tmp>/semimesh_<pid>/<name>`; only the process's folder is created, never `name` itself.
inline std::filesystem::path temp_path(const std::string& name) { return process_scratch_folder() / name; }

}  // namespace semimesh::test
