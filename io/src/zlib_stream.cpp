#include "zlib_stream.hpp"

#include <stdexcept>

namespace semimesh::io {
namespace {

constexpr std::size_t kStageBytes = 1 << 16;  // small values are gathered before deflate sees them

std::runtime_error zlib_error(const char* what, int code) {
  return std::runtime_error(std::string("zlib: ") + what + " failed (code " + std::to_string(code) + ")");
}

}  // namespace

ZlibStream::ZlibStream(int level) {
  const int rc = deflateInit(&z_, level);
  if (rc != Z_OK) throw zlib_error("deflateInit", rc);
  staged_.reserve(kStageBytes);
}

ZlibStream::~ZlibStream() { deflateEnd(&z_); }

void ZlibStream::add(const void* data, std::size_t bytes) {
  if (finished_) throw std::logic_error("ZlibStream::add after finish");
  raw_bytes_ += bytes;
  staged_.append(static_cast<const char*>(data), bytes);
  if (staged_.size() >= kStageBytes) deflate_staged(Z_NO_FLUSH);
}

void ZlibStream::deflate_staged(int flush) {
  z_.next_in = reinterpret_cast<Bytef*>(staged_.data());
  z_.avail_in = static_cast<uInt>(staged_.size());
  int rc;
  do {
    const std::size_t had = out_.size();
    out_.resize(had + kStageBytes);
    z_.next_out = reinterpret_cast<Bytef*>(out_.data() + had);
    z_.avail_out = static_cast<uInt>(kStageBytes);
    rc = deflate(&z_, flush);
    if (rc == Z_STREAM_ERROR) throw zlib_error("deflate", rc);
    out_.resize(had + kStageBytes - z_.avail_out);
  } while (z_.avail_out == 0 || (flush == Z_FINISH && rc != Z_STREAM_END));
  staged_.clear();
}

const std::string& ZlibStream::finish() {
  if (!finished_) deflate_staged(Z_FINISH);
  finished_ = true;
  return out_;
}

std::string zlib_compress(const char* data, std::size_t bytes, int level) {
  uLongf size = compressBound(bytes);
  std::string out(size, '\0');
  const int rc = compress2(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(data), bytes,
                           level);
  if (rc != Z_OK) throw zlib_error("compress2", rc);
  out.resize(size);
  return out;
}

void write_base64(AtomicFile& out, const std::string& bytes) {
  static const char* const alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string chunk;
  chunk.reserve(1 << 16);
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::size_t n = bytes.size();
  for (std::size_t i = 0; i < n; i += 3) {
    const unsigned v = (b[i] << 16) | ((i + 1 < n ? b[i + 1] : 0) << 8) | (i + 2 < n ? b[i + 2] : 0);
    chunk += alphabet[(v >> 18) & 63];
    chunk += alphabet[(v >> 12) & 63];
    chunk += i + 1 < n ? alphabet[(v >> 6) & 63] : '=';
    chunk += i + 2 < n ? alphabet[v & 63] : '=';
    if (chunk.size() >= (1 << 16) - 4) out.write(chunk), chunk.clear();
  }
  out.write(chunk);
}

}  // namespace semimesh::io
