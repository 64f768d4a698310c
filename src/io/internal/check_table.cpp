// SPDX-License-Identifier: MIT
#include "io/internal/check_table.hpp"

#include "io/internal/results_keys.hpp"

namespace catena::internal {
namespace {

// The order of a row's cells.
const nlohmann::json& check_fields() {
  static const nlohmann::json fields = {
      key::check,    key::compare,   key::plane,   key::mode,   key::value_a,         key::value_b,
      key::measured, key::tolerance, key::verdict, key::detail, key::tolerance_reason};
  return fields;
}

nlohmann::json expanded(const nlohmann::json& table) {
  const nlohmann::json& fields = table.at(key::fields);
  nlohmann::json records = nlohmann::json::array();
  for (const auto& row : table.at(key::rows)) {
    nlohmann::json record = nlohmann::json::object();
    for (std::size_t i = 0; i < fields.size() && i < row.size(); ++i)
      record[fields[i].get<std::string>()] = row[i];
    records.push_back(std::move(record));
  }
  return records;
}

}  // namespace

nlohmann::json check_table(const nlohmann::json& records) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& record : records) {
    nlohmann::json row = nlohmann::json::array();
    for (const auto& field : check_fields())
      row.push_back(record.value(field.get<std::string>(), nlohmann::json()));
    rows.push_back(std::move(row));
  }
  return {{key::fields, check_fields()}, {key::rows, rows}};
}

void expand_check_tables(nlohmann::json& document) {
  if (!document.contains(key::scenes) || !document[key::scenes].is_array()) return;
  for (auto& scene : document[key::scenes]) {
    if (!scene.is_object() || !scene.contains(key::checks)) continue;
    nlohmann::json& checks = scene[key::checks];
    if (checks.is_object() && checks.contains(key::fields) && checks.contains(key::rows))
      checks = expanded(checks);
  }
}

}  // namespace catena::internal
