// zlib (Debian's zlib1g) for the compressed writers: a deflate stream fed piece by piece, and
// base64 output. Level 1 (Z_BEST_SPEED): mesh data compresses nearly as well as at the default
// level, several times faster.
#pragma once

#include "semimesh/io/atomic_file.hpp"

#include <zlib.h>

#include <cstddef>
#include <string>

namespace semimesh::io {

class ZlibStream {
 public:
  explicit ZlibStream(int level = Z_BEST_SPEED);
  ~ZlibStream();
  ZlibStream(const ZlibStream&) = delete;
  ZlibStream& operator=(const ZlibStream&) = delete;

  void add(const void* data, std::size_t bytes);
  template <typename T>
  void add_value(const T& value) {
    add(&value, sizeof value);
  }
  /// Ends the stream and returns the zlib-format (RFC 1950) bytes; add() is no longer allowed.
  const std::string& finish();
  std::size_t raw_bytes() const { return raw_bytes_; }

 private:
  void deflate_staged(int flush);

  z_stream z_{};
  std::string staged_, out_;
  std::size_t raw_bytes_ = 0;
  bool finished_ = false;
};

/// One zlib stream of a whole buffer (VTK compresses each block of an array on its own).
std::string zlib_compress(const char* data, std::size_t bytes, int level = Z_BEST_SPEED);

/// Appends the standard base64 (RFC 4648, padded) encoding of `bytes` to `out`.
void write_base64(AtomicFile& out, const std::string& bytes);

}  // namespace semimesh::io
