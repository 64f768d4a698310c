// SPDX-License-Identifier: MIT
#include "io/internal/toml_work_bounds.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "catena/core/error.hpp"

namespace catena::internal {

namespace {

// The index just past the string that opens at text[i] (a basic "..." or literal '...' string,
// either of them possibly multi-line """...""" / '''...'''); text.size() when unterminated
// (the parser then reports the syntax error). Counts the newlines it skips into `line`.
std::size_t skip_string(const std::string& text, std::size_t i, std::size_t& line) {
  const char quote = text[i];
  const bool multi_line = text.compare(i, 3, std::string(3, quote)) == 0;
  const std::size_t open = multi_line ? 3 : 1;
  for (std::size_t k = i + open; k < text.size(); ++k) {
    if (text[k] == '\n') ++line;
    if (quote == '"' && text[k] == '\\') {
      ++k;
      if (k < text.size() && text[k] == '\n') ++line;
      continue;
    }
    if (text[k] != quote || (multi_line && text.compare(k, 3, std::string(3, quote)) != 0))
      continue;
    return k + open;
  }
  return text.size();
}

// The keys, strings and inline tables of one line, checked at its end: toml11 3.x spends time
// proportional to the line's length on each of them.
struct LineTally {
  std::size_t number = 1;  // 1-based line of the text
  std::size_t begin = 0;   // index of its first character
  std::size_t slow_items = 0;
  bool blank = true;  // nothing but spaces so far: a '[' here opens a table header
};

void check_line(const LineTally& tally, std::size_t end, const std::string& origin) {
  const std::size_t length = end - tally.begin;
  if (length > kMaxTomlSlowLineLength && tally.slow_items > kMaxLongLineSlowItems) {
    throw ParseError(fmt::format(
        "{}: line {}: {} keys, strings or inline tables on a line of {} characters (the limit is "
        "{} on a line longer than {}: the TOML parser takes time proportional to the line's "
        "length for each); put them on separate lines",
        origin, tally.number, tally.slow_items, length, kMaxLongLineSlowItems,
        kMaxTomlSlowLineLength));
  }
}

}  // namespace

TomlScanCounts check_toml_work_bounds(const std::string& text, const std::string& origin) {
  TomlScanCounts counts;
  LineTally tally;
  int depth = 0;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '"' || c == '\'') {
      ++tally.slow_items;
      tally.blank = false;
      const std::size_t before = tally.number;
      i = skip_string(text, i, tally.number);
      // A multi-line string ends on another line: its length counts for neither.
      if (tally.number != before) tally.begin = text.rfind('\n', i - 1) + 1;
      continue;
    }
    if (c == '#') {
      i = std::min(text.find('\n', i), text.size());
      continue;
    }
    if (c == '\n') {
      check_line(tally, i, origin);
      tally = LineTally{tally.number + 1, i + 1, 0, true};
    }
    if (c == '=' || (c == '[' && depth == 0 && tally.blank)) ++counts.keys;
    if (c != ' ' && c != '\t' && c != '\n') tally.blank = false;
    if (c == '[' || c == '{') ++depth;
    if ((c == ']' || c == '}') && depth > 0) --depth;
    if (c == '{' || c == '=') ++tally.slow_items;
    if (c == ',' || c == '=' || c == '[' || c == '{') ++counts.items;
    if (depth > kMaxTomlNesting) {
      throw ParseError(fmt::format(
          "{}: line {}: arrays and inline tables nested deeper than {} levels (the limit)", origin,
          tally.number, kMaxTomlNesting));
    }
    if (counts.items > kMaxTomlItems) {
      throw ParseError(fmt::format(
          "{}: line {}: more than {} values, keys and tables (the limit, counting each ',', '=', "
          "'[' and '{{' outside strings and comments): a scene needs at most 100000 forcing "
          "frequencies and a few thousand other values",
          origin, tally.number, kMaxTomlItems));
    }
    if (counts.keys > kMaxTomlKeys) {
      throw ParseError(fmt::format(
          "{}: line {}: more than {} keys and table headers (the limit): a scene has a few hundred",
          origin, tally.number, kMaxTomlKeys));
    }
    counts.deepest = std::max(counts.deepest, depth);
    ++i;
  }
  check_line(tally, text.size(), origin);
  counts.lines = tally.number;
  return counts;
}

}  // namespace catena::internal
