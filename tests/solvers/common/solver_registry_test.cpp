// SPDX-License-Identifier: MIT
// The solver registry: the five solvers in their fixed order, lookup by name, the knob specs the
// docs and `catena solvers` are generated from, and run_solver (knobs validated before any work,
// a solver outside its model declining with the reason, each solver naming itself in its output).
#include "catena/solvers/solver_registry.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/solvers/fe_solver.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"

namespace catena {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A taut inclined cable with a finite EA: in every model but Gale's inextensible catenary.
testing::SolvedProblem taut_extensible() {
  return testing::prepare(make_taut_inclined_problem(0.1, 20.0, 10.0, 1.0));
}

SolverOutput run(const std::string& name,
                 const testing::SolvedProblem& solved,
                 const SolveRequest& request,
                 const SolverKnobs& knobs = {}) {
  const SolverEntry* entry = find_solver(name);
  if (entry == nullptr) throw std::logic_error("no solver " + name);
  return run_solver(*entry, SolveContext{solved.problem, solved.statics, solved.groups, request},
                    knobs);
}

std::string invalid_input_message(const std::string& name, const SolverKnobs& knobs) {
  const testing::SolvedProblem solved = taut_extensible();
  try {
    run(name, solved, testing::modes_request(1, 0), knobs);
  } catch (const InvalidInput& error) {
    return error.what();
  }
  return "";
}

// The default as `catena solvers` prints it, read back as a scene would write it.
KnobValue scene_value(const KnobSpec& spec) {
  if (spec.type == "flag") return spec.default_value == "true";
  if (spec.type == "integer") return std::stol(spec.default_value);
  if (spec.type == "real") return std::stod(spec.default_value);
  return spec.default_value.substr(1, spec.default_value.size() - 2);  // "\"adams\"" -> adams
}

TEST(SolverRegistry, ListsTheFiveSolversInTheirFixedOrder) {
  std::vector<std::string> names;
  for (const auto& entry : solver_registry()) names.push_back(entry.name);
  EXPECT_EQ(names, (std::vector<std::string>{"fe", "shooting", "frobenius", "asymptotic", "airy"}));
  // The same entries on every call (a static table, not rebuilt).
  EXPECT_EQ(&solver_registry(), &solver_registry());
}

TEST(SolverRegistry, FindSolverReturnsTheRegistryEntryOrNull) {
  for (const auto& entry : solver_registry()) {
    EXPECT_EQ(find_solver(entry.name), &entry) << entry.name;
  }
  EXPECT_EQ(find_solver("galerkin"), nullptr);
  EXPECT_EQ(find_solver(""), nullptr);
  EXPECT_EQ(find_solver("FE"), nullptr);  // names are exact
}

TEST(SolverRegistry, EveryEntryDescribesItselfAndItsKnobs) {
  const std::set<std::string> types = {"integer", "real", "flag", "choice"};
  for (const auto& entry : solver_registry()) {
    SCOPED_TRACE(entry.name);
    EXPECT_FALSE(entry.description.empty());
    EXPECT_TRUE(entry.validate_knobs);
    EXPECT_TRUE(entry.make_numerics);
    ASSERT_FALSE(entry.knobs.empty());
    std::set<std::string> names;
    for (const auto& knob : entry.knobs) {
      SCOPED_TRACE(knob.name);
      EXPECT_FALSE(knob.name.empty());
      EXPECT_TRUE(names.insert(knob.name).second) << "knob listed twice";
      EXPECT_FALSE(knob.description.empty());
      EXPECT_TRUE(types.count(knob.type)) << knob.type;
      EXPECT_FALSE(knob.default_value.empty());
      // Flags are true or false; every other knob says what values it accepts.
      if (knob.type == "flag") {
        EXPECT_TRUE(knob.default_value == "true" || knob.default_value == "false")
            << knob.default_value;
        EXPECT_TRUE(knob.valid.empty()) << knob.valid;
      } else {
        EXPECT_FALSE(knob.valid.empty());
      }
      if (knob.type == "choice") {
        EXPECT_EQ(knob.default_value.front(), '"');
        EXPECT_EQ(knob.default_value.back(), '"');
        EXPECT_TRUE(contains(knob.valid, knob.default_value)) << knob.valid;
      }
    }
  }
}

TEST(SolverRegistry, EveryDocumentedDefaultIsAcceptedWhenWrittenInAScene) {
  for (const auto& entry : solver_registry()) {
    for (const auto& knob : entry.knobs) {
      EXPECT_NO_THROW(entry.validate_knobs({{knob.name, scene_value(knob)}}))
          << entry.name << "." << knob.name;
    }
  }
}

TEST(SolverRegistry, UnknownKnobIsInvalidInputNamingTheKnobAndTheKnownOnes) {
  const std::string message = invalid_input_message("fe", {{"elemnts", 100L}});
  EXPECT_TRUE(contains(message, "[solvers.fe].elemnts")) << message;
  EXPECT_TRUE(contains(message, "elements")) << message;  // the known knob it should have been
  for (const auto& entry : solver_registry()) {
    EXPECT_THROW(entry.validate_knobs({{"no_such_knob", true}}), InvalidInput) << entry.name;
  }
}

TEST(SolverRegistry, OutOfRangeOrMistypedKnobIsInvalidInputNamingTheKnob) {
  EXPECT_TRUE(
      contains(invalid_input_message("fe", {{"elements", 1L}}), "[solvers.fe].elements = 1"));
  EXPECT_TRUE(
      contains(invalid_input_message("fe", {{"richardson", 1L}}), "[solvers.fe].richardson"));
  EXPECT_TRUE(contains(invalid_input_message("shooting", {{"rtol", std::string("small")}}),
                       "[solvers.shooting].rtol"));
}

TEST(SolverRegistry, KnobsAreValidatedBeforeApplicability) {
  // frobenius declines this cable, but a misspelt knob is still bad input, not a quiet decline.
  const std::string message = invalid_input_message("frobenius", {{"tolerence", 1e-10}});
  EXPECT_TRUE(contains(message, "[solvers.frobenius].tolerence")) << message;
}

TEST(SolverRegistry, InvalidRequestPropagatesAsInvalidInput) {
  const testing::SolvedProblem solved = taut_extensible();
  SolveRequest request = testing::modes_request(2, 0);
  request.inplane_modes = -1;
  EXPECT_THROW(run("fe", solved, request, {{"elements", 20L}}), InvalidInput);
}

TEST(SolverRegistry, FrobeniusDeclinesAnExtensibleCableWithTheReason) {
  const testing::SolvedProblem solved = taut_extensible();
  const SolverOutput output = run("frobenius", solved, testing::modes_request(2, 1));
  EXPECT_EQ(output.solver, "frobenius");
  EXPECT_EQ(output.summary.solver, "frobenius");
  EXPECT_EQ(output.summary.termination, Termination::NotApplicable);
  EXPECT_TRUE(contains(output.summary.message, "inextensible")) << output.summary.message;
  EXPECT_FALSE(output.summary.is_usable());
  // Declining does no work: no modes in either plane.
  EXPECT_FALSE(output.inplane.has_value());
  EXPECT_FALSE(output.outofplane.has_value());
}

TEST(SolverRegistry, RunSolverReadsTheKnobsLikeTheTypedEntryPoint) {
  // The registry path (scene knobs) and the typed path (options struct) run the same numerics:
  // the same options give bit-identical frequencies.
  const testing::SolvedProblem solved = taut_extensible();
  const SolveRequest request = testing::modes_request(3, 2);
  const SolverOutput by_name =
      run("fe", solved, request, {{"elements", 40L}, {"richardson", false}});
  FeSolverOptions options;
  options.elements = 40;
  options.richardson = false;
  const SolverOutput typed =
      solve_fe(solved.problem, solved.statics, solved.groups, request, options);
  ASSERT_TRUE(by_name.inplane && typed.inplane && by_name.outofplane && typed.outofplane);
  ASSERT_EQ(by_name.inplane->modes.size(), 3u);
  ASSERT_EQ(by_name.outofplane->modes.size(), 2u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(by_name.inplane->modes[i].omega_rad_s, typed.inplane->modes[i].omega_rad_s) << i;
  }
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(by_name.outofplane->modes[i].omega_rad_s, typed.outofplane->modes[i].omega_rad_s)
        << i;
  }
  EXPECT_EQ(by_name.summary.termination, Termination::Converged);
  EXPECT_EQ(by_name.summary.solver, "fe");
  EXPECT_GE(by_name.summary.wall_time_s, 0.0);
  // A knob left out takes its default: elements = 40 with Richardson on is a different mesh pair.
  const SolverOutput richardson = run("fe", solved, request, {{"elements", 40L}});
  EXPECT_NE(richardson.inplane->modes[0].omega_rad_s, by_name.inplane->modes[0].omega_rad_s);
}

