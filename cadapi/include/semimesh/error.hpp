// The base of every semimesh exception: a message written for the user (the file, entity or
// parameter at fault and what was expected) and its cause, which decides the exit code of the
// command line: bad input (the user can fix it) or an internal error (a bug to report).
#pragma once

#include <stdexcept>
#include <string>

namespace semimesh {

class Error : public std::runtime_error {
 public:
  enum class Cause { BadInput, Internal };
  Error(Cause cause, const std::string& message) : std::runtime_error(message), cause_(cause) {}
  Cause cause() const { return cause_; }

 private:
  Cause cause_;
};

/// An error in what the user gave (config, CAD, parameters that cannot work).
class InputError : public Error {
 public:
  explicit InputError(const std::string& message) : Error(Cause::BadInput, message) {}
};

}  // namespace semimesh
