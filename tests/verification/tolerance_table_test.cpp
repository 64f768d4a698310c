// SPDX-License-Identifier: MIT
// ToleranceTable::find: the first rule that matches check, solver pair (either order, "*"), scene
// glob and tag wins; the table's [[solver]] families and fe's default accuracy agree with the
// solver registry.
#include "catena/verification/tolerance_table.hpp"

#include <gtest/gtest.h>

#include "catena/io/tolerance_reader.hpp"
#include "catena/solvers/solver_registry.hpp"

namespace catena {
namespace {

ToleranceRule rule(std::string check,
                   std::string a,
                   std::string b,
                   double max,
                   std::string scene = "*",
                   std::string tag = "") {
  ToleranceRule r;
  r.check = std::move(check);
  r.compare = {std::move(a), std::move(b)};
  r.scene_pattern = std::move(scene);
  r.tag = std::move(tag);
  r.max = max;
  r.reason = "test";
  return r;
}

TEST(ToleranceTable, FirstMatchingRuleWins) {
  const ToleranceTable table({rule("frequency", "fe", "shooting", 1e-6, "gale-*"),
                              rule("frequency", "fe", "*", 1e-4, "*", "stress"),
                              rule("frequency", "*", "*", 1e-2)});
  EXPECT_EQ(table.find("frequency", "shooting", "fe", "gale-1", {})->max, 1e-6);  // either order
  EXPECT_EQ(table.find("frequency", "fe", "shooting", "other", {"stress"})->max, 1e-4);
  EXPECT_EQ(table.find("frequency", "fe", "shooting", "other", {})->max, 1e-2);
  EXPECT_EQ(table.find("frequency", "airy", "frobenius", "gale-1", {})->max, 1e-2);
  EXPECT_EQ(table.find("mac", "fe", "shooting", "gale-1", {}), nullptr);
}

TEST(ToleranceTable, EmptyTableFindsNothing) {
  const ToleranceTable table;
  EXPECT_TRUE(table.rules().empty());
  EXPECT_EQ(table.find("frequency", "fe", "shooting", "x", {}), nullptr);
}

TEST(ToleranceTable, AModelRuleAddsItsPublishedOrderInTheModelParameter) {
  ToleranceRule r = rule("frequency", "asymptotic", "*", 1e-9);
  r.model_parameter = "eps";
  r.model_order = 2;
  r.constant = 0.5;
  r.strain_constant = 0.25;
  const ModelParameters scene{0.1, 1e-3};
  EXPECT_DOUBLE_EQ(r.model_term(scene), 0.5 * 0.01 + 0.25 * 1e-3);
  EXPECT_DOUBLE_EQ(r.tolerance(scene), 1e-9 + 0.5 * 0.01 + 0.25 * 1e-3);
  // Halving eps quarters the model part: the order, not a solver's estimate, sets it.
  EXPECT_DOUBLE_EQ(r.model_term({0.05, 0.0}), r.model_term({0.1, 0.0}) / 4.0);
  // A rule without a model term is its fixed max.
  EXPECT_EQ(rule("frequency", "fe", "*", 1e-6).tolerance(scene), 1e-6);
}

TEST(ToleranceTable, FindsASolverDeclarationByName) {
  SolverAccuracy fe;
  fe.name = "fe";
  fe.exact = true;
  fe.accuracy = 1e-6;
  const ToleranceTable table({}, {fe});
  ASSERT_NE(table.solver("fe"), nullptr);
  EXPECT_EQ(table.solver("fe")->accuracy, 1e-6);
  EXPECT_EQ(table.solver("shooting"), nullptr);
}

// verification/tolerances.toml declares each solver's family (exact or model) for the estimate
// check, and the registry declares its kind for everything else: one must not drift from the
// other. The same for the accuracy a solver asked for none is held to (fe: 1e-6).
TEST(ToleranceTable, TheBuiltinSolverDeclarationsAgreeWithTheRegistry) {
  const ToleranceTable table = builtin_tolerance_table();
  for (const SolverEntry& entry : solver_registry()) {
    SCOPED_TRACE(entry.name);
    const SolverAccuracy* declared = table.solver(entry.name);
    ASSERT_NE(declared, nullptr);
    EXPECT_EQ(declared->exact, entry.kind == SolverKind::Exact);
    if (entry.accuracy_target && declared->accuracy_knob.empty()) {
      EXPECT_DOUBLE_EQ(declared->accuracy, entry.accuracy_target({}));
    }
  }
}

}  // namespace
}  // namespace catena
