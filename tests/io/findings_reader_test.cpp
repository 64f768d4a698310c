// SPDX-License-Identifier: MIT
// Reading the reviewed findings: the built-in file parses, and an entry must have exactly its
// seven keys.
#include "catena/io/findings_reader.hpp"

#include <gtest/gtest.h>

#include "catena/core/error.hpp"

namespace catena {
namespace {

const std::string kFinding = R"(
[[finding]]
scene = "gale-x"
quantity = "inplane_frequency"
mode = 2
solver = "frobenius"
printed = 1.25
ours = 1.2345
diagnosis = "a misprint"
)";

TEST(FindingsReader, ReadsEveryField) {
  const FindingsTable table = parse_findings_table(kFinding, "f.toml");
  ASSERT_EQ(table.findings().size(), 1u);
  const Finding& f = table.findings()[0];
  EXPECT_EQ(f.scene, "gale-x");
  EXPECT_EQ(f.quantity, "inplane_frequency");
  EXPECT_EQ(f.mode, 2);
  EXPECT_EQ(f.solver, "frobenius");
  EXPECT_EQ(f.printed, 1.25);
  EXPECT_EQ(f.ours, 1.2345);
  EXPECT_EQ(f.diagnosis, "a misprint");
}

TEST(FindingsReader, BuiltinFindingsHaveADiagnosisEach) {
  const FindingsTable table = builtin_findings_table();
  ASSERT_FALSE(table.findings().empty());
  for (const auto& f : table.findings()) EXPECT_FALSE(f.diagnosis.empty()) << f.scene;
}

TEST(FindingsReader, RejectsMissingUnknownAndMistypedKeys) {
  EXPECT_THROW(parse_findings_table(kFinding + "extra = 1\n", "f.toml"), ParseError);
  EXPECT_THROW(parse_findings_table("[[finding]]\nscene = \"x\"\n", "f.toml"), ParseError);
  std::string mistyped = kFinding;
  mistyped.replace(mistyped.find("mode = 2"), 8, "mode = \"two\"");
  EXPECT_THROW(parse_findings_table(mistyped, "f.toml"), ParseError);
  EXPECT_THROW(parse_findings_table("finding = 3\n", "f.toml"), ParseError);
  EXPECT_THROW(read_findings_file("/nonexistent/findings.toml"), ParseError);
}

}  // namespace
}  // namespace catena
