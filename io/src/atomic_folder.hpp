// A folder of files written together with the index file that names them (a ParaView .vtm and its
// folder of pieces): the pieces go to a temporary folder beside the final one; commit() moves an
// older folder aside, moves the new one in, commits the index and only then deletes the old folder.
// If anything fails the old folder and index stay as they were and nothing new is left behind.
#pragma once

#include "semimesh/io/atomic_file.hpp"

#include <string>

namespace semimesh::io {

class AtomicFolder {
 public:
  /// Creates `path.tmp-XXXXXX`; throws std::runtime_error naming the directory if it cannot, or
  /// naming `path` when something other than a folder stands there.
  explicit AtomicFolder(std::string path);
  ~AtomicFolder();
  AtomicFolder(const AtomicFolder&) = delete;
  AtomicFolder& operator=(const AtomicFolder&) = delete;

  /// Where to write the piece `name` before commit().
  std::string file(const std::string& name) const { return temp_path_ + "/" + name; }
  /// Puts the folder at its path (replacing an older one) and commits `index`; throws
  /// std::runtime_error naming the path on failure, with the older folder restored.
  void commit(AtomicFile& index);

 private:
  std::string path_, temp_path_;
  bool committed_ = false;
};

}  // namespace semimesh::io
