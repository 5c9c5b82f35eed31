// One declaration per parameter: each stage lists the keys of its params struct once, as rows of
// a table (key name, member, range, one-line doc). The same rows drive the stage's own check of a
// params struct (`check`), the reading and range checks of the TOML config and `--set`
// (pipeline/config.cpp), and the test that docs/config.md lists every key with its default (the
// struct's own default member initialiser: there is no second default) and its range.
//
// Ranges are written as docs/config.md writes them, and parsed from that text:
//   numbers   "> a", ">= a", "< a", "<= a", "(a, b)", "[a, b]", "(a, b]", "[a, b)"
//   strings   "\"x\" | \"y\" | ..." (one of), "non-empty"
//   arrays    "non-empty", or for a list of strings with choices: "each of \"x\" | \"y\""
//   ""        anything of the right type
#pragma once

#include "semimesh/error.hpp"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace semimesh::params {

/// What a key holds, as written in TOML.
enum class Type { Real, Integer, Boolean, String, Strings, Reals };

/// A key's value as read from TOML or taken from a params struct; std::monostate: an optional key
/// that is unset.
using Value = std::variant<std::monostate, double, long long, bool, std::string, std::vector<std::string>,
                           std::vector<double>>;

/// The value as docs/config.md and messages write it: 0.1, 5, true, "gll", ["a", "b"], [1, 2], unset.
std::string to_text(const Value& value);
/// The TOML type a user must write, for messages: "a finite number", "an integer", ...
std::string type_text(Type type, std::size_t count = 0);
/// What a message says was expected, from a key's range and type: choices as "\"a\" or \"b\"",
/// intervals of integers as "an integer in [1, 8]", other ranges as written.
std::string expected_text(std::string_view range, Type type);
/// Whether `value` lies in `range` (grammar above). Throws std::logic_error for a range text it
/// cannot parse (a bug in a table, caught by the tables' own test).
bool in_range(const Value& value, std::string_view range);

template <class P>
struct Key {
  std::string name;
  Type type = Type::Real;
  std::string range;           ///< in the grammar above
  std::string doc;             ///< one line, as in docs/config.md
  std::size_t count = 0;       ///< Type::Reals: how many numbers (0: any)
  bool optional = false;       ///< may be unset (std::monostate)
  std::function<Value(const P&)> get;
  std::function<void(P&, const Value&)> set;
};

template <class P>
using Table = std::vector<Key<P>>;

// ---- rows ----------------------------------------------------------------------------------------

template <class P>
Key<P> real(std::string name, double P::*m, std::string range, std::string doc) {
  return {std::move(name), Type::Real, std::move(range), std::move(doc), 0, false,
          [m](const P& p) { return Value(p.*m); }, [m](P& p, const Value& v) { p.*m = std::get<double>(v); }};
}

template <class P>
Key<P> real(std::string name, std::optional<double> P::*m, std::string range, std::string doc) {
  return {std::move(name), Type::Real, std::move(range), std::move(doc), 0, true,
          [m](const P& p) { return p.*m ? Value(*(p.*m)) : Value(); },
          [m](P& p, const Value& v) {
            if (std::holds_alternative<double>(v)) p.*m = std::get<double>(v); else p.*m = std::nullopt;
          }};
}

template <class P>
Key<P> integer(std::string name, int P::*m, std::string range, std::string doc) {
  return {std::move(name), Type::Integer, std::move(range), std::move(doc), 0, false,
          [m](const P& p) { return Value(static_cast<long long>(p.*m)); },
          [m](P& p, const Value& v) { p.*m = static_cast<int>(std::get<long long>(v)); }};
}

template <class P>
Key<P> boolean(std::string name, bool P::*m, std::string doc) {
  return {std::move(name), Type::Boolean, "", std::move(doc), 0, false, [m](const P& p) { return Value(p.*m); },
          [m](P& p, const Value& v) { p.*m = std::get<bool>(v); }};
}

template <class P>
Key<P> string(std::string name, std::string P::*m, std::string range, std::string doc) {
  return {std::move(name), Type::String, std::move(range), std::move(doc), 0, false,
          [m](const P& p) { return Value(p.*m); }, [m](P& p, const Value& v) { p.*m = std::get<std::string>(v); }};
}

