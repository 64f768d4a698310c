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

// Issue 32: at eps <= 1e-7 two independent exact string formulas (a WKB quadrature and a Bessel
// solution) both return omega_n = n omega_1 to the last bit. The values below are those of the
// taut_inclined eps = 1e-7 scene out of plane: n pi / sqrt(1 + e0), e0 = 7.5e-11, computed as
// n times the first (as a closed form does) and as the n-th multiple rounded once more (as a root
// finder lands on it).
TEST(Independence, IdentityDetectorLeavesTheStringLimitsHarmonicsAlone) {
  const double first = 3.14159265347;
  std::vector<CheckResult> harmonics;
  for (int n = 1; n <= 4; ++n) {
    const double v = n % 2 ? n * first : std::nextafter(n * first, 0.0);
    harmonics.push_back(value_check("frequency", n, v, v));
  }
  EXPECT_TRUE(identity_checks(harmonics).empty());
  // Missing modes are still harmonics (n = 1, 3).
  EXPECT_TRUE(identity_checks({harmonics[0], harmonics[2]}).empty());
}

// A test double of a real shared computation: bit-identical values off the string limit (the
// in-plane frequencies of a sagging cable are no harmonic series), and harmonics that are not
// frequencies (tension amplitudes), are still flagged, with a message that says what was seen.
TEST(Independence, IdentityDetectorStillCatchesSharedCodeOffTheStringLimit) {
  const std::vector<CheckResult> shared = {
      value_check("frequency", 1, 3.14160555418, 3.14160555418),
      value_check("frequency", 2, 6.28318530718, 6.28318530718),
      value_check("frequency", 3, 9.42477843857, 9.42477843857)};
  const auto flags = identity_checks(shared);
  ASSERT_EQ(flags.size(), 1u);
  EXPECT_NE(flags[0].detail.find("x vs y: all 3 in-plane frequency values are bit-identical"),
            std::string::npos)
      << flags[0].detail;
  EXPECT_NE(flags[0].detail.find("SolverEntry::computations"), std::string::npos);
  // One value off a harmonic by more than rounding (1e-12 relative) is no string limit either.
  EXPECT_EQ(identity_checks({value_check("frequency", 1, 1.0, 1.0),
                             value_check("frequency", 2, 2.0 + 2e-12, 2.0 + 2e-12)})
                .size(),
            1u);
  EXPECT_EQ(
      identity_checks({value_check("tension", 1, 1.0, 1.0), value_check("tension", 2, 2.0, 2.0)})
          .size(),
      1u);
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
