// What to load: a file path and/or generator parameters, as strings so that a config file, a
// command line and a test all speak the same language. Typed getters throw CadError naming the
// parameter and what was expected.
#pragma once

#include "semimesh/cad/error.hpp"

#include <map>
#include <optional>
#include <set>
#include <string>

namespace semimesh::cad {

class Params {
 public:
  Params() = default;
  Params(std::initializer_list<std::pair<const std::string, std::string>> init) : values_(init) {}

  void set(const std::string& key, const std::string& value) { values_[key] = value; }
  bool has(const std::string& key) const { return values_.count(key) != 0; }
  const std::map<std::string, std::string>& all() const { return values_; }

  std::string get_string(const std::string& key, const std::string& fallback) const;
  /// Parses a finite double; throws CadError(BadParameter) naming the key on malformed input.
  double get_double(const std::string& key, double fallback) const;
  int get_int(const std::string& key, int fallback) const;
  bool get_bool(const std::string& key, bool fallback) const;

  /// Throws CadError(BadParameter) listing any key not in `known` (catches typos).
  void require_known(const std::set<std::string>& known, const std::string& backend) const;

 private:
  std::map<std::string, std::string> values_;
};

struct Source {
  std::string path;  ///< file to load; empty for generators
  Params params;     ///< backend-specific parameters (e.g. "naca.code" = "0012")
};

}  // namespace semimesh::cad