TEST(SolverRegistry, EverySolverNamesItselfInItsOutput) {
  const testing::SolvedProblem solved = taut_extensible();
  for (const auto& entry : solver_registry()) {
    const SolverOutput output = run_solver(
        entry,
        SolveContext{solved.problem, solved.statics, solved.groups, testing::modes_request(2, 0)},
        {});
    EXPECT_EQ(output.solver, entry.name);
    EXPECT_EQ(output.summary.solver, entry.name);
    // Every solver but Gale's (inextensible only) covers this slightly sagging taut cable.
    if (entry.name == "frobenius") {
      EXPECT_EQ(output.summary.termination, Termination::NotApplicable);
    } else {
      EXPECT_TRUE(output.summary.is_usable())
          << entry.name << ": " << output.summary.brief_report();
      ASSERT_TRUE(output.inplane.has_value()) << entry.name;
      ASSERT_EQ(output.inplane->modes.size(), 2u) << entry.name;
      EXPECT_LT(output.inplane->modes[0].omega_rad_s, output.inplane->modes[1].omega_rad_s)
          << entry.name;
    }
  }
}

// The roles the harness reads instead of naming solvers (docs/reference/verdicts.md, "Solver
// roles"): each solver declares them in its entry.
TEST(SolverRegistry, EachSolverDeclaresItsRoles) {
  EXPECT_EQ(solver_names(SolverKind::Exact),
            (std::vector<std::string>{"fe", "shooting", "frobenius"}));
  EXPECT_EQ(solver_names(SolverKind::Model), (std::vector<std::string>{"asymptotic", "airy"}));
  for (const char* exact : {"fe", "shooting", "frobenius"}) EXPECT_TRUE(is_exact_solver(exact));
  for (const char* other : {"asymptotic", "airy", "galerkin"}) EXPECT_FALSE(is_exact_solver(other));
  // Most accurate at the defaults first: frobenius 1e-11, shooting 1.1e-9, fe 1e-6.
  EXPECT_EQ(exact_solvers_by_accuracy(), (std::vector<std::string>{"frobenius", "shooting", "fe"}));
  // Gale's series solves the inextensible catenary only: it certifies no reference.
  EXPECT_EQ(reference_solvers(), (std::vector<std::string>{"shooting", "fe"}));
  EXPECT_TRUE(find_solver("fe")->all_modes_at_once);
  EXPECT_FALSE(find_solver("shooting")->all_modes_at_once);
  EXPECT_FALSE(find_solver("frobenius")->all_modes_at_once);
  for (const auto& entry : solver_registry()) {
    // An exact solver states its accuracy; a model's is each mode's estimate.
    EXPECT_EQ(static_cast<bool>(entry.accuracy_target), entry.kind == SolverKind::Exact)
        << entry.name;
    // The models compute no forced response; every exact solver does.
    EXPECT_EQ(entry.computations.count("forced") == 1, entry.kind == SolverKind::Exact)
        << entry.name;
  }
}

