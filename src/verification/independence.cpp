// SPDX-License-Identifier: MIT
#include "catena/verification/independence.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <tuple>

namespace catena {
namespace {

bool is_value_check(const CheckResult& check) {
  return check.check == "frequency" || check.check == "tension" || check.check == "forced" ||
         check.check == "dynamic-tension";
}

// Per group: the number of values compared and whether every pair so far was bit-identical.
struct IdentityGroup {
  const CheckResult* first = nullptr;
  int values = 0;
  bool identical = true;
};

}  // namespace

std::optional<std::string> shared_computation(const SolverEntry& a,
                                              const SolverEntry& b,
                                              const std::string& quantity) {
  const auto x = a.computations.find(quantity);
  const auto y = b.computations.find(quantity);
  if (x == a.computations.end() || y == b.computations.end() || x->second != y->second)
    return std::nullopt;
  return x->second;
}

std::vector<CheckResult> identity_checks(const std::vector<CheckResult>& checks) {
  std::map<std::tuple<std::string, std::string, std::string>, IdentityGroup> groups;
  for (const auto& check : checks) {
    if (!is_value_check(check) || check.verdict == Verdict::Skipped) continue;
    if (!std::isfinite(check.value_a) || !std::isfinite(check.value_b)) continue;
    // Exact zeros are structure, not computation (no dynamic tension under out-of-plane forcing).
    if (check.value_a == 0.0 && check.value_b == 0.0) continue;
    IdentityGroup& group = groups[{check.check, check.compare, check.plane}];
    if (!group.first) group.first = &check;
    ++group.values;
    // Bit-identical, not merely close: two independent computations never round alike over a list.
    group.identical = group.identical && check.value_a == check.value_b;
  }
  std::vector<CheckResult> flags;
  for (const auto& [key, group] : groups) {
    if (group.values < 2 || !group.identical) continue;
    CheckResult flag;
    flag.scene = group.first->scene;
    flag.check = kIdentityCheck;
    flag.compare = group.first->compare;
    flag.plane = group.first->plane;
    flag.value_a = flag.value_b = std::nan("");
    flag.measured = group.values;
    flag.verdict = Verdict::Fail;
    flag.detail = fmt::format(
        "all {} {} values of {} are bit-identical: two values from shared code, a check "
        "that cannot fail (declare the shared computation in SolverEntry::computations)",
        group.values, std::get<0>(key), flag.compare);
    flags.push_back(std::move(flag));
  }
  return flags;
}

IndependenceTally tally_independence(const std::vector<SceneResult>& results) {
  IndependenceTally tally;
  for (const auto& result : results) {
    for (const auto& check : result.checks) {
      tally.identity_checks += check.check == kIdentityCheck;
      tally.shared_not_compared +=
          check.verdict == Verdict::Skipped && check.detail.rfind(kSharedComputationDetail, 0) == 0;
    }
  }
  return tally;
}

}  // namespace catena
