// SPDX-License-Identifier: MIT
// TOML documents as JSON and back: see toml_json.hpp.
#include "io/internal/toml_json.hpp"

#include "catena/core/error.hpp"

namespace catena::internal {

nlohmann::json json_from_toml(const toml::value& value) {
  switch (value.type()) {
    case toml::value_t::boolean:
      return value.as_boolean();
    case toml::value_t::integer:
      return value.as_integer();
    case toml::value_t::floating:
      return value.as_floating();
    case toml::value_t::string:
      return value.as_string().str;
    case toml::value_t::array: {
      nlohmann::json out = nlohmann::json::array();
      for (const toml::value& item : value.as_array()) out.push_back(json_from_toml(item));
      return out;
    }
    case toml::value_t::table: {
      nlohmann::json out = nlohmann::json::object();
      for (const auto& [key, item] : value.as_table()) out[key] = json_from_toml(item);
      return out;
    }
    default:
      throw ParseError("a TOML date or time has no JSON form: " + toml::format(value));
  }
}

toml::value toml_from_json(const nlohmann::json& json) {
  switch (json.type()) {
    case nlohmann::json::value_t::boolean:
      return toml::value(json.get<bool>());
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
      return toml::value(json.get<toml::integer>());
    case nlohmann::json::value_t::number_float:
      return toml::value(json.get<toml::floating>());
    case nlohmann::json::value_t::string:
      return toml::value(json.get<std::string>());
    case nlohmann::json::value_t::array: {
      toml::array out;
      out.reserve(json.size());
      for (const nlohmann::json& item : json) out.push_back(toml_from_json(item));
      return toml::value(std::move(out));
    }
    case nlohmann::json::value_t::object: {
      toml::table out;
      for (const auto& [key, item] : json.items()) out.emplace(key, toml_from_json(item));
      return toml::value(std::move(out));
    }
    default:
      throw ParseError("JSON null has no TOML form");
  }
}

}  // namespace catena::internal
