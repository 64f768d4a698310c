// SPDX-License-Identifier: MIT
#include "io/report/document.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <sstream>

namespace catena::internal {
namespace {

std::string md_cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string read_binary(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::string markdown_table(const Table& t) {
  std::string out = "|";
  for (const auto& h : t.header) out += " " + md_cell(h) + " |";
  out += "\n|";
  for (std::size_t i = 0; i < t.header.size(); ++i) out += "---|";
  out += "\n";
  for (const auto& row : t.rows) {
    out += "|";
    for (const auto& cell : row) out += " " + md_cell(cell) + " |";
    out += "\n";
  }
  return out + "\n";
}

const char* kStyle =
    "body{font-family:system-ui,sans-serif;max-width:1200px;margin:2em auto;padding:0 "
    "1em;color:#222}\n"
    "table{border-collapse:collapse;margin:0.5em 0 1.5em;font-size:0.9em}\n"
    "th,td{border:1px solid #ccc;padding:3px 8px;text-align:right}th{background:#f0f0f0}\n"
    "td:first-child,th:first-child{text-align:left}\n"
    ".PASS{color:#176117}.FAIL{color:#b00;font-weight:bold}.SOURCE{color:#a15c00;font-weight:bold}"
    "\n"
    "figure{margin:1em 0}figure img{max-width:100%;border:1px solid #ddd}\n"
    "figcaption{font-size:0.9em;color:#555}h2{border-bottom:1px solid #ccc;margin-top:2em}\n";

std::string html_table(const Table& t) {
  std::string out = "<table class=\"" + t.css_class + "\"><thead><tr>";
  for (const auto& h : t.header) out += "<th>" + html_escape(h) + "</th>";
  out += "</tr></thead><tbody>\n";
  for (const auto& row : t.rows) {
    out += "<tr>";
    for (const auto& cell : row) {
      // Verdict cells carry their verdict as a class (coloured by kStyle).
      const bool verdict =
          cell == "PASS" || cell == "FAIL" || cell == "SOURCE" || cell == "WARN" || cell == "SKIP";
      out += (verdict ? "<td class=\"" + cell + "\">" : std::string("<td>")) + html_escape(cell) +
             "</td>";
    }
    out += "</tr>\n";
  }
  return out + "</tbody></table>\n";
}

std::string html_block(const Block& block) {
  if (const auto* h = std::get_if<Heading>(&block)) {
    return fmt::format("<h{0} id=\"{2}\">{1}</h{0}>\n", h->level, html_escape(h->text),
                       html_escape(h->anchor));
  }
  if (const auto* p = std::get_if<Paragraph>(&block))
    return "<p>" + html_escape(p->text) + "</p>\n";
  if (const auto* t = std::get_if<Table>(&block)) return html_table(*t);
  const auto& img = std::get<Image>(block);
  // PNG from figures.py, SVG from the library's own plots (io/report/svg_plot.hpp).
  const char* type = img.file.extension() == ".svg" ? "image/svg+xml" : "image/png";
  return "<figure><img alt=\"" + html_escape(img.caption) + "\" src=\"data:" + type + ";base64," +
         base64(read_binary(img.file)) + "\"><figcaption>" + html_escape(img.caption) +
         "</figcaption></figure>\n";
}

}  // namespace

void add_table_or_none(Document& document, Table table) {
  // Built in place: GCC 12 warns (falsely) of an uninitialised Table when a temporary Paragraph is
  // moved into the variant.
  if (table.rows.empty()) {
    document.emplace_back(std::in_place_type<Paragraph>, "None.");
  } else {
    document.emplace_back(std::in_place_type<Table>, std::move(table));
  }
}

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  auto byte = [&](std::size_t i) {
    return static_cast<unsigned>(static_cast<std::uint8_t>(bytes[i]));
  };
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (byte(i) << 16) | (byte(i + 1) << 8) | byte(i + 2);
    out += table[v >> 18];
    out += table[(v >> 12) & 63];
    out += table[(v >> 6) & 63];
    out += table[v & 63];
  }
  if (i < bytes.size()) {
    unsigned v = byte(i) << 16;
    if (i + 1 < bytes.size()) v |= byte(i + 1) << 8;
    out += table[v >> 18];
    out += table[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string render_markdown(const Document& document, const std::filesystem::path& base) {
  std::string out;
  for (const auto& block : document) {
    if (const auto* h = std::get_if<Heading>(&block)) {
      out += std::string(static_cast<std::size_t>(h->level), '#') + " " + h->text + "\n\n";
    } else if (const auto* p = std::get_if<Paragraph>(&block)) {
      out += p->text + "\n\n";
    } else if (const auto* t = std::get_if<Table>(&block)) {
      out += markdown_table(*t);
    } else if (const auto* img = std::get_if<Image>(&block)) {
      out += fmt::format("![{}]({})\n\n*{}*\n\n", img->caption,
                         std::filesystem::relative(img->file, base).string(), img->caption);
    }
  }
  return out;
}

std::string render_html(const Document& document, const std::string& title) {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" +
                    html_escape(title) + "</title>\n<style>\n" + kStyle + "</style></head><body>\n";
  for (const auto& block : document) out += html_block(block);
  return out + "</body></html>\n";
}

}  // namespace catena::internal
