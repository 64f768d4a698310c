#include "io/internal/json_records.hpp"

namespace catena::internal {
namespace {

void append_records(const nlohmann::json& value, int indent, int depth, std::string& out) {
  const std::string inner(static_cast<std::size_t>(indent * (depth + 1)), ' ');
  const std::string outer(static_cast<std::size_t>(indent * depth), ' ');
  if (value.is_object() && !value.empty()) {
    out += '{';
    bool first = true;
    for (const auto& [key, item] : value.items()) {
      out += (first ? "\n" : ",\n") + inner + nlohmann::json(key).dump() + ": ";
      append_records(item, indent, depth + 1, out);
      first = false;
    }
    out += '\n' + outer + '}';
  } else if (value.is_array() && !value.empty() && !value.front().is_primitive()) {
    out += '[';
    bool first = true;
    for (const auto& item : value) {
      out += (first ? "\n" : ",\n") + inner + item.dump();
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
  append_records(value, indent, 0, out);
  return out;
}

}  // namespace catena::internal
