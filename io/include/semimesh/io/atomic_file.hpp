// Atomic file output: write `path.tmp-XXXXXX` in the same directory, fsync, rename over `path`.
// If anything fails (or the writer is destroyed without commit) the temporary file is removed and
// an existing `path` is left untouched. Output is buffered and formatted with fmt (fast).
#pragma once

#include <fmt/format.h>

#include <cstdio>
#include <string>

namespace semimesh::io {

class AtomicFile {
 public:
  /// Creates the temporary file; throws std::runtime_error naming the directory if it cannot.
  explicit AtomicFile(const std::string& path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Appends formatted text (fmt syntax).
  template <typename... Args>
  void print(fmt::format_string<Args...> format, Args&&... args) {
    fmt::format_to(std::back_inserter(buffer_), format, std::forward<Args>(args)...);
    if (buffer_.size() > kFlushBytes) flush_buffer();
  }
  void write(const std::string& text);
  /// Appends raw bytes (binary formats).
  void write(const void* data, std::size_t bytes);
  template <typename T>
  void write_value(const T& value) {
    write(&value, sizeof value);
  }
  /// Bytes appended so far.
  std::size_t bytes_written() const { return written_ + buffer_.size(); }
  /// Replaces bytes already appended, at [position, position + bytes) (a placeholder whose value
  /// is known only once what follows it is written); throws std::logic_error past the end.
  void overwrite(std::size_t position, const void* data, std::size_t bytes);
  /// Flushes, fsyncs and renames the temporary file to the final path; throws on any failure.
  void commit();

  const std::string& path() const { return path_; }

 private:
  static constexpr std::size_t kFlushBytes = 1 << 20;
  static constexpr std::size_t kWritebackBytes = std::size_t{16} << 20;
  void flush_buffer();
  /// Appends to the file after what the buffer held (which must be flushed already).
  void write_to_file(const char* data, std::size_t bytes);

  std::string path_, temp_path_;
  std::FILE* file_ = nullptr;
  fmt::memory_buffer buffer_;
  std::size_t written_ = 0;
  std::size_t started_writeback_ = 0;  ///< bytes [0, this) handed to the kernel's writeback
  bool committed_ = false;
};

}  // namespace semimesh::io
