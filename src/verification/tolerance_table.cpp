// SPDX-License-Identifier: MIT
#include "catena/verification/tolerance_table.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <cmath>

namespace catena {
namespace {

bool matches(const std::string& pattern, const std::string& name) {
  return pattern == "*" || pattern == name;
}

}  // namespace

bool is_model_parameter(const std::string& name) { return name == "eps"; }

double ToleranceRule::model_term(const ModelParameters& parameters) const {
  double term = strain_constant * parameters.strain;
  if (model_parameter == "eps") term += constant * std::pow(std::abs(parameters.eps), model_order);
  return term;
}

double ToleranceRule::tolerance(const ModelParameters& parameters) const {
  return max + model_term(parameters);
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
    if (rule.scene_pattern != "*" && fnmatch(rule.scene_pattern.c_str(), scene.c_str(), 0) != 0)
      continue;
    if (!rule.tag.empty() && std::find(tags.begin(), tags.end(), rule.tag) == tags.end()) continue;
    return &rule;
  }
  return nullptr;
}

const SolverAccuracy* ToleranceTable::solver(const std::string& name) const {
  for (const auto& s : solvers_) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

}  // namespace catena
