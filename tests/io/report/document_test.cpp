// SPDX-License-Identifier: MIT
// The report's document model rendered as Markdown and HTML.
#include "io/report/document.hpp"

#include <gtest/gtest.h>

namespace catena::internal {
namespace {

TEST(ReportDocument, Base64MatchesRfc4648Vectors) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

TEST(ReportDocument, MarkdownEscapesPipesAndHtmlEscapesMarkup) {
  Document document;
  document.push_back(Heading{2, "Results", "results"});
  document.push_back(Table{{"a|b", "verdict"}, {{"x", "FAIL"}}, "t"});
  add_table_or_none(document, Table{{"empty"}, {}, "e"});
  const std::string md = render_markdown(document, ".");
  EXPECT_NE(md.find("## Results\n"), std::string::npos) << md;
  EXPECT_NE(md.find("| a\\|b | verdict |\n|---|---|\n| x | FAIL |"), std::string::npos) << md;
  EXPECT_NE(md.find("None."), std::string::npos) << md;
  const std::string html = render_html(document, "<title>");
  EXPECT_NE(html.find("&lt;title&gt;"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"FAIL\">FAIL</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("<h2 id=\"results\">Results</h2>"), std::string::npos);
  EXPECT_EQ(html_escape("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
}

}  // namespace
}  // namespace catena::internal
