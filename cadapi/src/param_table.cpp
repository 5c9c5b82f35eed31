#include "semimesh/params/table.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace semimesh::params {
namespace {

// Shortest text that reads back as the same double (0.1, not 0.1000000000000000055; -10, not -1e+01).
std::string number_text(double x) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

double parse_number(std::string_view text, std::string_view range) {
  const std::string t(trim(text));
  char* end = nullptr;
  const double x = std::strtod(t.c_str(), &end);
  if (t.empty() || *end != '\0') throw std::logic_error("parameter range '" + std::string(range) + "': bad number '" + t + "'");
  return x;
}

bool number_in_range(double x, std::string_view range) {
  const std::string_view r = trim(range);
  if (r.empty()) return std::isfinite(x);
  if (!std::isfinite(x)) return false;
  for (const auto& [op, test] : std::initializer_list<std::pair<std::string_view, int>>{{">=", 0}, {"<=", 1}, {">", 2}, {"<", 3}})
    if (r.substr(0, op.size()) == op) {
      const double a = parse_number(r.substr(op.size()), range);
      return test == 0 ? x >= a : test == 1 ? x <= a : test == 2 ? x > a : x < a;
    }
  const auto comma = r.find(',');
  if (r.size() < 5 || comma == std::string_view::npos || (r.front() != '(' && r.front() != '[') ||
      (r.back() != ')' && r.back() != ']'))
    throw std::logic_error("parameter range '" + std::string(range) + "' is not in the range grammar");
  const double a = parse_number(r.substr(1, comma - 1), range), b = parse_number(r.substr(comma + 1, r.size() - comma - 2), range);
  const bool above = r.front() == '(' ? x > a : x >= a;
  const bool below = r.back() == ')' ? x < b : x <= b;
  return above && below;
}

// "\"a\" | \"b\"" -> {a, b}; empty when `range` is not a list of choices.
std::vector<std::string> choices_of(std::string_view range) {
  std::vector<std::string> names;
  std::string_view r = trim(range);
  while (!r.empty()) {
    if (r.front() != '"') return {};
    const auto close = r.find('"', 1);
    if (close == std::string_view::npos) return {};
    names.emplace_back(r.substr(1, close - 1));
    r = trim(r.substr(close + 1));
    if (!r.empty()) {
      if (r.front() != '|') return {};
      r = trim(r.substr(1));
    }
  }
  return names;
}

bool string_in_range(const std::string& s, std::string_view range) {
  const std::string_view r = trim(range);
  if (r.empty()) return true;
  if (r == "non-empty") return !s.empty();
  const std::vector<std::string> names = choices_of(r);
  if (names.empty()) throw std::logic_error("parameter range '" + std::string(range) + "' is not in the range grammar");
  for (const std::string& n : names)
    if (n == s) return true;
  return false;
}

}  // namespace

std::string to_text(const Value& value) {
  struct Text {
    std::string operator()(std::monostate) const { return "unset"; }
    std::string operator()(double x) const { return number_text(x); }
    std::string operator()(long long n) const { return std::to_string(n); }
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(const std::string& s) const { return '"' + s + '"'; }
    std::string operator()(const std::vector<std::string>& list) const {
      std::string out = "[";
      for (std::size_t i = 0; i < list.size(); ++i) out += (i ? ", \"" : "\"") + list[i] + '"';
      return out + "]";
    }
    std::string operator()(const std::vector<double>& list) const {
      std::string out = "[";
      for (std::size_t i = 0; i < list.size(); ++i) out += (i ? ", " : "") + number_text(list[i]);
      return out + "]";
    }
  };
  return std::visit(Text{}, value);
}

std::string type_text(Type type, std::size_t count) {
  switch (type) {
    case Type::Real: return "a finite number";
    case Type::Integer: return "an integer";
    case Type::Boolean: return "true or false";
    case Type::String: return "a string";
    case Type::Strings: return "a non-empty array of strings";
    case Type::Reals: return count ? "an array of " + std::to_string(count) + " numbers" : "an array of numbers";
  }
  return "a value";
}

bool in_range(const Value& value, std::string_view range) {
  if (const auto* x = std::get_if<double>(&value)) return number_in_range(*x, range);
  if (const auto* n = std::get_if<long long>(&value)) return number_in_range(static_cast<double>(*n), range);
  if (const auto* s = std::get_if<std::string>(&value)) return string_in_range(*s, range);
  if (const auto* list = std::get_if<std::vector<std::string>>(&value)) {
    const std::string_view r = trim(range);
    if (r.substr(0, 8) == "each of ") {
      for (const std::string& s : *list)
        if (!string_in_range(s, r.substr(8))) return false;
      return !list->empty();
    }
    if (r == "non-empty" || r.empty()) return !list->empty();
    throw std::logic_error("parameter range '" + std::string(range) + "' does not apply to a list of strings");
  }
  if (const auto* list = std::get_if<std::vector<double>>(&value)) {
    for (double x : *list)
      if (!std::isfinite(x)) return false;
    return trim(range).empty() || !list->empty();
  }
  return true;  // booleans, unset optionals
}

std::string expected_text(std::string_view range, Type type) {
  const std::string_view r = trim(range);
  const bool each = r.substr(0, 8) == "each of ";
  const std::vector<std::string> names = choices_of(each ? r.substr(8) : r);
  if (!names.empty()) {
    std::string out = each ? "each one of " : "";
    for (std::size_t i = 0; i < names.size(); ++i)
      out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + ('"' + names[i] + '"');
    return out;
  }
  if (type == Type::Integer && !r.empty() && (r.front() == '[' || r.front() == '(')) return "an integer in " + std::string(r);
  return std::string(r);
}

std::string choice_range(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) out += (i ? " | \"" : "\"") + names[i] + '"';
  return out;
}

}  // namespace semimesh::params
