#include "semimesh/io/output_set.hpp"
#include "os_error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace semimesh::io {
namespace fs = std::filesystem;
namespace {

// A rename and the directory entries it changed survive a crash once the folder is synced.
void sync_folder(const std::string& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

OutputSet::OutputSet(std::string directory) : directory_(std::move(directory)) {
  std::string name = (fs::path(directory_) / ".semimesh-staging-XXXXXX").string();
  if (!::mkdtemp(name.data())) throw detail::os_error("cannot create a staging folder in", directory_);
  staging_ = name;
}

OutputSet::~OutputSet() {
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

std::string OutputSet::staged(const std::string& name) const {
  if (name.empty() || name.find('/') != std::string::npos || name == ".older" || name == "." || name == "..")
    throw std::invalid_argument("output name '" + name + "' is not a plain file name");
  return (fs::path(staging_) / name).string();
}

std::string OutputSet::final_path(const std::string& staged_path) const {
  return (fs::path(directory_) / fs::path(staged_path).filename()).string();
}

void OutputSet::commit() {
  if (committed_) throw std::logic_error("OutputSet::commit called twice");
  const fs::path older_folder = fs::path(staging_) / ".older";
  fs::create_directory(older_folder);
  struct Move {
    fs::path from, to;
  };
  std::vector<Move> done;  // renames made so far, undone in reverse on failure
  const auto move = [&](const fs::path& from, const fs::path& to) {
    if (std::rename(from.c_str(), to.c_str()) != 0)
      throw detail::os_error("cannot move '" + from.string() + "' to", to.string());
    done.push_back({from, to});
  };
  std::vector<fs::path> staged_entries;  // listed first: the loop below empties the folder
  for (const fs::directory_entry& entry : fs::directory_iterator(staging_))
    if (entry.path() != older_folder) staged_entries.push_back(entry.path());
  // A folder never replaces a file nor a file a folder (a user's folder named like a mesh file is
  // not an older mesh): refused before anything moves.
  for (const fs::path& entry : staged_entries) {
    const fs::path target = fs::path(directory_) / entry.filename();
    const fs::file_status older = fs::symlink_status(target);
    if (older.type() != fs::file_type::not_found && fs::is_directory(older) != fs::is_directory(entry))
      throw std::runtime_error("cannot write '" + target.string() + "': a " +
                               (fs::is_directory(older) ? "folder" : "file") + " of that name is in the way");
  }
  try {
    for (const fs::path& entry : staged_entries) {
      const fs::path target = fs::path(directory_) / entry.filename();
      if (fs::symlink_status(target).type() != fs::file_type::not_found) move(target, older_folder / entry.filename());
      move(entry, target);
    }
  } catch (...) {
    for (auto it = done.rbegin(); it != done.rend(); ++it) std::rename(it->to.c_str(), it->from.c_str());
    throw;
  }
  committed_ = true;
  sync_folder(directory_);
  // The older files go with the staging folder (destructor).
}

}  // namespace semimesh::io
