#include "conformity_beside.hpp"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <system_error>
#include <utility>

namespace semimesh::pipeline {

ConformityBeside::ConformityBeside(const mesh::Mesh& mesh) : mesh_(mesh) {
  try {
    run_ = std::async(std::launch::async, [this] {
      ::setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 19);
      found_ = checks::check_conformity(mesh_, checks::Located::Later);
    });
  } catch (const std::system_error&) {  // no thread to be had: checked at the join, on the caller's
  }
}

ConformityBeside::~ConformityBeside() {
  if (run_.valid()) run_.wait();
}

checks::ConformityResult ConformityBeside::join() {
  if (run_.valid())
    run_.get();
  else
    found_ = checks::check_conformity(mesh_, checks::Located::Later);
  checks::locate_problems(mesh_, found_);
  return std::move(found_);
}

}  // namespace semimesh::pipeline
