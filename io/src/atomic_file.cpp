#include "semimesh/io/atomic_file.hpp"
#include "os_error.hpp"

#include <cerrno>
#include <cstring>
#include <mutex>
#include <fcntl.h>
#include <sys/stat.h>
#include <stdexcept>
#include <unistd.h>
#include <vector>

namespace semimesh::io {
namespace {

std::string directory_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

}  // namespace

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
  std::vector<char> name(path.begin(), path.end());
  const std::string suffix = ".tmp-XXXXXX";
  name.insert(name.end(), suffix.begin(), suffix.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw detail::os_error("cannot create a temporary file in directory", directory_of(path));
  temp_path_ = name.data();
  // mkstemp creates the file 0600; a mesh file should get the usual 0666 less the umask (umask has
  // no read-only query, so it is set and restored; files are written by several threads at once,
  // so no other AtomicFile may read the umask in between).
  static std::mutex umask_mutex;
  mode_t mask;
  {
    const std::lock_guard<std::mutex> lock(umask_mutex);
    mask = ::umask(0);
    ::umask(mask);
  }
  ::fchmod(fd, 0666 & ~mask);
  file_ = ::fdopen(fd, "wb");
  if (!file_) {
    ::close(fd);
    ::unlink(temp_path_.c_str());
    throw detail::os_error("cannot open temporary file", temp_path_);
  }
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  if (file_) std::fclose(file_);
  ::unlink(temp_path_.c_str());
}

void AtomicFile::write(const std::string& text) {
  buffer_.append(text.data(), text.data() + text.size());
  if (buffer_.size() > kFlushBytes) flush_buffer();
}

void AtomicFile::write(const void* data, std::size_t bytes) {
  const char* c = static_cast<const char*>(data);
  if (bytes >= kFlushBytes) {  // a large piece goes to the file as it is, not copied through the buffer
    flush_buffer();
    write_to_file(c, bytes);
    return;
  }
  buffer_.append(c, c + bytes);
  if (buffer_.size() > kFlushBytes) flush_buffer();
}

void AtomicFile::overwrite(std::size_t position, const void* data, std::size_t bytes) {
  if (position + bytes > bytes_written()) throw std::logic_error("AtomicFile::overwrite past the end of " + temp_path_);
  if (position >= written_) {  // still in the buffer
    std::memcpy(buffer_.data() + (position - written_), data, bytes);
    return;
  }
  flush_buffer();
  if (std::fflush(file_) != 0 ||
      ::pwrite(::fileno(file_), data, bytes, static_cast<off_t>(position)) != static_cast<ssize_t>(bytes))
    throw detail::os_error("cannot write to", temp_path_);
}

void AtomicFile::flush_buffer() {
  write_to_file(buffer_.data(), buffer_.size());
  buffer_.clear();
}

void AtomicFile::write_to_file(const char* data, std::size_t bytes) {
  if (bytes && std::fwrite(data, 1, bytes, file_) != bytes) throw detail::os_error("cannot write to", temp_path_);
  written_ += bytes;
  // The disk is the slowest part of a large write (~180 MB/s here against ~1 GB/s of formatting):
  // start writing each full stretch back now, so that it overlaps the formatting of the next one
  // and the fsync in commit() waits only for the tail. A hint: its failure changes nothing.
  if (written_ - started_writeback_ >= kWritebackBytes && std::fflush(file_) == 0) {
    ::sync_file_range(::fileno(file_), static_cast<off_t>(started_writeback_),
                      static_cast<off_t>(written_ - started_writeback_), SYNC_FILE_RANGE_WRITE);
    started_writeback_ = written_;
  }
}

void AtomicFile::commit() {
  flush_buffer();
  if (std::fflush(file_) != 0 || ::fsync(::fileno(file_)) != 0) throw detail::os_error("cannot flush", temp_path_);
  const int closed = std::fclose(file_);
  file_ = nullptr;
  if (closed != 0) throw detail::os_error("cannot close", temp_path_);
  if (::rename(temp_path_.c_str(), path_.c_str()) != 0) throw detail::os_error("cannot rename the temporary file to", path_);
  committed_ = true;
  // Make the rename itself durable.
  const int dir = ::open(directory_of(path_).c_str(), O_RDONLY | O_DIRECTORY);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

}  // namespace semimesh::io
