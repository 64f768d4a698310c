// SPDX-License-Identifier: MIT
// The strict TOML table reader shared by the scene, tolerance and findings readers.
#include "io/internal/toml_table_reader.hpp"

#include <gtest/gtest.h>

#include "catena/core/error.hpp"

namespace catena::internal {
namespace {

TEST(TomlTableReader, ReadsTypedValuesAndRejectsUnreadKeys) {
  const toml::value doc = parse_toml(
      "x = 1\ny = 2.5\nname = \"n\"\nflag = true\nlist = [\"a\", \"b\"]\nextra = 0\n", "t.toml");
  TableReader root(doc, "t.toml", "");
  EXPECT_EQ(root.number("x"), 1.0);
  EXPECT_EQ(root.number("y"), 2.5);
  EXPECT_EQ(root.integer("x"), 1);
  EXPECT_EQ(root.string("name"), "n");
  EXPECT_TRUE(root.boolean("flag", false));
  EXPECT_EQ(root.strings("list"), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(root.number("missing", 7.0), 7.0);
  try {
    root.finish();
    FAIL() << "extra was never read";
  } catch (const ParseError& error) {
    EXPECT_NE(std::string(error.what()).find("t.toml: extra: unknown key"), std::string::npos)
        << error.what();
  }
}

TEST(TomlTableReader, WrongTypesAndMissingKeysNameTheKey) {
  const toml::value doc = parse_toml("[t]\ns = 1\nn = \"x\"\n", "t.toml");
  TableReader root(doc, "t.toml", "");
  TableReader t = root.subtable("t");
  EXPECT_THROW(t.string("s"), ParseError);
  EXPECT_THROW(t.number("n"), ParseError);
  try {
    t.number("absent");
    FAIL();
  } catch (const ParseError& error) {
    EXPECT_NE(std::string(error.what()).find("[t].absent: missing required key"), std::string::npos)
        << error.what();
  }
  EXPECT_THROW(parse_toml("x = = 1", "bad.toml"), ParseError);
}

TEST(TomlTableReader, TableArraysAreNumbered) {
  const toml::value doc = parse_toml("[[item]]\na = 1\n[[item]]\na = 2\nb = 3\n", "t.toml");
  TableReader root(doc, "t.toml", "");
  auto items = root.table_array("item");
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[1].number("a"), 2.0);
  EXPECT_NE(items[1].where("b").find("[item#2].b"), std::string::npos);
  EXPECT_THROW(items[1].finish(), ParseError);
  EXPECT_TRUE(root.table_array("none").empty());
}

}  // namespace
}  // namespace catena::internal
