// An error from the operating system naming what failed, the path and errno's text (one definition
// for the atomic file, folder and output set).
#pragma once

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace semimesh::io::detail {

inline std::runtime_error os_error(const std::string& what, const std::string& path) {
  return std::runtime_error(what + " '" + path + "': " + std::strerror(errno));
}

}  // namespace semimesh::io::detail
