// SPDX-License-Identifier: MIT
#include "io/internal/json_text.hpp"

#include "io/internal/utf8_text.hpp"

namespace catena::internal {

nlohmann::json utf8_json(const nlohmann::json& document) {
  if (document.is_string()) return utf8_text(document.get_ref<const std::string&>());
  if (document.is_array()) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& item : document) out.push_back(utf8_json(item));
    return out;
  }
  if (document.is_object()) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [key, item] : document.items()) out[utf8_text(key)] = utf8_json(item);
    return out;
  }
  return document;
}

std::string json_text(const nlohmann::json& document, int indent) {
  return utf8_json(document).dump(indent);
}

}  // namespace catena::internal
