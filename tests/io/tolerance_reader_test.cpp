// SPDX-License-Identifier: MIT
// Reading the tolerance table: the built-in table (verification/tolerances.toml) parses and every
// rule carries a reason; malformed rules are rejected naming the file and the rule.
#include "catena/io/tolerance_reader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "catena/core/error.hpp"

namespace catena {
namespace {

const char* kOneRule = R"(
[[tolerance]]
check = "frequency"
compare = ["fe", "*"]
scene = "gale-*"
tag = "gale"
max = 1e-6
model_parameter = "eps"
model_order = 2
constant = 0.5
strain_constant = 0.25
beyond = "warn"
reason = "fe's target plus a model term"

[[solver]]
name = "shooting"
family = "exact"
accuracy = 1e-10
accuracy_knob = "rtol"
reason = "rtol"
)";

TEST(ToleranceReader, ReadsEveryFieldOfARule) {
  const ToleranceTable table = parse_tolerance_table(kOneRule, "t.toml");
  ASSERT_EQ(table.rules().size(), 1u);
  const ToleranceRule& rule = table.rules()[0];
  EXPECT_EQ(rule.check, "frequency");
  EXPECT_EQ(rule.compare, (std::vector<std::string>{"fe", "*"}));
  EXPECT_EQ(rule.scene_pattern, "gale-*");
  EXPECT_EQ(rule.tag, "gale");
  EXPECT_EQ(rule.max, 1e-6);
  EXPECT_EQ(rule.model_parameter, "eps");
  EXPECT_EQ(rule.model_order, 2);
  EXPECT_EQ(rule.constant, 0.5);
  EXPECT_EQ(rule.strain_constant, 0.25);
  EXPECT_TRUE(rule.warn_only);
  EXPECT_EQ(rule.reason, "fe's target plus a model term");
  ASSERT_EQ(table.solvers().size(), 1u);
  const SolverAccuracy* shooting = table.solver("shooting");
  ASSERT_NE(shooting, nullptr);
  EXPECT_TRUE(shooting->exact);
  EXPECT_EQ(shooting->accuracy, 1e-10);
  EXPECT_EQ(shooting->accuracy_knob, "rtol");
  EXPECT_EQ(table.solver("fe"), nullptr);
}

TEST(ToleranceReader, RejectsEstimateFactorNamingTheKey) {
  // A tolerance that grows with a solver's self-reported estimate is no longer expressible.
  const std::string text =
      "[[tolerance]]\ncheck = \"frequency\"\ncompare = [\"fe\", \"*\"]\nmax = "
      "1e-7\nestimate_factor = 3.0\n"
      "reason = \"r\"\n";
  try {
    parse_tolerance_table(text, "t.toml");
    FAIL() << "estimate_factor must be rejected";
  } catch (const InvalidInput& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("t.toml: [tolerance#1].estimate_factor"), std::string::npos) << message;
    EXPECT_NE(message.find("self-reported error estimate"), std::string::npos) << message;
  }
}

TEST(ToleranceReader, AModelTermNeedsParameterOrderAndConstantTogether) {
  const std::string rule =
      "[[tolerance]]\ncheck = \"f\"\ncompare = [\"a\", \"b\"]\nmax = 1e-9\nreason = \"r\"\n";
  EXPECT_THROW(parse_tolerance_table(rule + "model_order = 2\nconstant = 1.0\n", "t.toml"),
               InvalidInput);
  EXPECT_THROW(
      parse_tolerance_table(
          rule + "model_parameter = \"lambda\"\nmodel_order = 2\nconstant = 1.0\n", "t.toml"),
      InvalidInput);
  EXPECT_THROW(
      parse_tolerance_table(rule + "model_parameter = \"eps\"\nconstant = 1.0\n", "t.toml"),
      ParseError);
  EXPECT_THROW(
      parse_tolerance_table(rule + "model_parameter = \"eps\"\nmodel_order = 2\nconstant = -1.0\n",
                            "t.toml"),
      InvalidInput);
  EXPECT_THROW(parse_tolerance_table(rule + "strain_constant = -0.5\n", "t.toml"), InvalidInput);
  EXPECT_NO_THROW(parse_tolerance_table(rule + "strain_constant = 0.5\n", "t.toml"));
}

TEST(ToleranceReader, RejectsMalformedSolverDeclarations) {
  const std::string head = "[[solver]]\nname = \"fe\"\nreason = \"r\"\n";
  EXPECT_THROW(parse_tolerance_table(head + "family = \"exact\"\n", "t.toml"),
               ParseError);  // no accuracy
  EXPECT_THROW(parse_tolerance_table(head + "family = \"exactish\"\naccuracy = 1e-6\n", "t.toml"),
               InvalidInput);
  EXPECT_THROW(parse_tolerance_table(head + "family = \"exact\"\naccuracy = 0.0\n", "t.toml"),
               InvalidInput);
}