// The entry's accuracy target is the one the solver's plane summaries report, whenever the solver
// was asked for one (one function for both: no copy to drift). fe asked for no tolerance reports
// none; its entry then states what its default mesh is declared to reach.
TEST(SolverRegistry, TheEntrysAccuracyTargetIsTheOneTheSummariesReport) {
  struct Case {
    const char* solver;
    SolverKnobs knobs;
    bool inextensible;
  };
  const std::vector<Case> cases = {{"shooting", {}, false},
                                   {"shooting", {{"rtol", 1e-8}, {"root_tolerance", 1e-9}}, false},
                                   {"fe", {{"tolerance", 1e-3}}, false},
                                   {"frobenius", {}, true},
                                   {"frobenius", {{"tolerance", 1e-15}}, true}};
  const testing::SolvedProblem taut = taut_extensible();
  const testing::SolvedProblem gale = testing::prepare(make_gale_sag_problem(0.0, 0.9));
  for (const Case& c : cases) {
    SCOPED_TRACE(c.solver);
    const SolverOutput output =
        run(c.solver, c.inextensible ? gale : taut, testing::modes_request(2, 0), c.knobs);
    ASSERT_TRUE(output.inplane.has_value()) << output.summary.brief_report();
    EXPECT_DOUBLE_EQ(output.inplane->summary.accuracy_target,
                     find_solver(c.solver)->accuracy_target(c.knobs));
  }
  // fe's default tolerance is its declared accuracy: the summaries report it (0 asks for none).
  EXPECT_DOUBLE_EQ(run("fe", taut, testing::modes_request(2, 0)).inplane->summary.accuracy_target,
                   1e-6);
  EXPECT_DOUBLE_EQ(run("fe", taut, testing::modes_request(2, 0), {{"tolerance", 0.0}})
                       .inplane->summary.accuracy_target,
                   -1.0);
  EXPECT_DOUBLE_EQ(find_solver("fe")->accuracy_target({}), 1e-6);
  EXPECT_THROW(find_solver("shooting")->accuracy_target({{"rtol", -1.0}}), InvalidInput);
}

TEST(SolverRegistry, RegisterSolverRejectsAnEntryItCannotRun) {
  SolverEntry unnamed = *find_solver("fe");
  unnamed.name.clear();
  EXPECT_THROW(register_solver(unnamed), InvalidInput);
  EXPECT_THROW(register_solver(*find_solver("fe")), InvalidInput);  // the name is taken
  SolverEntry hollow;
  hollow.name = "hollow";
  EXPECT_THROW(register_solver(hollow), InvalidInput);  // no validate_knobs, no make_numerics
  EXPECT_EQ(solver_registry().size(), 5u);
}

}  // namespace
}  // namespace catena
