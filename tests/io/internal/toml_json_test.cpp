// SPDX-License-Identifier: MIT
// The built-in tables' JSON form (io/internal/toml_json.hpp): the TOML document rebuilt from it is
// the one toml11 parses from the file, value for value and type for type.
#include "io/internal/toml_json.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/io/findings_reader.hpp"
#include "catena/io/tolerance_reader.hpp"
#include "io/internal/builtin_tables.hpp"
#include "io/internal/toml_table_reader.hpp"

namespace catena::internal {
namespace {

std::string source_file(const std::string& relative) {
  std::ifstream in(std::string(CATENA_SOURCE_DIR) + "/" + relative);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(TomlJson, KeepsEveryTypeAndNesting) {
  const toml::value document = parse_toml(
      "i = 3\nf = 3.0\nnegative = -2.5e-300\nb = false\ns = \"quote \\\" backslash \\\\ tab \\t "
      "é\"\n"
      "list = [1, 2.5, \"x\", [true]]\n[[rule]]\nname = \"a\"\n[[rule]]\nname = \"b\"\n[t.u]\nv = "
      "1\n",
      "t.toml");
  const toml::value back = toml_from_json(json_from_toml(document));
  EXPECT_EQ(back, document);
  EXPECT_TRUE(back.at("i").is_integer());
  EXPECT_TRUE(back.at("f").is_floating());
  EXPECT_EQ(back.at("negative").as_floating(), -2.5e-300);
  EXPECT_EQ(back.at("s").as_string().str, "quote \" backslash \\ tab \t é");
  EXPECT_EQ(back.at("rule").as_array().at(1).at("name").as_string().str, "b");
}

TEST(TomlJson, ADateHasNoJsonFormAndNullNoTomlForm) {
  EXPECT_THROW(json_from_toml(parse_toml("d = 2026-11-26\n", "t.toml")), ParseError);
  EXPECT_THROW(toml_from_json(nlohmann::json::parse("{\"x\": null}")), ParseError);
}

// The embedded JSON is built from the files by the build (src/tools/embed_tables.cpp); equality
// with the files' own documents shows it is neither stale nor lossy.
TEST(TomlJson, TheBuiltInTablesAreTheFilesDocuments) {
  const std::pair<const char*, const char*> tables[] = {
      {kBuiltinTolerancesJson, "verification/tolerances.toml"},
      {kBuiltinFindingsJson, "verification/findings.toml"}};
  for (const auto& [json, file] : tables) {
    const toml::value from_file = parse_toml(source_file(file), file);
    EXPECT_EQ(toml_from_json(nlohmann::json::parse(json)), from_file) << file;
  }
}

TEST(TomlJson, TheBuiltInTablesReadAsTheFilesDo) {
  EXPECT_EQ(builtin_tolerance_table().rules().size(),
            read_tolerance_file(std::string(CATENA_SOURCE_DIR) + "/verification/tolerances.toml")
                .rules()
                .size());
  EXPECT_EQ(builtin_findings_table().findings().size(),
            read_findings_file(std::string(CATENA_SOURCE_DIR) + "/verification/findings.toml")
                .findings()
                .size());
}

}  // namespace
}  // namespace catena::internal
