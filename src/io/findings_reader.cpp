// SPDX-License-Identifier: MIT
#include "catena/io/findings_reader.hpp"

#include "catena/io/file_access.hpp"
#include "io/internal/builtin_tables.hpp"
#include "io/internal/toml_json.hpp"
#include "io/internal/toml_table_reader.hpp"

namespace catena {
namespace {

Finding read_finding(internal::TableReader& item) {
  Finding finding;
  finding.scene = item.string("scene");
  finding.quantity = item.string("quantity");
  finding.mode = static_cast<int>(item.integer("mode"));
  finding.solver = item.string("solver");
  finding.printed = item.number("printed");
  finding.ours = item.number("ours");
  finding.diagnosis = item.string("diagnosis");
  item.finish();
  return finding;
}

// The table from its TOML document (parsed from text, or rebuilt from the built-in JSON).
FindingsTable read_findings_document(const toml::value& document, const std::string& origin) {
  internal::TableReader root(document, origin, "");
  std::vector<Finding> findings;
  for (internal::TableReader& item : root.table_array("finding"))
    findings.push_back(read_finding(item));
  root.finish();
  return FindingsTable(std::move(findings));
}

}  // namespace

FindingsTable parse_findings_table(const std::string& text, const std::string& origin) {
  return read_findings_document(internal::parse_toml(text, origin), origin);
}

FindingsTable read_findings_file(const std::filesystem::path& path) {
  return parse_findings_table(read_input_file(path, "findings file"), path_text(path));
}

FindingsTable builtin_findings_table() {
  return read_findings_document(
      internal::toml_from_json(nlohmann::json::parse(internal::kBuiltinFindingsJson)),
      "verification/findings.toml (built in)");
}

}  // namespace catena
