// Atomic file output: write `path.tmp-XXXXXX` in the same directory, fsync, rename over `path`.
// If anything fails (or the writer is destroyed without commit) the temporary file is removed and
// an existing `path` is left untouched. Output is buffered and formatted with fmt (fast); each full
// buffer goes to the file on a thread of the file's own while the caller fills the next one.
#pragma once

#include <fmt/format.h>

#include <cstdio>
#include <memory>
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
  /// A failure of an earlier buffer's write is thrown here or by the write after it, naming the file.
  void commit();

  const std::string& path() const { return path_; }

 private:
  static constexpr std::size_t kFlushBytes = 1 << 20;
  class BackgroundWrite;
  /// Hands the buffer to the background write (after the one before it is done) and starts a new one.
  void flush_buffer();
  /// Waits until every buffer handed over is in the file; rethrows the first failure.
  void drain();

  std::string path_, temp_path_;
  std::FILE* file_ = nullptr;
  fmt::memory_buffer buffer_;
  std::size_t written_ = 0;  ///< bytes handed to the background write
  std::unique_ptr<BackgroundWrite> background_;  ///< started by the first full buffer
  bool committed_ = false;
};

}  // namespace semimesh::io
