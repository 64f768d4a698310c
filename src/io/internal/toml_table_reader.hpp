// SPDX-License-Identifier: MIT
#pragma once
// Strict reading of TOML tables, shared by every TOML format of io/ (scenes, the tolerance table,
// the findings): every key a reader asks for is recorded and finish() rejects the rest, so an
// unknown or misspelt key is an error naming "<file>: [<table>].<key>", never silently ignored.

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <toml.hpp>
#include <vector>

#include "catena/core/types.hpp"

namespace catena::internal {

/// Parses TOML text; a syntax error, or text beyond the bounds of toml_work_bounds.hpp (nesting,
/// items, long lines), is a ParseError naming `origin`.
toml::value parse_toml(const std::string& text, const std::string& origin);

/// Reads one TOML table strictly. Messages name "<origin>: [<path>].<key>".
class TableReader {
 public:
  /// `table` must outlive the reader.
  TableReader(const toml::value& table, std::string origin, std::string path);

  std::string where(const std::string& key) const;
  /// Whether `key` is present; the key is then known here (listed by finish()'s message).
  bool has(const std::string& key) const;
  /// Lists `key`, read by other code than this reader, among the keys known here.
  void known_elsewhere(const std::string& key);
  /// The value of `key` (recorded as used), or nullptr.
  const toml::value* find(const std::string& key);
  /// The value of `key`; ParseError when missing.
  const toml::value& require(const std::string& key);

  double to_number(const toml::value& value, const std::string& key) const;
  double number(const std::string& key);
  double number(const std::string& key, double fallback);
  /// A finite number that must satisfy `ok`; `rule` and `unit` go into the InvalidInput message.
  double checked(const std::string& key,
                 bool (*ok)(double),
                 const char* rule,
                 const char* unit,
                 std::optional<double> fallback = std::nullopt);
  long integer(const std::string& key);
  long integer(const std::string& key, long fallback);
  /// An integer in [low, high] (`fallback` when absent; required without one). A value outside
  /// the range is an InvalidInput naming the key and the range, never a wrapped cast.
  long read_integer(const std::string& key,
                    long low,
                    long high,
                    std::optional<long> fallback = std::nullopt);
  /// An array of integers in [low, high] (required); whole numbers written as floats (2.0) count.
  std::vector<long> integers(const std::string& key, long low, long high);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key);
  std::string string(const std::string& key, const std::string& fallback);
  /// An array of finite numbers (required).
  std::vector<double> numbers(const std::string& key);
  /// An array of strings (required).
  std::vector<std::string> strings(const std::string& key);
  /// [x, z] [m].
  Vec2 point(const std::string& key);
  TableReader subtable(const std::string& key);
  /// The tables of an array of tables `[[key]]` (empty when absent), each named "<key>#<n>".
  std::vector<TableReader> table_array(const std::string& key);

  /// Throws ParseError for the first key never read, listing every key read or asked about.
  void finish() const;

  const toml::value& value() const { return table_; }
  static std::string type_name(const toml::value& value);

 private:
  const toml::value& table_;
  std::string origin_;
  std::string path_;
  std::set<std::string> used_;
  mutable std::set<std::string>
      asked_;  // by has(): known here, but reading them is up to the caller
};

}  // namespace catena::internal
