// zlib (Debian's zlib1g) for the compressed writers. Level 1 (Z_BEST_SPEED): mesh data compresses
// nearly as well as at the default level, several times faster. Data is compressed in 1 MiB chunks
// on every hardware thread at once: a ZlibStream deflates each chunk on its own and joins them
// with sync flushes into one zlib stream (the way pigz does; the dictionary restarts per chunk,
// which costs a fraction of a percent); zlib_compress_blocks compresses independent blocks.
#pragma once

#include "semimesh/io/atomic_file.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace semimesh::io {

/// What the data is: doubles barely repeat, so LZ77 matching (the zlib default) costs much time
/// for little gain on them; run-length matching keeps most of the gain at 2-3 times the speed.
enum class Content { Integers, Doubles };

/// One zlib-format (RFC 1950) stream fed piece by piece.
class ZlibStream {
 public:
  explicit ZlibStream(Content content = Content::Integers) : content_(content) {}
  void add(const void* data, std::size_t bytes);
  template <typename T>
  void add_value(const T& value) {
    add(&value, sizeof value);
  }
  /// Ends the stream and returns its bytes; add() is no longer allowed.
  const std::string& finish();

 private:
  void deflate_pending(bool last);

  std::vector<std::string> pending_;  // full chunks waiting for a free thread each
  std::string staged_, body_, out_;
  Content content_;
  unsigned long adler_ = 1;
  bool finished_ = false;
};

/// Each block compressed as its own zlib stream (VTK's vtkZLibDataCompressor layout), in parallel.
std::vector<std::string> zlib_compress_blocks(const std::vector<std::string>& blocks, Content content);

/// Appends the standard base64 (RFC 4648, padded) encoding of `bytes` to `out`.
void write_base64(AtomicFile& out, const std::string& bytes);

}  // namespace semimesh::io
