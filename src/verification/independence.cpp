// SPDX-License-Identifier: MIT
#include "catena/verification/independence.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>
#include <vector>

namespace catena {
namespace {

bool is_value_check(const CheckResult& check) {
  return check.check == "frequency" || check.check == "tension" || check.check == "forced" ||
         check.check == "dynamic-tension";
}

// Per group: the number of values compared, whether every pair so far was bit-identical, and the
// values (for the string-limit test below).
struct IdentityGroup {
  const CheckResult* first = nullptr;
  int values = 0;
  bool identical = true;
  std::vector<double> list;
};

// A list of frequencies that are whole multiples of the lowest, each to a few roundings: the
// spectrum of a string, omega_n = n omega_1, the limit every exact and asymptotic formula reaches
// as the sag vanishes (eps -> 0). Two independent formulas there evaluate the same closed form and
// may round alike to the last bit (asymptotic's WKB and airy's Bessel string at eps <= 1e-7, issue
// 32): their coincidence is that of the known limit, not evidence of shared code. A shared code
// path away from the limit gives values that are not all harmonics and is still flagged.
bool is_harmonic_series(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const double first = values.front();
  if (!(first > 0.0)) return false;
  // n omega_1 and the n-th root each carry a few roundings: 8 ulp of the value.
  constexpr double kRoundings = 8.0 * std::numeric_limits<double>::epsilon();
  for (const double v : values) {
    const double n = std::round(v / first);
    if (n < 1.0 || std::abs(v - n * first) > kRoundings * v) return false;
  }
  return true;
}

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
    group.list.push_back(check.value_a);
  }
  std::vector<CheckResult> flags;
  for (const auto& [key, group] : groups) {
    if (group.values < 2 || !group.identical) continue;
    if (std::get<0>(key) == "frequency" && is_harmonic_series(group.list)) continue;
    CheckResult flag;
    flag.scene = group.first->scene;
    flag.check = kIdentityCheck;
    flag.compare = group.first->compare;
    flag.plane = group.first->plane;
    flag.value_a = flag.value_b = std::nan("");
    flag.measured = group.values;
    flag.verdict = Verdict::Fail;
    const std::string& plane = std::get<2>(key);
    flag.detail = fmt::format(
        "{}: all {} {}{} values are bit-identical. Two independent computations almost never "
        "round alike over a whole list (exact harmonics n omega_1, the string limit, excepted), so "
        "these values most likely come from the same code: the pair is one witness, not two, and "
        "its checks could not have failed. If the two solvers share the computation, declare it "
        "in SolverEntry::computations (the pair is then not compared); if they should be "
        "independent, find the code they share",
        flag.compare, group.values, plane.empty() ? "" : plane + " ", std::get<0>(key));
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
