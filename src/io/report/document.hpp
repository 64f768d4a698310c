// SPDX-License-Identifier: MIT
#pragma once
// A tiny document model of the report, rendered twice: Markdown for people reading diffs, HTML
// (self-contained, figures embedded) for browsers.

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace catena::internal {

struct Heading {
  int level;
  std::string text;
  std::string anchor;
};
struct Paragraph {
  std::string text;
};
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::string css_class;
};
struct Image {
  std::filesystem::path file;
  std::string caption;
};
using Block = std::variant<Heading, Paragraph, Table, Image>;
using Document = std::vector<Block>;

/// Adds `table`, or the paragraph "None." when it has no rows.
void add_table_or_none(Document& document, Table table);

/// Markdown; image links relative to `base` (the directory report.md is written to).
std::string render_markdown(const Document& document, const std::filesystem::path& base);
/// A self-contained HTML page (images embedded as base64 data).
std::string render_html(const Document& document, const std::string& title);

/// RFC 4648 base64 of `bytes`.
std::string base64(const std::string& bytes);
std::string html_escape(const std::string& text);

}  // namespace catena::internal
