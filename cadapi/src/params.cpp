#include "semimesh/cad/source.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace semimesh::cad {
namespace {
[[noreturn]] void bad(const std::string& key, const std::string& value, const std::string& expected) {
  throw CadError(CadError::Kind::BadParameter, "parameter '" + key + "' = '" + value + "': expected " + expected);
}
}  // namespace

std::string Params::get_string(const std::string& key, const std::string& fallback) const {
  auto it = values_.find(key);
  return it == values_.end() ? fallback : it->second;
}

double Params::get_double(const std::string& key, double fallback) const {
  auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  const char* text = it->second.c_str();
  char* end = nullptr;
  errno = 0;
  double v = std::strtod(text, &end);
  if (end == text || *end != '\0' || errno == ERANGE || !std::isfinite(v)) bad(key, it->second, "a finite number");
  return v;
}

int Params::get_int(const std::string& key, int fallback) const {
  auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  const char* text = it->second.c_str();
  char* end = nullptr;
  errno = 0;
  long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || errno == ERANGE || v < INT32_MIN || v > INT32_MAX) bad(key, it->second, "an integer");
  return static_cast<int>(v);
}

bool Params::get_bool(const std::string& key, bool fallback) const {
  auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  const std::string& v = it->second;
  if (v == "true" || v == "1" || v == "yes" || v == "on") return true;
  if (v == "false" || v == "0" || v == "no" || v == "off") return false;
  bad(key, v, "true or false");
}

void Params::require_known(const std::set<std::string>& known, const std::string& backend) const {
  for (const auto& kv : values_) {
    if (known.count(kv.first)) continue;
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    throw CadError(CadError::Kind::BadParameter,
                   "unknown parameter '" + kv.first + "' for backend '" + backend + "' (known: " + list + ")");
  }
}

}  // namespace semimesh::cad
