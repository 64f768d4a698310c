// SPDX-License-Identifier: MIT
// Independence: the shared-computation lookup on declared code paths, the registry's declarations,
// and the identity detector on hand-made check lists.
#include "catena/verification/independence.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace catena {
namespace {

SolverEntry entry(const std::string& name, std::map<std::string, std::string> computations) {
  SolverEntry e;
  e.name = name;
  e.computations = std::move(computations);
  return e;
}

TEST(Independence, SharedOnlyWhenBothDeclareTheSameId) {
  const SolverEntry a =
      entry("a", {{"frequency-out-of-plane", "wkb"}, {"frequency-in-plane", "a-det"}});
  const SolverEntry b =
      entry("b", {{"frequency-out-of-plane", "wkb"}, {"frequency-in-plane", "b-det"}});
  const SolverEntry c = entry("c", {});
  EXPECT_EQ(shared_computation(a, b, "frequency-out-of-plane"), "wkb");
  EXPECT_EQ(shared_computation(a, b, "frequency-in-plane"), std::nullopt);
  EXPECT_EQ(shared_computation(a, c, "frequency-out-of-plane"),
            std::nullopt);  // undeclared: not shared
}

TEST(Independence, EveryRegisteredSolverDeclaresItsFrequencyPaths) {
  for (const auto& solver : solver_registry()) {
    EXPECT_TRUE(solver.computations.count("frequency-in-plane")) << solver.name;
    EXPECT_TRUE(solver.computations.count("frequency-out-of-plane")) << solver.name;
    for (const auto& [quantity, id] : solver.computations) {
      EXPECT_NE(std::find(compared_quantities().begin(), compared_quantities().end(), quantity),
                compared_quantities().end())
          << solver.name << ": " << quantity;
      EXPECT_FALSE(id.empty()) << solver.name << ": " << quantity;
    }
  }
  // The exact solvers share nothing with anyone.
  for (const char* exact : {"fe", "shooting", "frobenius"}) {
    for (const auto& other : solver_registry()) {
      if (other.name == exact) continue;
      for (const auto& quantity : compared_quantities()) {
        EXPECT_EQ(shared_computation(*find_solver(exact), other, quantity), std::nullopt)
            << exact << " and " << other.name << " on " << quantity;
      }
    }
  }
}

CheckResult value_check(const std::string& kind, int mode, double a, double b) {
  CheckResult c;
  c.scene = "s";
  c.check = kind;
  c.compare = "x vs y";
  c.plane = "in-plane";
  c.mode = mode;
  c.value_a = a;
  c.value_b = b;
  c.verdict = Verdict::Pass;
  return c;
}

TEST(Independence, IdentityDetectorFlagsAWholeListOfBitIdenticalValues) {
  const std::vector<CheckResult> identical = {value_check("frequency", 1, 1.5, 1.5),
                                              value_check("frequency", 2, 2.5, 2.5)};
  const auto flags = identity_checks(identical);
  ASSERT_EQ(flags.size(), 1u);
  EXPECT_EQ(flags[0].check, kIdentityCheck);
  EXPECT_EQ(flags[0].verdict, Verdict::Fail);
  EXPECT_EQ(flags[0].compare, "x vs y");
  // One differing value, a single value, or a non-value check (MAC) is not flagged.
  EXPECT_TRUE(
      identity_checks({identical[0], value_check("frequency", 2, 2.5, std::nextafter(2.5, 3.0))})
          .empty());
  EXPECT_TRUE(identity_checks({identical[0]}).empty());
  EXPECT_TRUE(
      identity_checks({value_check("mac", 1, 1.0, 1.0), value_check("mac", 2, 1.0, 1.0)}).empty());
  // Exact zeros (no dynamic tension under out-of-plane forcing) and skipped checks are no evidence.
  EXPECT_TRUE(
      identity_checks({value_check("forced", 1, 0.0, 0.0), value_check("forced", 2, 0.0, 0.0)})
          .empty());
  CheckResult skipped = identical[1];
  skipped.verdict = Verdict::Skipped;
  EXPECT_TRUE(identity_checks({identical[0], skipped}).empty());
  // Different planes are different lists.
  CheckResult other_plane = identical[1];
  other_plane.plane = "out-of-plane";
  EXPECT_TRUE(identity_checks({identical[0], other_plane}).empty());
}

TEST(Independence, TallyCountsIdentityFlagsAndSharedSkips) {
  SceneResult result;
  result.checks =
      identity_checks({value_check("tension", 1, 3.0, 3.0), value_check("tension", 2, 4.0, 4.0)});
  CheckResult skip = value_check("frequency", 0, std::nan(""), std::nan(""));
  skip.verdict = Verdict::Skipped;
  skip.detail = std::string(kSharedComputationDetail) + "wkb-out-of-plane";
  result.checks.push_back(skip);
  const IndependenceTally tally = tally_independence({result, result});
  EXPECT_EQ(tally.identity_checks, 2);
  EXPECT_EQ(tally.shared_not_compared, 2);
}

}  // namespace
}  // namespace catena
