// Keeps OpenCASCADE from printing while a file is read: its default messenger writes the STEP
// reader's statistics and parse errors, and the BREP reader's version complaints, to stdout,
// which would corrupt the output of a caller (e.g. `semimesh ... --json`). Our errors are thrown.
#pragma once

#include <Message_SequenceOfPrinters.hxx>

namespace semimesh::occ {

/// While alive, the default messenger has no printers; the destructor puts them back.
/// Not thread-safe: OCC's default messenger is process-wide.
class QuietMessages {
 public:
  QuietMessages();
  ~QuietMessages();
  QuietMessages(const QuietMessages&) = delete;
  QuietMessages& operator=(const QuietMessages&) = delete;

 private:
  Message_SequenceOfPrinters removed_;
};

}  // namespace semimesh::occ
