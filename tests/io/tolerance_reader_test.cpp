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
estimate_factor = 3
beyond = "warn"
reason = "fe's Richardson estimate"
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
  EXPECT_EQ(rule.estimate_factor, 3.0);
  EXPECT_TRUE(rule.warn_only);
  EXPECT_EQ(rule.reason, "fe's Richardson estimate");
}

TEST(ToleranceReader, BuiltinTableHasAReasonForEveryRule) {
  const ToleranceTable table = builtin_tolerance_table();
  ASSERT_FALSE(table.rules().empty());
  for (const auto& rule : table.rules()) EXPECT_FALSE(rule.reason.empty()) << rule.check;
  const ToleranceRule* rule = table.find("frequency", "shooting", "frobenius", "any", {});
  ASSERT_NE(rule, nullptr);
  EXPECT_EQ(rule->max, 1e-8);
  EXPECT_NE(table.find("frequency", "asymptotic", "shooting", "any", {}), nullptr);
}

TEST(ToleranceReader, BuiltinTableEqualsTheFileInTheRepository) {
  const ToleranceTable file =
      read_tolerance_file(std::filesystem::path(CATENA_SOURCE_DIR) / "verification/tolerances.toml");
  const ToleranceTable builtin = builtin_tolerance_table();
  ASSERT_EQ(file.rules().size(), builtin.rules().size());
  for (std::size_t i = 0; i < file.rules().size(); ++i) {
    EXPECT_EQ(file.rules()[i].check, builtin.rules()[i].check);
    EXPECT_EQ(file.rules()[i].max, builtin.rules()[i].max);
    EXPECT_EQ(file.rules()[i].reason, builtin.rules()[i].reason);
  }
}

TEST(ToleranceReader, RejectsMalformedRules) {
  EXPECT_THROW(parse_tolerance_table("[[tolerance]]\ncheck = \"frequency\"\n", "t.toml"), ParseError);
  EXPECT_THROW(parse_tolerance_table("[[tolerance]]\ncheck = \"f\"\ncompare = [\"a\", \"b\"]\nmax = -1.0\nreason = \"r\"\n", "t.toml"),
               InvalidInput);
  EXPECT_THROW(parse_tolerance_table("[[tolerance]]\ncheck = \"f\"\ncompare = [\"a\"]\nmax = 1.0\nreason = \"r\"\n", "t.toml"),
               ParseError);
  EXPECT_THROW(parse_tolerance_table("[[tolerance]]\ncheck = \"f\"\ncompare = [\"a\", \"b\"]\nmax = 1.0\nreason = \"r\"\nbeyond = \"maybe\"\n", "t.toml"),
               InvalidInput);
  EXPECT_THROW(parse_tolerance_table("tolerances = 1\n", "t.toml"), ParseError);
  EXPECT_THROW(parse_tolerance_table("[[tolerance\n", "t.toml"), ParseError);
  try {
    parse_tolerance_table("[[tolerance]]\ncheck = \"f\"\ncompare = [\"a\", \"b\"]\nmax = 1.0\nreason = \"r\"\nfoo = 1\n", "t.toml");
    FAIL() << "an unknown key must be rejected";
  } catch (const ParseError& error) {
    EXPECT_NE(std::string(error.what()).find("t.toml: [tolerance#1].foo"), std::string::npos) << error.what();
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

}  // namespace
}  // namespace catena
