// The exit codes of every `semimesh` subcommand (docs/config.md, docs/architecture.md section 3).
#pragma once

#include "semimesh/error.hpp"

namespace semimesh::app {

constexpr int kExitOk = 0;
constexpr int kExitBadInput = 1;     ///< the user can fix it: config, CAD file, arguments, parameters
constexpr int kExitInvalidMesh = 2;  ///< a mesh was produced (or read) and failed its checks
constexpr int kExitInternal = 3;     ///< a bug: report it

inline int exit_code(Error::Cause cause) { return cause == Error::Cause::BadInput ? kExitBadInput : kExitInternal; }

}  // namespace semimesh::app
