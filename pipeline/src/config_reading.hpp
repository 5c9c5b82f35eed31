// Reading the configuration's TOML (config.cpp's parse_config): where each value came from (a file
// line or a --set), the --set overrides applied to the parsed file, and one [section] at a time,
// typed and range-checked reads (the params rows) that remember which keys were used, so that
// anything left over is reported as unknown.
#pragma once

#include "semimesh/pipeline/config.hpp"

#include <toml++/toml.h>

#include <map>
#include <set>
#include <string>

namespace semimesh::pipeline::detail {

// Where each value came from, so errors can point at it.
struct Origin {
  std::string source_name;
  std::map<std::string, std::string> overrides;  // dotted key -> the --set text that set it
};

/// "--set key=value", "file:line" or the file's name: where the value of `key` was given.
std::string location(const Origin& origin, const std::string& key, const toml::node* node);

/// Throws ConfigError naming the key, where it was given, its value and what was expected.
[[noreturn]] void reject(const Origin& origin, const std::string& key, const toml::node* node, const std::string& expected);

// One [section] of the file: typed reads that remember which keys were used, so that anything
// left over is reported as unknown.
class Section {
 public:
  /// The table `parent[key]`, called `name` in messages (its dotted path).
  Section(const Origin& origin, const toml::table& parent, const std::string& key, const std::string& name,
          bool or_value = false)
      : origin_(origin), name_(name) {
    const toml::node* node = parent.get(key);
    if (node && !node->is_table() && !or_value) reject(origin, name, node, "a table [" + name + "]");
    table_ = node ? node->as_table() : nullptr;
  }

  std::string key(const std::string& k) const { return name_ + "." + k; }
  const Origin& origin() const { return origin_; }

  const toml::node* take(const std::string& k) {
    known_.insert(k);
    return table_ ? table_->get(k) : nullptr;
  }

  /// A nested table [name.sub] read by its own Section.
  Section sub(const std::string& k, bool or_value = false) {
    known_.insert(k);
    static const toml::table empty;
    return Section(origin_, table_ ? *table_ : empty, k, key(k), or_value);
  }

  /// Whether the key holds a table (read as a section of its own).
  bool holds_table(const std::string& k) const { return table_ && table_->get(k) && table_->get(k)->is_table(); }

  /// Throws when `ok` is false, naming the key (which must have been read) and what was expected.
  void require(bool ok, const std::string& k, const std::string& expected) const {
    if (!ok) reject(origin_, key(k), table_ ? table_->get(k) : nullptr, expected);
  }

  bool has(const std::string& k) const { return table_ && table_->contains(k); }

  /// Throws on the first key (in file order) that no read asked for.
  void reject_unknown() const {
    if (!table_) return;
    const toml::node* first = nullptr;
    std::string first_key;
    for (const auto& [k, node] : *table_) {
      if (known_.count(std::string(k.str()))) continue;
      if (!first || node.source().begin.line < first->source().begin.line) {
        first = &node;
        first_key = std::string(k.str());
      }
    }
    if (!first) return;
    std::string keys;
    for (const auto& k : known_) keys += (keys.empty() ? "" : ", ") + k;
    throw ConfigError("config error: " + location(origin_, key(first_key), first) + ": unknown key " + key(first_key) +
                      " (known keys of [" + name_ + "]: " + keys + ")");
  }

 private:
  const Origin& origin_;
  std::string name_;
  const toml::table* table_ = nullptr;
  std::set<std::string> known_;
};

/// Sets `dotted.key` in `root` to the TOML value of the text after '=' (a bare word becomes a
/// string); a key inside a section of alternatives drops the other alternatives.
void apply_override(toml::table& root, const std::string& assignment, Origin& origin);

/// The TOML node as a params::Value of the key's type, or a rejection naming what was expected.
params::Value value_of(const Origin& origin, const std::string& key, const toml::node& n, params::Type type,
                       std::size_t count);

// Reads every key of a table that the section holds: type, then range (as the table writes it).
template <class P>
void read_keys(Section& s, const params::Table<P>& table, P& target, const std::set<std::string>& table_or_value = {}) {
  for (const params::Key<P>& k : table) {
    if (table_or_value.count(k.name) && s.holds_table(k.name)) continue;  // its own section reads it
    const toml::node* n = s.take(k.name);
    if (!n) continue;
    const params::Value v = value_of(s.origin(), s.key(k.name), *n, k.type, k.count);
    if (!params::in_range(v, k.range)) reject(s.origin(), s.key(k.name), n, params::expected_text(k.range, k.type));
    k.set(target, v);
  }
}

}  // namespace semimesh::pipeline::detail
