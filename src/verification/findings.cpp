#include "catena/verification/findings.hpp"

#include <fmt/format.h>
#include <sstream>
#include <toml.hpp>

#include "catena/core/error.hpp"
#include "verification/internal/builtin_findings.hpp"

namespace catena {

FindingsTable FindingsTable::parse(const std::string& text, const std::string& origin) {
  std::istringstream stream(text);
  toml::value document;
  try {
    document = toml::parse(stream, origin);
  } catch (const std::exception& error) {
    throw ParseError(fmt::format("{}: TOML syntax error: {}", origin, error.what()));
  }
  FindingsTable table;
  for (const auto& [key, value] : document.as_table()) {
    if (key != "finding" || !value.is_array()) {
      throw ParseError(fmt::format("{}: {}: unknown key (only [[finding]])", origin, key));
    }
    int index = 0;
    for (const auto& item : value.as_array()) {
      ++index;
      const std::string where = fmt::format("{}: [[finding]] #{}", origin, index);
      Finding f;
      try {
        f.scene = toml::find<std::string>(item, "scene");
        f.quantity = toml::find<std::string>(item, "quantity");
        f.mode = toml::find<int>(item, "mode");
        f.solver = toml::find<std::string>(item, "solver");
        f.printed = toml::find<double>(item, "printed");
        f.ours = toml::find<double>(item, "ours");
        f.diagnosis = toml::find<std::string>(item, "diagnosis");
      } catch (const std::exception& error) {
        throw ParseError(fmt::format("{}: {}", where, error.what()));
      }
      if (item.as_table().size() != 7) throw ParseError(where + ": unknown keys (expected exactly 7)");
      table.findings_.push_back(std::move(f));
    }
  }
  return table;
}

const FindingsTable& FindingsTable::builtin() {
  static const FindingsTable table = parse(internal::kBuiltinFindings, "verification/findings.toml (built in)");
  return table;
}

const Finding* FindingsTable::find(const std::string& scene, const std::string& quantity, int mode,
                                   const std::string& solver) const {
  for (const auto& f : findings_) {
    if (f.scene == scene && f.quantity == quantity && f.mode == mode && f.solver == solver) return &f;
  }
  return nullptr;
}

}  // namespace catena
