// The conformity check run beside the stages after it: it reads element and entity ids only,
// never a node's position (its problems' centroids come at the join), so it may run while the
// checks certify the elements and the writers resample the node positions in place. On a thread
// of its own at the lowest priority (Linux: the thread's nice value, which the threads its parts
// run on inherit), it takes the cores those leave idle (the writers' serial formatting leaves one)
// instead of slowing them.
#pragma once

#include "semimesh/checks/conformity.hpp"
#include "semimesh/mesh/mesh.hpp"

#include <future>

namespace semimesh::pipeline {

class ConformityBeside {
 public:
  /// Starts checking `mesh`, which must not change (but for its node positions) until join().
  explicit ConformityBeside(const mesh::Mesh& mesh);
  /// Waits for the check (a join that did not happen, e.g. on an error, still waits).
  ~ConformityBeside();
  ConformityBeside(const ConformityBeside&) = delete;
  ConformityBeside& operator=(const ConformityBeside&) = delete;

  /// The check's result, its problems located at the mesh's node positions now; rethrows its error.
  /// Once only.
  checks::ConformityResult join();

 private:
  const mesh::Mesh& mesh_;
  checks::ConformityResult found_;
  std::future<void> run_;
};

}  // namespace semimesh::pipeline
