// Deflate for the compressed writers, at the fastest level (mesh data compresses nearly as well as
// at the default level, several times faster), on every hardware thread at once. Arrays of doubles
// (the node coordinates) go in stored blocks: deflate gains 16-19 % on them at ~100 MB/s a core,
// ten times slower than the disk, where ids and indices shrink 3-7 times (docs/benchmarks.md).
//  - ZlibStream (Nektar++'s B64Z: one zlib stream per array): zlib (Debian's zlib1g), 1 MiB chunks
//    each deflated on its own and joined with sync flushes into one stream (the way pigz does; the
//    dictionary restarts per chunk, which costs a fraction of a percent). libdeflate cannot join
//    chunks: it ends every buffer with a final block.
//  - zlib_compress_blocks (VTK's independent blocks): libdeflate (Debian's libdeflate0), whole
//    buffers, faster than zlib (bench/io/bench_io prints the figures).
// Chunk and block boundaries depend on the data only, so the bytes do not depend on the threads.
// Output is handed on as it is made (to the file): nothing holds a whole array. A ZlibStream
// compresses one batch in the background while its caller produces the next.
#pragma once

#include "semimesh/io/atomic_file.hpp"

#include <cstddef>
#include <functional>
#include <future>
#include <utility>
#include <string>
#include <vector>

namespace semimesh::io {

/// What the data is: doubles barely repeat, so deflate costs much time for little gain on them:
/// they are stored (deflate's uncompressed blocks: a valid stream that every reader inflates).
enum class Content { Integers, Doubles };

/// One zlib-format (RFC 1950) stream fed piece by piece; its bytes go to `sink` in order.
class ZlibStream {
 public:
  using Sink = std::function<void(const char* data, std::size_t bytes)>;
  explicit ZlibStream(Sink sink, Content content = Content::Integers);
  void add(const void* data, std::size_t bytes);
  template <typename T>
  void add_value(const T& value) {
    add(&value, sizeof value);
  }
  /// Ends the stream (the last chunk and the checksum go to the sink); add() is no longer allowed.
  void finish();

 private:
  struct Batch {
    std::vector<std::string> parts;                               // deflated chunks, in order
    std::vector<std::pair<unsigned long, std::size_t>> adler;     // each chunk's Adler-32 and length
  };
  void deflate_pending(bool last);
  void drain();  // waits for the batch in flight and hands its bytes to the sink

  Sink sink_;
  std::future<Batch> in_flight_;
  std::vector<std::string> pending_;  // full chunks waiting for a free thread each
  std::string staged_;
  Content content_;
  unsigned long adler_ = 1;
  bool finished_ = false;
};

/// Each block compressed as its own zlib stream (VTK's vtkZLibDataCompressor layout), in parallel.
std::vector<std::string> zlib_compress_blocks(const std::vector<std::string>& blocks, Content content);

/// Standard base64 (RFC 4648, padded) of a byte stream fed piece by piece, appended to a file.
class Base64Out {
 public:
  explicit Base64Out(AtomicFile& out) : out_(out) {}
  void add(const char* data, std::size_t bytes);
  /// Encodes the last one or two bytes with padding.
  void finish();

 private:
  void encode(const unsigned char* b, std::size_t n);  // n a multiple of 3, or the padded tail
  AtomicFile& out_;
  unsigned char carry_[2] = {0, 0};
  int carried_ = 0;
  std::string text_;
};

}  // namespace semimesh::io
