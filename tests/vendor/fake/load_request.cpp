#include "load_request.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

namespace semimesh::vendor_fake {
namespace {

constexpr const char* kNacaScheme = "naca:";

std::string trim(const std::string& text) {
  const char* space = " \t\r\n";
  size_t first = text.find_first_not_of(space);
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(space) - first + 1);
}

bool starts_with(const std::string& text, const std::string& prefix) { return text.compare(0, prefix.size(), prefix) == 0; }

// "k=v;k=v" -> (key, value) pairs; `what` names the string in error messages.
std::vector<std::pair<std::string, std::string>> split_pairs(const std::string& text, const std::string& what) {
  std::vector<std::pair<std::string, std::string>> out;
  size_t begin = 0;
  while (begin <= text.size()) {
    size_t end = text.find(';', begin);
    if (end == std::string::npos) end = text.size();
    std::string item = trim(text.substr(begin, end - begin));
    begin = end + 1;
    if (item.empty()) continue;
    size_t eq = item.find('=');
    if (eq == std::string::npos || trim(item.substr(0, eq)).empty())
      throw FakeError{VC_ERR_BAD_PARAM, what + ": '" + item + "' is not of the form key=value"};
    out.emplace_back(trim(item.substr(0, eq)), trim(item.substr(eq + 1)));
  }
  return out;
}

void read_vcad_file(const std::string& path, LoadRequest& request) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw FakeError{VC_ERR_FILE_NOT_FOUND, "cannot open '" + path + "': no such file"};
  std::ifstream in(path);
  if (!std::filesystem::is_regular_file(path, ec) || !in)
    throw FakeError{VC_ERR_FILE_NOT_FOUND, "cannot open '" + path + "' for reading"};
  bool header_seen = false;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::string text = trim(line);
    if (text.empty() || text[0] == '#') continue;
    const std::string where = "'" + path + "' line " + std::to_string(number);
    if (!header_seen) {
      if (text != "vcad 1") throw FakeError{VC_ERR_BAD_FILE, where + ": expected the header 'vcad 1', found '" + text + "'"};
      header_seen = true;
      continue;
    }
    size_t eq = text.find('=');
    if (eq == std::string::npos || trim(text.substr(0, eq)).empty())
      throw FakeError{VC_ERR_BAD_FILE, where + ": expected 'key = value', found '" + text + "'"};
    request.naca.set(trim(text.substr(0, eq)), trim(text.substr(eq + 1)));
  }
  if (!header_seen) throw FakeError{VC_ERR_BAD_FILE, "'" + path + "' is empty: expected the header 'vcad 1'"};
  request.from_file = true;
}

vc_unit parse_units(const std::string& value) {
  if (value == "m") return VC_UNIT_METRE;
  if (value == "mm") return VC_UNIT_MILLIMETRE;
  if (value == "cm") return VC_UNIT_CENTIMETRE;
  if (value == "in") return VC_UNIT_INCH;
  if (value == "ft") return VC_UNIT_FOOT;
  throw FakeError{VC_ERR_BAD_PARAM, "option units='" + value + "': expected one of m, mm, cm, in, ft"};
}

double parse_tolerance(const std::string& value) {
  char* end = nullptr;
  errno = 0;
  double tolerance = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(tolerance) || tolerance <= 0.0)
    throw FakeError{VC_ERR_BAD_PARAM, "option tolerance='" + value + "': expected a positive number"};
  return tolerance;
}

}  // namespace

LoadRequest parse_load_request(const char* path, const char* options) {
  if (!path) throw FakeError{VC_ERR_BAD_PARAM, "path is NULL"};
  LoadRequest request;
  const std::string source = path;
  if (starts_with(source, kNacaScheme)) {
    for (const auto& [key, value] : split_pairs(source.substr(std::char_traits<char>::length(kNacaScheme)), "path"))
      request.naca.set(key, value);
  } else {
    read_vcad_file(source, request);
  }
  for (const auto& [key, value] : split_pairs(options ? options : "", "options")) {
    if (key == "units") request.units = parse_units(value);
    else if (key == "tolerance") request.tolerance = parse_tolerance(value);
    else if (starts_with(key, "naca.")) request.naca.set(key, value);
    else throw FakeError{VC_ERR_UNKNOWN_OPTION, "unknown load option '" + key + "' (known: units, tolerance, naca.*)"};
  }
  return request;
}

}  // namespace semimesh::vendor_fake
