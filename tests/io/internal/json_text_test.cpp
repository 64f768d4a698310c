// SPDX-License-Identifier: MIT
// The one point where JSON documents become text (io/internal/json_text.hpp): any string, from any
// file, comes out as valid UTF-8. nlohmann::json's dump threw on a 0xFF byte in a scene's error
// message, and `verify` lost its whole report.json (exit 3).
#include "io/internal/json_text.hpp"

#include <gtest/gtest.h>

#include <string>

#include "io/internal/json_records.hpp"
#include "io/internal/utf8_text.hpp"

namespace catena::internal {
namespace {

TEST(Utf8Text, EscapesInvalidBytesAndKeepsValidText) {
  EXPECT_EQ(utf8_text("caténaire"), "caténaire");
  EXPECT_EQ(utf8_text(std::string("a\xFF"
                                  "b")),
            "a\\xFFb");
  EXPECT_EQ(utf8_text(std::string("\xFF\xFEx\0", 4)), std::string("\\xFF\\xFEx\0", 10));
  EXPECT_TRUE(is_utf8("plain"));
  EXPECT_FALSE(is_utf8(std::string("\xC0\xAF")));  // an overlong '/'
}

TEST(JsonText, EveryStringAndKeyComesOutValid) {
  const std::string bad = "name \xFF in \xC3";
  nlohmann::json document = {{"error", bad},
                             {bad, {{"nested", nlohmann::json::array({bad, 1.5, nullptr})}}},
                             {"number", 2}};
  EXPECT_THROW(static_cast<void>(document.dump()), nlohmann::json::type_error);  // the defect
  for (const std::string& text :
       {json_text(document), json_text(document, 2), dump_records(document, 1)}) {
    const nlohmann::json back = nlohmann::json::parse(text);  // valid JSON, valid UTF-8
    EXPECT_EQ(back["error"], "name \\xFF in \\xC3");
    EXPECT_EQ(back["name \\xFF in \\xC3"]["nested"][0], "name \\xFF in \\xC3");
    EXPECT_EQ(back["name \\xFF in \\xC3"]["nested"][1], 1.5);
    EXPECT_EQ(back["number"], 2);
  }
}

}  // namespace
}  // namespace catena::internal
