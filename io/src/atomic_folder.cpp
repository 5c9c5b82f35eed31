#include "atomic_folder.hpp"
#include "os_error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sys/stat.h>
#include <stdexcept>
#include <vector>

namespace semimesh::io {
namespace {

// A new empty folder `prefix` + random suffix; its path.
std::string make_temporary_folder(const std::string& prefix) {
  std::vector<char> name(prefix.begin(), prefix.end());
  const std::string suffix = "XXXXXX";
  name.insert(name.end(), suffix.begin(), suffix.end());
  name.push_back('\0');
  if (!::mkdtemp(name.data())) throw detail::os_error("cannot create a temporary folder", prefix + suffix);
  // mkdtemp makes it 0700; a mesh folder gets the usual 0777 less the umask (see AtomicFile).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::chmod(name.data(), 0777 & ~mask);
  return name.data();
}

}  // namespace

AtomicFolder::AtomicFolder(std::string path) : path_(std::move(path)) {
  if (std::filesystem::exists(path_) && !std::filesystem::is_directory(path_))
    throw std::runtime_error("cannot write the folder '" + path_ + "': a file that is not a folder is in the way");
  temp_path_ = make_temporary_folder(path_ + ".tmp-");
}

AtomicFolder::~AtomicFolder() {
  if (committed_) return;
  std::error_code ignored;
  std::filesystem::remove_all(temp_path_, ignored);
}

void AtomicFolder::commit(AtomicFile& index) {
  namespace fs = std::filesystem;
  std::error_code ignored;
  // An older folder is renamed onto an empty temporary one (rename replaces an empty folder).
  std::string old;
  if (fs::exists(path_)) {
    old = make_temporary_folder(path_ + ".old-");
    if (std::rename(path_.c_str(), old.c_str()) != 0) {
      const std::runtime_error error = detail::os_error("cannot move aside the folder", path_);
      fs::remove(old, ignored);
      throw error;
    }
  }
  const auto restore = [&] {
    if (!old.empty()) std::rename(old.c_str(), path_.c_str());
  };
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    const std::runtime_error error = detail::os_error("cannot rename the temporary folder to", path_);
    restore();
    throw error;
  }
  try {
    index.commit();
  } catch (...) {
    fs::remove_all(path_, ignored);
    restore();
    throw;
  }
  committed_ = true;
  if (!old.empty()) fs::remove_all(old, ignored);
}

}  // namespace semimesh::io
