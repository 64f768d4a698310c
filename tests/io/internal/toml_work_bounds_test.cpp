// SPDX-License-Identifier: MIT
// The bounds on the TOML parser's work (issue 32, item 4): a file under the 1 MiB size limit is
// parsed, or refused by the linear pre-scan, without toml11's quadratic paths. Asserts on what
// the scan counts; the one clock in here is a hang guard, not a speed test.
#include "io/internal/toml_work_bounds.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "io/internal/toml_table_reader.hpp"

namespace catena::internal {
namespace {

// `key = [item, item, ...]` on one line, `count` items.
std::string one_line_array(const std::string& item, std::size_t count) {
  std::string text = "x = [";
  for (std::size_t i = 0; i < count; ++i) text += (i ? "," : "") + item;
  return text + "]\n";
}

std::string refusal(const std::string& text) {
  try {
    check_toml_work_bounds(text, "f.toml");
  } catch (const ParseError& error) {
    return error.what();
  }
  return "";
}

TEST(TomlWorkBounds, CountsItemsOutsideStringsAndComments) {
  const TomlScanCounts counts =
      check_toml_work_bounds("a = [1, 2, {b = 3}]  # , = [ {\ns = \"[,={\"\n", "f.toml");
  // a's '=', '[', two ',', '{', b's '=', s's '=': 7; the comment and the string count nothing.
  EXPECT_EQ(counts.items, 7u);
  EXPECT_EQ(counts.keys, 3u);  // a, b and s
  EXPECT_EQ(counts.lines, 3u);
  EXPECT_EQ(counts.deepest, 2);
}

TEST(TomlWorkBounds, TheLargestForcingArrayOnOneLinePasses) {
  // 100 000 forcing frequencies is the scene's largest array; on one line of 700 kB it holds
  // numbers only, which toml11 parses in time linear in the line.
  const std::string text = one_line_array("0.001", 100000);
  const TomlScanCounts counts = check_toml_work_bounds(text, "f.toml");
  EXPECT_EQ(counts.items, 100000u + 1u);  // 99 999 commas, '=' and '['
}

TEST(TomlWorkBounds, AFileOfTinyItemsUnderTheSizeLimitIsRefusedAtTheItemLimit) {
  // 1 MiB of "1," (524 000 items) took toml11 minutes on one line and seconds on short lines.
  const std::string text = one_line_array("1", (kMaxInputFileBytes - 8) / 2);
  ASSERT_LE(text.size(), kMaxInputFileBytes);
  const std::string message = refusal(text);
  EXPECT_NE(message.find("f.toml: line 1: more than 110000 values"), std::string::npos) << message;
}

TEST(TomlWorkBounds, ManyKeysOrTableHeadersAreRefused) {
  // 87 000 keys on their own lines fill 1 MiB and took toml11 2-4 s.
  std::string keys, headers;
  for (std::size_t i = 0; i <= kMaxTomlKeys; ++i) {
    keys += fmt::format("k{} = 1\n", i);
    headers += "[[p]]\n";
  }
  for (const std::string& text : {keys, headers}) {
    const std::string message = refusal(text);
    EXPECT_NE(message.find(
                  fmt::format("line {}: more than 10000 keys and table headers", kMaxTomlKeys + 1)),
              std::string::npos)
        << message;
  }
  EXPECT_EQ(check_toml_work_bounds(std::string(headers, 6), "f.toml").keys, kMaxTomlKeys);
}

TEST(TomlWorkBounds, ManyStringsOrInlineTablesOnALongLineAreRefused) {
  // toml11 spends time proportional to the line's length on each key, string or inline table.
  for (const std::string item : {"\"a\"", "{a=1}"}) {
    const std::string message = refusal(one_line_array(item, 300));
    EXPECT_NE(message.find("f.toml: line 1: "), std::string::npos) << message;
    EXPECT_NE(message.find("put them on separate lines"), std::string::npos) << message;
    // The same items one per line pass.
    std::string split = "x = [\n";
    for (int i = 0; i < 300; ++i) split += item + ",\n";
    EXPECT_EQ(refusal(split + "]\n"), "") << item;
  }
}

TEST(TomlWorkBounds, AFewStringsOnALongNumberLineAndLongStringsPass) {
  EXPECT_EQ(refusal("s = { omega = " + one_line_array("0.5", 400).substr(4) + "}\n"), "");
  EXPECT_EQ(refusal("s = \"" + std::string(5000, 'a') + "\"\n"), "");
  EXPECT_EQ(refusal("s = \"\"\"\n" + std::string(5000, 'a') + "\n\"\"\"\nt = [1]\n"), "");
}

// Hang guard (not a speed test): before the fix, toml11 took ~4 s for 30 000 floats on one line
// and grew with the square of the count (about 45 s for 100 000); now about a second. 30 s only
// catches a return of the quadratic path on a loaded CI machine.
TEST(TomlWorkBounds, HangGuardOneHundredThousandFloatsOnOneLine) {
  const std::string text = one_line_array("0.001", 100000);
  const auto start = std::chrono::steady_clock::now();
  const toml::value parsed = parse_toml(text, "f.toml");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(parsed.at("x").as_array().size(), 100000u);
  EXPECT_LT(seconds, 30.0);
}

}  // namespace
}  // namespace catena::internal
