#include "catena/verification/tolerance_table.hpp"

#include <algorithm>
#include <fnmatch.h>

namespace catena {
namespace {

bool matches(const std::string& pattern, const std::string& name) {
  return pattern == "*" || pattern == name;
}

}  // namespace

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
