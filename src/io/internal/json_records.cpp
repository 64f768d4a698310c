// SPDX-License-Identifier: MIT
#include "io/internal/json_records.hpp"

#include "io/internal/json_text.hpp"

namespace catena::internal {
namespace {

bool is_record_array(const nlohmann::json& value) {
  return value.is_array() && !value.empty() && !value.front().is_primitive();
}

// True when `value` holds an array of records somewhere (a scene holds its checks): it is laid out
// over several lines; anything else in an array of records is one line.
bool holds_record_array(const nlohmann::json& value) {
  if (is_record_array(value)) return true;
  if (!value.is_structured()) return false;
  for (const auto& item : value) {
    if (holds_record_array(item)) return true;
  }
  return false;
}

// An object of numbers, strings and arrays of them (a solver summary, the groups): one line.
bool is_flat(const nlohmann::json& value) {
  for (const auto& item : value) {
    if (item.is_object() || is_record_array(item)) return false;
  }
  return true;
}

void append_records(const nlohmann::json& value, int indent, int depth, std::string& out) {
  const std::string inner(static_cast<std::size_t>(indent * (depth + 1)), ' ');
  const std::string outer(static_cast<std::size_t>(indent * depth), ' ');
  if (value.is_object() && !value.empty() && !is_flat(value)) {
    out += '{';
    bool first = true;
    for (const auto& [key, item] : value.items()) {
      out += (first ? "\n" : ",\n") + inner + nlohmann::json(key).dump() + ": ";
      append_records(item, indent, depth + 1, out);
      first = false;
    }
    out += '\n' + outer + '}';
  } else if (is_record_array(value)) {
    out += '[';
    bool first = true;
    for (const auto& item : value) {
      out += (first ? "\n" : ",\n") + inner;
      if (holds_record_array(item)) {
        append_records(item, indent, depth + 1, out);
      } else {
        out += item.dump();
      }
      first = false;
    }
    out += '\n' + outer + ']';
  } else {
    out += value.dump();  // a scalar, an empty container or an array of scalars: one line
  }
}

}  // namespace

std::string dump_records(const nlohmann::json& value, int indent) {
  std::string out;
  append_records(utf8_json(value), indent, 0, out);  // valid UTF-8 before any dump
  return out;
}

}  // namespace catena::internal
