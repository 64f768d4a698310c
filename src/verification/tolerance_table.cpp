#include "catena/verification/tolerance_table.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fnmatch.h>
#include <fstream>
#include <sstream>
#include <toml.hpp>

#include "catena/core/error.hpp"
#include "verification/internal/builtin_tolerances.hpp"

namespace catena {
namespace {

bool matches(const std::string& pattern, const std::string& name) {
  return pattern == "*" || pattern == name;
}

}  // namespace

ToleranceTable ToleranceTable::parse(const std::string& text, const std::string& origin) {
  std::istringstream stream(text);
  toml::value document;
  try {
    document = toml::parse(stream, origin);
  } catch (const std::exception& error) {
    throw ParseError(fmt::format("{}: TOML syntax error: {}", origin, error.what()));
  }
  ToleranceTable table;
  if (!document.is_table()) throw ParseError(origin + ": not a TOML table");
  for (const auto& [key, value] : document.as_table()) {
    if (key != "tolerance") throw ParseError(fmt::format("{}: {}: unknown key (only [[tolerance]])", origin, key));
    if (!value.is_array()) throw ParseError(origin + ": tolerance: expected [[tolerance]] tables");
    int index = 0;
    for (const auto& item : value.as_array()) {
      ++index;
      const std::string where = fmt::format("{}: [[tolerance]] #{}", origin, index);
      if (!item.is_table()) throw ParseError(where + ": expected a table");
      ToleranceRule rule;
      for (const auto& [k, v] : item.as_table()) {
        auto number = [&] {
          if (v.is_floating()) return v.as_floating();
          if (v.is_integer()) return static_cast<double>(v.as_integer());
          throw ParseError(fmt::format("{}.{}: expected a number", where, k));
        };
        auto text_value = [&] {
          if (!v.is_string()) throw ParseError(fmt::format("{}.{}: expected a string", where, k));
          return v.as_string().str;
        };
        if (k == "check") rule.check = text_value();
        else if (k == "scene") rule.scene_pattern = text_value();
        else if (k == "tag") rule.tag = text_value();
        else if (k == "reason") rule.reason = text_value();
        else if (k == "max") rule.max = number();
        else if (k == "estimate_factor") rule.estimate_factor = number();
        else if (k == "beyond") {
          const std::string beyond = text_value();
          if (beyond != "fail" && beyond != "warn") {
            throw InvalidInput(fmt::format("{}.beyond = \"{}\": must be \"fail\" or \"warn\"", where, beyond));
          }
          rule.warn_only = beyond == "warn";
        }
        else if (k == "compare") {
          if (!v.is_array() || v.as_array().size() != 2) {
            throw ParseError(fmt::format("{}.compare: expected two names", where));
          }
          for (const auto& name : v.as_array()) {
            if (!name.is_string()) throw ParseError(fmt::format("{}.compare: expected strings", where));
            rule.compare.push_back(name.as_string().str);
          }
        } else {
          throw ParseError(fmt::format("{}.{}: unknown key", where, k));
        }
      }
      if (rule.check.empty() || rule.compare.size() != 2 || rule.reason.empty()) {
        throw ParseError(where + ": needs check, compare (two names) and reason");
      }
      if (!(rule.max > 0.0) || !std::isfinite(rule.max) || rule.estimate_factor < 0.0) {
        throw InvalidInput(where + ": max must be finite and > 0, estimate_factor >= 0");
      }
      table.rules_.push_back(std::move(rule));
    }
  }
  return table;
}

ToleranceTable ToleranceTable::load(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ParseError(fmt::format("{}: cannot open tolerance file", path));
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse(buffer.str(), path);
}

const ToleranceTable& ToleranceTable::builtin() {
  static const ToleranceTable table = parse(internal::kBuiltinTolerances, "verification/tolerances.toml (built in)");
  return table;
}

const ToleranceRule* ToleranceTable::find(const std::string& check,
                                          const std::string& a,
                                          const std::string& b,
                                          const std::string& scene,
                                          const std::vector<std::string>& tags) const {
  for (const auto& rule : rules_) {
    if (rule.check != check) continue;
    const bool pair = (matches(rule.compare[0], a) && matches(rule.compare[1], b)) ||
                      (matches(rule.compare[0], b) && matches(rule.compare[1], a));
    if (!pair) continue;
    if (rule.scene_pattern != "*" && fnmatch(rule.scene_pattern.c_str(), scene.c_str(), 0) != 0) continue;
    if (!rule.tag.empty() && std::find(tags.begin(), tags.end(), rule.tag) == tags.end()) continue;
    return &rule;
  }
  return nullptr;
}

}  // namespace catena
