#include "catena/io/tolerance_reader.hpp"

#include <cmath>
#include <fmt/format.h>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "io/internal/builtin_tolerances.hpp"
#include "io/internal/toml_table_reader.hpp"

namespace catena {
namespace {

ToleranceRule read_rule(internal::TableReader& item) {
  ToleranceRule rule;
  rule.check = item.string("check");
  rule.compare = item.strings("compare");
  if (rule.compare.size() != 2) {
    throw ParseError(fmt::format("{}: expected two names, got {}", item.where("compare"), rule.compare.size()));
  }
  rule.scene_pattern = item.string("scene", "*");
  rule.tag = item.string("tag", "");
  rule.max = item.number("max", 0.0);
  rule.estimate_factor = item.number("estimate_factor", 0.0);
  const std::string beyond = item.string("beyond", "fail");
  if (beyond != "fail" && beyond != "warn") {
    throw InvalidInput(fmt::format("{} = \"{}\": must be \"fail\" or \"warn\"", item.where("beyond"), beyond));
  }
  rule.warn_only = beyond == "warn";
  rule.reason = item.string("reason");
  item.finish();
  if (rule.check.empty() || rule.reason.empty()) {
    throw ParseError(fmt::format("{}: check and reason must not be empty", item.where("check")));
  }
  if (!(rule.max > 0.0) || !std::isfinite(rule.max) || !(rule.estimate_factor >= 0.0)) {
    throw InvalidInput(fmt::format("{}: max must be finite and > 0, estimate_factor >= 0", item.where("max")));
  }
  return rule;
}

}  // namespace

ToleranceTable parse_tolerance_table(const std::string& text, const std::string& origin) {
  const toml::value document = internal::parse_toml(text, origin);
  internal::TableReader root(document, origin, "");
  std::vector<ToleranceRule> rules;
  for (internal::TableReader& item : root.table_array("tolerance")) rules.push_back(read_rule(item));
  root.finish();
  return ToleranceTable(std::move(rules));
}

ToleranceTable read_tolerance_file(const std::filesystem::path& path) {
  return parse_tolerance_table(read_input_file(path, "tolerance file"), path_text(path));
}

ToleranceTable builtin_tolerance_table() {
  return parse_tolerance_table(internal::kBuiltinTolerances, "verification/tolerances.toml (built in)");
}

}  // namespace catena