TEST(ToleranceReader, BuiltinTableDeclaresEverySolverAndNoToleranceGrowsWithAnEstimate) {
  const ToleranceTable table = builtin_tolerance_table();
  for (const char* name : {"fe", "shooting", "frobenius", "asymptotic", "airy"}) {
    EXPECT_NE(table.solver(name), nullptr) << name;
  }
  EXPECT_TRUE(table.solver("shooting")->exact);
  EXPECT_FALSE(table.solver("airy")->exact);
  // Model rules carry the published order of their model: eps^2.
  const ToleranceRule* model = table.find("frequency", "asymptotic", "shooting", "any", {});
  ASSERT_NE(model, nullptr);
  EXPECT_EQ(model->model_parameter, "eps");
  EXPECT_EQ(model->model_order, 2);
}

TEST(ToleranceReader, BuiltinTableHasAReasonForEveryRule) {
  const ToleranceTable table = builtin_tolerance_table();
  ASSERT_FALSE(table.rules().empty());
  for (const auto& rule : table.rules()) EXPECT_FALSE(rule.reason.empty()) << rule.check;
  const ToleranceRule* rule = table.find("frequency", "shooting", "frobenius", "any", {});
  ASSERT_NE(rule, nullptr);
  EXPECT_EQ(rule->max, 1e-9);
  EXPECT_NE(table.find("frequency", "asymptotic", "shooting", "any", {}), nullptr);
}

TEST(ToleranceReader, BuiltinTableEqualsTheFileInTheRepository) {
  const ToleranceTable file = read_tolerance_file(std::filesystem::path(CATENA_SOURCE_DIR) /
                                                  "verification/tolerances.toml");
  const ToleranceTable builtin = builtin_tolerance_table();
  ASSERT_EQ(file.rules().size(), builtin.rules().size());
  for (std::size_t i = 0; i < file.rules().size(); ++i) {
    EXPECT_EQ(file.rules()[i].check, builtin.rules()[i].check);
    EXPECT_EQ(file.rules()[i].max, builtin.rules()[i].max);
    EXPECT_EQ(file.rules()[i].reason, builtin.rules()[i].reason);
  }
}

TEST(ToleranceReader, RejectsMalformedRules) {
  EXPECT_THROW(parse_tolerance_table("[[tolerance]]\ncheck = \"frequency\"\n", "t.toml"),
               ParseError);
  EXPECT_THROW(
      parse_tolerance_table(
          "[[tolerance]]\ncheck = \"f\"\ncompare = [\"a\", \"b\"]\nmax = -1.0\nreason = \"r\"\n",
          "t.toml"),
      InvalidInput);
  EXPECT_THROW(
      parse_tolerance_table(
          "[[tolerance]]\ncheck = \"f\"\ncompare = [\"a\"]\nmax = 1.0\nreason = \"r\"\n", "t.toml"),
      ParseError);
  EXPECT_THROW(parse_tolerance_table("[[tolerance]]\ncheck = \"f\"\ncompare = [\"a\", \"b\"]\nmax "
                                     "= 1.0\nreason = \"r\"\nbeyond = \"maybe\"\n",
                                     "t.toml"),
               InvalidInput);
  EXPECT_THROW(parse_tolerance_table("tolerances = 1\n", "t.toml"), ParseError);
  EXPECT_THROW(parse_tolerance_table("[[tolerance\n", "t.toml"), ParseError);
  try {
    parse_tolerance_table(
        "[[tolerance]]\ncheck = \"f\"\ncompare = [\"a\", \"b\"]\nmax = 1.0\nreason = \"r\"\nfoo = "
        "1\n",
        "t.toml");
    FAIL() << "an unknown key must be rejected";
  } catch (const ParseError& error) {
    EXPECT_NE(std::string(error.what()).find("t.toml: [tolerance#1].foo"), std::string::npos)
        << error.what();
  }
}

TEST(ToleranceReader, MissingFileIsAParseErrorNamingIt) {
  try {
    read_tolerance_file("/nonexistent/tolerances.toml");
    FAIL() << "a missing file must throw";
  } catch (const ParseError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/tolerances.toml"), std::string::npos);
  }
}

// An empty --tolerances file used to pass reading and stop the run with
// "SceneRunOptions::tolerances is empty while checks are asked", a message for programmers.
TEST(ToleranceReader, AFileWithoutRulesIsRefusedNamingTheFile) {
  for (const char* text : {"", "# nothing yet\n",
                           "[[solver]]\nname = \"fe\"\nfamily = \"exact\"\naccuracy = 1e-6\n"
                           "reason = \"r\"\n"}) {
    try {
      parse_tolerance_table(text, "mine.toml");
      ADD_FAILURE() << "accepted a table without rules: '" << text << "'";
    } catch (const ParseError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("mine.toml: no [[tolerance]] tables"), std::string::npos) << message;
      EXPECT_EQ(message.find("SceneRunOptions"), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace catena
