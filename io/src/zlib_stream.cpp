#include "zlib_stream.hpp"

#include <libdeflate.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <future>
#include <stdexcept>
#include <thread>

namespace semimesh::io {
namespace {

constexpr std::size_t kChunkBytes = 1 << 20;
constexpr int kLibdeflateLevel = 1;
constexpr int kStoredLevel = 0;  // libdeflate and zlib alike: uncompressed blocks only

std::runtime_error zlib_error(const char* what, int code) {
  return std::runtime_error(std::string("zlib: ") + what + " failed (code " + std::to_string(code) + ")");
}

std::size_t num_threads() { return std::max(1u, std::thread::hardware_concurrency()); }

/// Raw deflate of one chunk, ended by a sync flush (more chunks follow) or the final block.
std::string deflate_chunk(const std::string& in, bool last, Content content) {
  z_stream z{};
  const int level = content == Content::Doubles ? kStoredLevel : Z_BEST_SPEED;
  int rc = deflateInit2(&z, level, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY);
  if (rc != Z_OK) throw zlib_error("deflateInit2", rc);
  std::string out(deflateBound(&z, in.size()) + 16, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  rc = deflate(&z, last ? Z_FINISH : Z_SYNC_FLUSH);
  const bool done = last ? rc == Z_STREAM_END : rc == Z_OK && z.avail_in == 0;
  out.resize(out.size() - z.avail_out);
  deflateEnd(&z);
  if (!done) throw zlib_error("deflate", rc);
  return out;
}

/// One whole zlib stream, by libdeflate (faster than zlib's fastest level: the VTU of bench_io's
/// prism block 0.49 s against 1.15 s CPU; it compresses whole buffers only, which is what an
/// independent block is; on a real mesh's Float64 points the ratio is within 7 %). A compressor per
/// thread and level: libdeflate's are not shared between threads, and making one costs more than a
/// block.
std::string compress_block(const std::string& in, Content content) {
  struct Compressor {
    explicit Compressor(int level) : c(libdeflate_alloc_compressor(level)) {}
    ~Compressor() { libdeflate_free_compressor(c); }
    libdeflate_compressor* c;
  };
  thread_local Compressor fastest(kLibdeflateLevel), stored(kStoredLevel);
  const Compressor& compressor = content == Content::Doubles ? stored : fastest;
  if (!compressor.c) throw std::runtime_error("libdeflate: cannot allocate a compressor");
  std::string out(libdeflate_zlib_compress_bound(compressor.c, in.size()), '\0');
  const std::size_t bytes = libdeflate_zlib_compress(compressor.c, in.data(), in.size(), out.data(), out.size());
  if (bytes == 0) throw std::runtime_error("libdeflate: a block did not fit its bound");
  out.resize(bytes);
  return out;
}

/// f(i) for i in [0, n), spread over the hardware threads; results in order.
template <typename F>
std::vector<std::string> parallel_map(std::size_t n, F f) {
  std::vector<std::string> out(n);
  const std::size_t threads = std::min(num_threads(), n);
  std::vector<std::future<void>> workers;
  for (std::size_t t = 1; t < threads; ++t)
    workers.push_back(std::async(std::launch::async, [&, t] {
      for (std::size_t i = t; i < n; i += threads) out[i] = f(i);
    }));
  for (std::size_t i = 0; i < n; i += threads) out[i] = f(i);
  for (auto& w : workers) w.get();  // rethrows a worker's exception
  return out;
}

}  // namespace

ZlibStream::ZlibStream(Sink sink, Content content) : sink_(std::move(sink)), content_(content) {
  sink_("\x78\x01", 2);  // zlib header: deflate, 32 KiB window, fastest level
}

void ZlibStream::add(const void* data, std::size_t bytes) {
  if (finished_) throw std::logic_error("ZlibStream::add after finish");
  const char* c = static_cast<const char*>(data);
  while (bytes) {
    const std::size_t take = std::min(bytes, kChunkBytes - staged_.size());
    staged_.append(c, take);
    c += take, bytes -= take;
    if (staged_.size() == kChunkBytes) {
      pending_.push_back(std::move(staged_));
      staged_.clear();
      staged_.reserve(kChunkBytes);
      if (pending_.size() == num_threads()) deflate_pending(false);
    }
  }
}

void ZlibStream::deflate_pending(bool last) {
  // The batch compresses in the background while the caller produces the next one.
  drain();
  in_flight_ = std::async(std::launch::async, [batch = std::move(pending_), last, content = content_] {
    Batch out;
    out.parts = parallel_map(batch.size(), [&](std::size_t i) {
      return deflate_chunk(batch[i], last && i + 1 == batch.size(), content);
    });
    // libdeflate's Adler-32 (vectorised): the same checksum as zlib's, several times faster.
    for (const std::string& chunk : batch)
      out.adler.emplace_back(libdeflate_adler32(1, chunk.data(), chunk.size()), chunk.size());
    return out;
  });
  pending_.clear();
}

void ZlibStream::drain() {
  if (!in_flight_.valid()) return;
  const Batch batch = in_flight_.get();  // rethrows a compression error
  for (std::size_t i = 0; i < batch.parts.size(); ++i) {
    sink_(batch.parts[i].data(), batch.parts[i].size());
    adler_ = adler32_combine(adler_, batch.adler[i].first, static_cast<z_off_t>(batch.adler[i].second));
  }
}

void ZlibStream::finish() {
  if (finished_) return;
  pending_.push_back(std::move(staged_));  // possibly empty: it carries the final block
  deflate_pending(true);
  drain();
  char checksum[4];
  for (int k = 0; k < 4; ++k) checksum[k] = static_cast<char>((adler_ >> (24 - 8 * k)) & 0xff);
  sink_(checksum, 4);
  finished_ = true;
}

std::vector<std::string> zlib_compress_blocks(const std::vector<std::string>& blocks, Content content) {
  return parallel_map(blocks.size(), [&](std::size_t i) { return compress_block(blocks[i], content); });
}

void Base64Out::add(const char* data, std::size_t bytes) {
  const auto* b = reinterpret_cast<const unsigned char*>(data);
  while (carried_ > 0 && bytes > 0) {  // complete the triple carried over from the last piece
    if (carried_ == 2) {
      const unsigned char triple[3] = {carry_[0], carry_[1], *b};
      encode(triple, 3);
      carried_ = 0;
    } else {  // one carried
      carry_[1] = *b;
      carried_ = 2;
    }
    ++b, --bytes;
  }
  const std::size_t whole = bytes - bytes % 3;
  encode(b, whole);
  if (bytes > whole) {  // nothing is carried here: bytes is 0 whenever the loop above left some
    carry_[0] = b[whole];
    if (bytes - whole == 2) carry_[1] = b[whole + 1];
    carried_ = static_cast<int>(bytes - whole);
  }
}

void Base64Out::encode(const unsigned char* b, std::size_t n) {
  static const char* const alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  // Two characters per 12 bits from one lookup: a triple is two lookups and two 2-byte copies.
  static const std::array<std::array<char, 2>, 4096> pairs = [] {
    std::array<std::array<char, 2>, 4096> t{};
    for (unsigned v = 0; v < 4096; ++v) t[v] = {alphabet[v >> 6], alphabet[v & 63]};
    return t;
  }();
  constexpr std::size_t kTextBytes = 1 << 16;
  std::size_t i = 0;
  while (n - i >= 3) {  // the whole triples, a buffer's room at a time
    const std::size_t room = kTextBytes > text_.size() ? (kTextBytes - text_.size()) / 4 : 0;
    const std::size_t triples = std::min((n - i) / 3, std::max<std::size_t>(room, 1));
    const std::size_t at = text_.size();
    text_.resize(at + 4 * triples);
    char* out = text_.data() + at;
    for (std::size_t t = 0; t < triples; ++t, i += 3, out += 4) {
      const unsigned v = (unsigned{b[i]} << 16) | (unsigned{b[i + 1]} << 8) | b[i + 2];
      std::memcpy(out, pairs[v >> 12].data(), 2);
      std::memcpy(out + 2, pairs[v & 4095].data(), 2);
    }
    if (text_.size() >= kTextBytes) out_.write(text_), text_.clear();
  }
  if (i == n) return;  // else the padded tail of one or two bytes (finish)
  const unsigned v = (unsigned{b[i]} << 16) | (i + 1 < n ? unsigned{b[i + 1]} << 8 : 0u);
  const char quad[4] = {alphabet[(v >> 18) & 63], alphabet[(v >> 12) & 63], i + 1 < n ? alphabet[(v >> 6) & 63] : '=',
                        '='};
  text_.append(quad, 4);
}

void Base64Out::finish() {
  encode(carry_, carried_);
  carried_ = 0;
  out_.write(text_);
  text_.clear();
}

}  // namespace semimesh::io
