// The files of one run, replacing an earlier run's files of the same names all together or not at
// all. Each file (or folder) is first written in a hidden staging folder inside the output folder
// (same file system, so moving it in is a rename); commit() moves every older file of the same name
// aside, moves the new ones in, and only then deletes the older ones. If a move fails, the moves
// already made are undone. Destroyed without commit() — a writer threw — it deletes the staging
// folder and the output folder is exactly as it was.
#pragma once

#include <string>
#include <vector>

namespace semimesh::io {

class OutputSet {
 public:
  /// Creates `directory/.semimesh-staging-XXXXXX`; throws std::runtime_error naming the directory.
  explicit OutputSet(std::string directory);
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  /// Where to write what will be `directory/name` (a plain name, no folder part) before commit().
  std::string staged(const std::string& name) const;
  /// The final path of a path that staged() returned (or of a name).
  std::string final_path(const std::string& staged_path) const;
  /// Moves everything in the staging folder into the directory; throws std::runtime_error naming
  /// the path on failure, with every older file back in place and nothing new left.
  void commit();

 private:
  std::string directory_, staging_;
  bool committed_ = false;
};

}  // namespace semimesh::io