template <class P>
Key<P> strings(std::string name, std::vector<std::string> P::*m, std::string range, std::string doc) {
  return {std::move(name), Type::Strings, std::move(range), std::move(doc), 0, false,
          [m](const P& p) { return Value(p.*m); },
          [m](P& p, const Value& v) { p.*m = std::get<std::vector<std::string>>(v); }};
}

template <class P>
Key<P> strings(std::string name, std::optional<std::vector<std::string>> P::*m, std::string range, std::string doc) {
  return {std::move(name), Type::Strings, std::move(range), std::move(doc), 0, true,
          [m](const P& p) { return p.*m ? Value(*(p.*m)) : Value(); },
          [m](P& p, const Value& v) {
            if (std::holds_alternative<std::vector<std::string>>(v)) p.*m = std::get<std::vector<std::string>>(v);
            else p.*m = std::nullopt;
          }};
}

template <class P, std::size_t N>
Key<P> reals(std::string name, std::array<double, N> P::*m, std::string range, std::string doc) {
  return {std::move(name), Type::Reals, std::move(range), std::move(doc), N, false,
          [m](const P& p) { return Value(std::vector<double>((p.*m).begin(), (p.*m).end())); },
          [m](P& p, const Value& v) {
            const auto& x = std::get<std::vector<double>>(v);
            std::copy(x.begin(), x.end(), (p.*m).begin());
          }};
}

template <class P, std::size_t N>
Key<P> reals(std::string name, std::optional<std::array<double, N>> P::*m, std::string range, std::string doc) {
  return {std::move(name), Type::Reals, std::move(range), std::move(doc), N, true,
          [m](const P& p) { return p.*m ? Value(std::vector<double>((p.*m)->begin(), (p.*m)->end())) : Value(); },
          [m](P& p, const Value& v) {
            if (!std::holds_alternative<std::vector<double>>(v)) {
              p.*m = std::nullopt;
              return;
            }
            std::array<double, N> a{};
            const auto& x = std::get<std::vector<double>>(v);
            std::copy(x.begin(), x.end(), a.begin());
            p.*m = a;
          }};
}

/// The range text of a choice: "\"a\" | \"b\"".
std::string choice_range(const std::vector<std::string>& names);

/// An enum member written as one of `names` (the i-th name is the i-th value).
template <class P, class E>
Key<P> choice(std::string name, E P::*m, std::vector<std::pair<std::string, E>> names, std::string doc) {
  std::vector<std::string> texts;
  for (const auto& n : names) texts.push_back(n.first);
  return {std::move(name), Type::String, choice_range(texts), std::move(doc), 0, false,
          [m, names](const P& p) {
            for (const auto& [text, value] : names)
              if (p.*m == value) return Value(text);
            return Value(std::string("?"));
          },
          [m, names](P& p, const Value& v) {
            for (const auto& [text, value] : names)
              if (std::get<std::string>(v) == text) p.*m = value;
          }};
}

/// The rows of a member struct, as rows of the enclosing one (e.g. ShellParams inside the
/// pipeline's [nearfield] section).
template <class Outer, class Inner>
Table<Outer> nested(Inner Outer::*m, const Table<Inner>& inner) {
  Table<Outer> out;
  for (const Key<Inner>& k : inner)
    out.push_back({k.name, k.type, k.range, k.doc, k.count, k.optional,
                   [m, get = k.get](const Outer& o) { return get(o.*m); },
                   [m, set = k.set](Outer& o, const Value& v) { set(o.*m, v); }});
  return out;
}

/// The first key of `p` (in table order) whose value is out of its range, as the message
/// "section.key = value: expected range"; nullopt when every key is in range. Stages throw it as
/// their own error type.
template <class P>
std::optional<std::string> violation(const P& p, const Table<P>& table, std::string_view section) {
  for (const Key<P>& k : table) {
    const Value v = k.get(p);
    if (std::holds_alternative<std::monostate>(v)) continue;  // an unset optional key
    if (!in_range(v, k.range))
      return std::string(section) + "." + k.name + " = " + to_text(v) + ": expected " + expected_text(k.range, k.type);
  }
  return std::nullopt;
}

}  // namespace semimesh::params
