// SPDX-License-Identifier: MIT
// Limits on work: a run whose deadline has passed stops after the unit of work in progress and
// keeps valid partial results (never a hang, never a wrong "converged"); progress is reported
// per unit; oversized requests are refused naming the field. No test depends on timing: an
// already expired deadline makes every check deterministic.
#include "catena/solvers/run_limits.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <string>

#include "catena/core/error.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "solvers/common/work_meter.hpp"

namespace catena {
namespace {

// A deadline that has already passed.
RunLimits expired_limits() {
  RunLimits limits;
  limits.deadline = RunLimits::Clock::now() - std::chrono::seconds(1);
  limits.time_limit_s = 0.5;
  return limits;
}

SolverOutput run(const std::string& solver,
                 const testing::SolvedProblem& solved,
                 const SolveRequest& request,
                 const RunLimits* limits) {
  const SolveContext context{solved.problem, solved.statics, solved.groups, request, limits};
  return run_solver(*find_solver(solver), context, {});
}

SolveRequest modes_and_forcing(int inplane, int outofplane) {
  SolveRequest request = testing::modes_request(inplane, outofplane);
  request.points = 11;
  request.forced = ForcedRequest{};
  request.forced->omegas_rad_s = {0.3, 0.6, 0.9};
  return request;
}

class ExpiredDeadline : public ::testing::TestWithParam<std::string> {
 protected:
  // Gale's inextensible catenary, h/b = 0, sag parameter 0.7: fe, shooting and frobenius apply.
  testing::SolvedProblem solved = testing::prepare(make_gale_sag_problem(0.0, 0.7));
};

// The first part starts (its first unit always runs); the deadline has passed, so it stops
// there and the parts not started are reported with nothing done.
TEST_P(ExpiredDeadline, StopsWithValidPartialResultsAndSaysWhy) {
  const RunLimits limits = expired_limits();
  const SolveRequest request = modes_and_forcing(4, 2);
  const SolverOutput limited = run(GetParam(), solved, request, &limits);
  const SolverOutput full = run(GetParam(), solved, request, nullptr);
  ASSERT_EQ(full.summary.termination, Termination::Converged) << full.summary.message;
  EXPECT_EQ(limited.summary.termination, Termination::NoConvergence);
  ASSERT_TRUE(limited.inplane && limited.outofplane);
  const ModalResult& inplane = *limited.inplane;
  EXPECT_EQ(inplane.summary.termination, Termination::NoConvergence);
  EXPECT_NE(inplane.summary.message.find("time limit of 0.5 s reached after"), std::string::npos)
      << inplane.summary.message;
  EXPECT_LT(inplane.modes.size(), 4u);
  // What is returned is what the unlimited run returns: the lowest modes, exactly.
  for (std::size_t i = 0; i < inplane.modes.size(); ++i) {
    EXPECT_EQ(inplane.modes[i].index, static_cast<int>(i) + 1);
    EXPECT_EQ(inplane.modes[i].omega_rad_s, full.inplane->modes[i].omega_rad_s);
  }
  EXPECT_TRUE(limited.outofplane->modes.empty());
  EXPECT_NE(limited.outofplane->summary.message.find("reached after 0 of 2 out-of-plane modes"),
            std::string::npos)
      << limited.outofplane->summary.message;
  EXPECT_TRUE(limited.forced.empty());
  EXPECT_NE(limited.summary.message.find("reached after 0 of 3 forced frequencies"),
            std::string::npos)
      << limited.summary.message;
}

INSTANTIATE_TEST_SUITE_P(Solvers,
                         ExpiredDeadline,
                         ::testing::Values("fe", "shooting", "frobenius"));

// shooting stops per mode: exactly the first mode is kept. frobenius checks before each
// determinant (one root at max_terms in quad precision takes dozens of them: a 60-mode Gale
// scene ran 39 s under --time-limit 5, issue 32), so past the deadline it keeps none.
TEST_F(ExpiredDeadline, ShootingKeepsTheFirstModeFoundAndFrobeniusStopsInsideIt) {
  const RunLimits limits = expired_limits();
  for (const auto& [solver, kept] : {std::pair{"shooting", 1u}, std::pair{"frobenius", 0u}}) {
    const SolverOutput output = run(solver, solved, testing::modes_request(5, 0), &limits);
    ASSERT_TRUE(output.inplane) << solver;
    EXPECT_EQ(output.inplane->modes.size(), kept) << solver;
    EXPECT_EQ(output.summary.termination, Termination::NoConvergence) << solver;
    EXPECT_NE(output.summary.message.find(
                  fmt::format("time limit of 0.5 s reached after {} of 5 in-plane modes", kept)),
              std::string::npos)
        << solver << ": " << output.summary.message;
  }
}

// A hang guard (not a speed test): frobenius on Gale's catenary, sag parameter 0.9, 60 modes per
// plane at max_terms 5000 and tolerance 1e-15 takes minutes; under a 1 s limit it stops with the
// reason. 30 s only catches a check that no longer runs inside the root search.
TEST(RunLimitsTimeLimit, FrobeniusStopsWithinTheLimitOnALongRun) {
  const testing::SolvedProblem solved = testing::prepare(make_gale_sag_problem(0.0, 0.9));
  const RunLimits limits = RunLimits::time_limit(1.0);
  const SolveContext context{solved.problem, solved.statics, solved.groups,
                             testing::modes_request(60, 60), &limits};
  const auto start = RunLimits::Clock::now();
  const SolverOutput output =
      run_solver(*find_solver("frobenius"), context, {{"max_terms", 5000L}, {"tolerance", 1e-15}});
  const double seconds = std::chrono::duration<double>(RunLimits::Clock::now() - start).count();
  EXPECT_EQ(output.summary.termination, Termination::NoConvergence);
  EXPECT_NE(output.summary.message.find("time limit of 1 s reached after"), std::string::npos)
      << output.summary.message;
  EXPECT_LT(seconds, 30.0);
}

// A hang guard (not a speed test): fe at 1000 in-plane modes grows its default mesh to 2000
// elements, and one Lanczos run there takes minutes that cannot be split into levels; under a 1 s
// limit the operator's stop hook ends it with the reason. 30 s only catches a hook that no longer
// reaches inside the iteration.
TEST(RunLimitsTimeLimit, FeStopsInsideOneLanczosRunOnALongRun) {
  const testing::SolvedProblem solved = testing::prepare(make_gale_sag_problem(0.0, 0.9));
  const RunLimits limits = RunLimits::time_limit(1.0);
  const SolveContext context{solved.problem, solved.statics, solved.groups,
                             testing::modes_request(1000, 0), &limits};
  const auto start = RunLimits::Clock::now();
  const SolverOutput output = run_solver(*find_solver("fe"), context, {});
  const double seconds = std::chrono::duration<double>(RunLimits::Clock::now() - start).count();
  EXPECT_EQ(output.summary.termination, Termination::NoConvergence);
  EXPECT_NE(output.summary.message.find("time limit of 1 s reached after"), std::string::npos)
      << output.summary.message;
  EXPECT_LT(seconds, 30.0);
}

// A forced response alone: its first frequency is computed, the rest are not.
TEST_F(ExpiredDeadline, ForcedResponseKeepsTheFrequenciesDone) {
  const RunLimits limits = expired_limits();
  SolveRequest request = modes_and_forcing(0, 0);
  for (const std::string solver : {"fe", "shooting", "frobenius"}) {
    const SolverOutput output = run(solver, solved, request, &limits);
    ASSERT_EQ(output.forced.size(), 1u) << solver << ": " << output.summary.message;
    EXPECT_EQ(output.forced[0].omega_rad_s, 0.3);
    EXPECT_EQ(output.summary.termination, Termination::NoConvergence) << solver;
    EXPECT_NE(output.summary.message.find("reached after 1 of 3 forced frequencies"),
              std::string::npos)
        << solver << ": " << output.summary.message;
  }
}

// airy checks its scan every chunk of steps: an expired deadline stops it after the first chunk
// with the roots below the point reached, each the unlimited run's.
TEST(ExpiredDeadlineAiry, StopsTheScanAndKeepsTheRootsBelow) {
  const testing::SolvedProblem solved =
      testing::prepare(make_taut_inclined_problem(0.5, 30.0, 50.0, 1.0));
  const RunLimits limits = expired_limits();
  const SolveRequest request = testing::modes_request(60, 0);
  const SolverOutput full = run("airy", solved, request, nullptr);
  ASSERT_TRUE(full.inplane && full.inplane->modes.size() == 60u) << full.summary.message;
  const SolverOutput limited = run("airy", solved, request, &limits);
  ASSERT_TRUE(limited.inplane);
  EXPECT_LT(limited.inplane->modes.size(), 60u);
  EXPECT_EQ(limited.summary.termination, Termination::NoConvergence);
  EXPECT_NE(limited.summary.message.find("time limit of 0.5 s"), std::string::npos)
      << limited.summary.message;
  for (std::size_t i = 0; i < limited.inplane->modes.size(); ++i)
    EXPECT_EQ(limited.inplane->modes[i].omega_rad_s, full.inplane->modes[i].omega_rad_s);
}

TEST(Progress, ReportsEachUnitOfEveryPart) {
  const testing::SolvedProblem solved = testing::prepare(make_gale_sag_problem(0.0, 0.7));
  std::map<std::string, std::vector<long>> done_by_part;
  RunLimits limits;
  limits.progress = [&](const std::string& solver, const std::string& part, long done, long total) {
    EXPECT_EQ(solver, "shooting");
    done_by_part[part + " of " + std::to_string(total)].push_back(done);
  };
  const SolverOutput output = run("shooting", solved, modes_and_forcing(3, 2), &limits);
  EXPECT_EQ(output.summary.termination, Termination::Converged) << output.summary.message;
  EXPECT_EQ(done_by_part["in-plane modes of 3"], (std::vector<long>{1, 2, 3}));
  EXPECT_EQ(done_by_part["out-of-plane modes of 2"], (std::vector<long>{1, 2}));
  EXPECT_EQ(done_by_part["forced frequencies of 3"], (std::vector<long>{1, 2, 3}));
  EXPECT_EQ(done_by_part.size(), 3u);
}

TEST(RunLimitsTimeLimit, RefusesNonPositiveNonFiniteAndHugeLimits) {
  for (double bad : {0.0, -1.0, std::nan(""), kInfinity, 2e9}) {
    EXPECT_THROW(RunLimits::time_limit(bad), InvalidInput) << bad;
  }
  try {
    RunLimits::check_time_limit(-2.0, "--time-limit");
    FAIL();
  } catch (const InvalidInput& error) {
    EXPECT_NE(std::string(error.what()).find("--time-limit = -2"), std::string::npos)
        << error.what();
  }
  const RunLimits limits = RunLimits::time_limit(3600.0);
  EXPECT_FALSE(limits.expired());
  EXPECT_EQ(limits.time_limit_s, 3600.0);
}

TEST(SolveRequestLimits, RefusesTooManyModesOrForcingFrequenciesNamingTheField) {
  SolveRequest request = testing::modes_request(kMaxRequestModes, kMaxRequestModes);
  EXPECT_NO_THROW(request.validate());
  auto message_of = [](const SolveRequest& r) {
    try {
      r.validate();
    } catch (const InvalidInput& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  request.inplane_modes = kMaxRequestModes + 1;
  EXPECT_NE(message_of(request).find("inplane_modes = 1001"), std::string::npos)
      << message_of(request);
  request.inplane_modes = 1;
  request.outofplane_modes = kMaxRequestModes + 1;
  EXPECT_NE(message_of(request).find("outofplane_modes"), std::string::npos) << message_of(request);
  request.outofplane_modes = 0;
  request.forced = ForcedRequest{};
  request.forced->omegas_rad_s.assign(SolveRequest::kMaxForcingFrequencies, 1.0);
  EXPECT_NO_THROW(request.validate());
  request.forced->omegas_rad_s.push_back(1.0);
  EXPECT_NE(message_of(request).find("omegas_rad_s: 100001 forcing frequencies"), std::string::npos)
      << message_of(request);
}

}  // namespace
}  // namespace catena
