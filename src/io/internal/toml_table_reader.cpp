// SPDX-License-Identifier: MIT
#include "io/internal/toml_table_reader.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "catena/core/error.hpp"
#include "io/internal/toml_linear_values.hpp"
#include "io/internal/toml_work_bounds.hpp"

namespace catena::internal {

toml::value parse_toml(const std::string& text, const std::string& origin) {
  check_toml_work_bounds(text, origin);
  std::istringstream stream(text);
  try {
    return toml::parse(stream, origin);
  } catch (const std::exception& error) {
    throw ParseError(fmt::format("{}: TOML syntax error: {}", origin, error.what()));
  }
}

TableReader::TableReader(const toml::value& table, std::string origin, std::string path)
    : table_(table), origin_(std::move(origin)), path_(std::move(path)) {}

std::string TableReader::where(const std::string& key) const {
  return path_.empty() ? fmt::format("{}: {}", origin_, key)
                       : fmt::format("{}: [{}].{}", origin_, path_, key);
}

bool TableReader::has(const std::string& key) const {
  asked_.insert(key);  // a key asked about is known here, present or not
  return table_.as_table().count(key) > 0;
}

void TableReader::known_elsewhere(const std::string& key) { asked_.insert(key); }

const toml::value* TableReader::find(const std::string& key) {
  used_.insert(key);
  const auto& map = table_.as_table();
  const auto it = map.find(key);
  return it == map.end() ? nullptr : &it->second;
}

const toml::value& TableReader::require(const std::string& key) {
  const toml::value* value = find(key);
  if (!value) throw ParseError(fmt::format("{}: missing required key", where(key)));
  return *value;
}

double TableReader::to_number(const toml::value& value, const std::string& key) const {
  if (value.is_floating()) return value.as_floating();
  if (value.is_integer()) return static_cast<double>(value.as_integer());
  throw ParseError(fmt::format("{}: expected a number, got {}", where(key), type_name(value)));
}

double TableReader::number(const std::string& key) { return to_number(require(key), key); }

double TableReader::number(const std::string& key, double fallback) {
  const toml::value* value = find(key);
  return value ? to_number(*value, key) : fallback;
}

double TableReader::checked(const std::string& key,
                            bool (*ok)(double),
                            const char* rule,
                            const char* unit,
                            std::optional<double> fallback) {
  const double value = fallback && !has(key) ? number(key, *fallback) : number(key);
  if (!std::isfinite(value) || !ok(value)) {
    throw InvalidInput(fmt::format("{} = {}: must be {} [{}]", where(key), value, rule, unit));
  }
  return value;
}

long TableReader::integer(const std::string& key) {
  if (!has(key)) require(key);
  return integer(key, 0);
}

long TableReader::integer(const std::string& key, long fallback) {
  const toml::value* value = find(key);
  if (!value) return fallback;
  if (!value->is_integer()) {
    throw ParseError(fmt::format("{}: expected an integer, got {}", where(key), type_name(*value)));
  }
  return static_cast<long>(value->as_integer());
}

long TableReader::read_integer(const std::string& key,
                               long low,
                               long high,
                               std::optional<long> fallback) {
  if (fallback && !has(key)) return *fallback;
  const long value = integer(key);
  if (value < low || value > high) {
    throw InvalidInput(
        fmt::format("{} = {}: must be an integer in [{}, {}]", where(key), value, low, high));
  }
  return value;
}

std::vector<long> TableReader::integers(const std::string& key, long low, long high) {
  std::vector<long> out;
  for (double x : numbers(key)) {
    // The range test comes first: casting a double outside long's range is undefined.
    if (!(x >= static_cast<double>(low) && x <= static_cast<double>(high)) || x != std::floor(x)) {
      throw InvalidInput(
          fmt::format("{}: entry {} must be an integer in [{}, {}]", where(key), x, low, high));
    }
    out.push_back(static_cast<long>(x));
  }
  return out;
}

bool TableReader::boolean(const std::string& key, bool fallback) {
  const toml::value* value = find(key);
  if (!value) return fallback;
  if (!value->is_boolean()) {
    throw ParseError(
        fmt::format("{}: expected true or false, got {}", where(key), type_name(*value)));
  }
  return value->as_boolean();
}

std::string TableReader::string(const std::string& key) {
  if (!has(key)) require(key);
  return string(key, "");
}

std::string TableReader::string(const std::string& key, const std::string& fallback) {
  const toml::value* value = find(key);
  if (!value) return fallback;
  if (!value->is_string()) {
    throw ParseError(fmt::format("{}: expected a string, got {}", where(key), type_name(*value)));
  }
  return value->as_string().str;
}

std::vector<double> TableReader::numbers(const std::string& key) {
  const toml::value& value = require(key);
  if (!value.is_array()) {
    throw ParseError(
        fmt::format("{}: expected an array of numbers, got {}", where(key), type_name(value)));
  }
  std::vector<double> out;
  for (const auto& item : value.as_array()) {
    const double x = to_number(item, key);
    if (!std::isfinite(x))
      throw InvalidInput(fmt::format("{}: entry {} is not finite", where(key), x));
    out.push_back(x);
  }
  return out;
}

std::vector<std::string> TableReader::strings(const std::string& key) {
  const toml::value& value = require(key);
  if (!value.is_array()) {
    throw ParseError(
        fmt::format("{}: expected an array of strings, got {}", where(key), type_name(value)));
  }
  std::vector<std::string> out;
  for (const auto& item : value.as_array()) {
    if (!item.is_string()) {
      throw ParseError(fmt::format("{}: expected strings, got {}", where(key), type_name(item)));
    }
    out.push_back(item.as_string().str);
  }
  return out;
}

Vec2 TableReader::point(const std::string& key) {
  const std::vector<double> xs = numbers(key);
  if (xs.size() != 2) {
    throw InvalidInput(
        fmt::format("{}: expected [x, z] (2 numbers) [m], got {} numbers", where(key), xs.size()));
  }
  return {xs[0], xs[1]};
}

TableReader TableReader::subtable(const std::string& key) {
  const toml::value& value = require(key);
  if (!value.is_table()) {
    throw ParseError(fmt::format("{}: expected a table, got {}", where(key), type_name(value)));
  }
  return TableReader(value, origin_, path_.empty() ? key : path_ + "." + key);
}

std::vector<TableReader> TableReader::table_array(const std::string& key) {
  const toml::value* list = find(key);
  if (!list) return {};
  if (!list->is_array()) {
    throw ParseError(fmt::format("{}: expected an array of tables [[{}]]", where(key), key));
  }
  std::vector<TableReader> tables;
  int index = 0;
  for (const auto& item : list->as_array()) {
    ++index;
    if (!item.is_table()) {
      throw ParseError(fmt::format("{}: [[{}]] entry {}: expected a table", origin_, key, index));
    }
    tables.emplace_back(item, origin_, fmt::format("{}#{}", key, index));
  }
  return tables;
}

void TableReader::finish() const {
  for (const auto& [key, value] : table_.as_table()) {
    if (used_.count(key)) continue;
    // Every key this reader read or asked about: the list is complete for the table, whatever
    // was present (a table read only when present, such as [checks], asks with has()).
    std::set<std::string> keys = asked_;
    keys.insert(used_.begin(), used_.end());
    std::string known;
    for (const auto& k : keys) known += (known.empty() ? "" : ", ") + k;
    throw ParseError(fmt::format("{}: unknown key (known here: {})", where(key), known));
  }
}

std::string TableReader::type_name(const toml::value& value) {
  std::ostringstream out;
  out << value.type();
  return out.str();
}

}  // namespace catena::internal
