// SPDX-License-Identifier: MIT
#pragma once
// Bounds on the work of the TOML parser, checked by a linear scan of the text before toml11 sees
// it (docs/reference/scene-format.md, "Limits"). toml11 3.x recurses once per nesting level, and
// spends microseconds per item plus, for keys, strings and inline tables, time proportional to
// the length of their line (it builds error candidates that copy the line): without these bounds
// a 1 MiB file could take minutes to parse.

#include <cstddef>
#include <string>

namespace catena::internal {

/// Deepest nesting of arrays and inline tables: our deepest is 2.
inline constexpr int kMaxTomlNesting = 64;
/// Most items in one file, counting each `,`, `=`, `[` and `{` outside strings and comments:
/// 100 000 forcing frequencies (the largest array a scene accepts) plus the rest of a scene;
/// toml11 parses that many in about a second (benchmarks/results/toml-parse-time.md).
inline constexpr std::size_t kMaxTomlItems = 110000;
/// Most keys and table headers in one file (each `=`, and each `[` opening a header, outside
/// strings and comments): toml11 spends 10-40 us on each, against 5-10 us per array value; a scene
/// has a few hundred.
inline constexpr std::size_t kMaxTomlKeys = 10000;
/// Longest line that may hold more than kMaxLongLineSlowItems keys, strings or inline tables;
/// longer lines may hold arrays of numbers (which toml11 parses in time linear in the line).
inline constexpr std::size_t kMaxTomlSlowLineLength = 1000;
inline constexpr std::size_t kMaxLongLineSlowItems = 16;

/// What the scan counted (for tests and the benchmark table).
struct TomlScanCounts {
  std::size_t items = 0;
  std::size_t keys = 0;
  std::size_t lines = 0;
  int deepest = 0;
};

/// Throws ParseError naming `origin` and the line when `text` breaks one of the bounds above;
/// otherwise returns what it counted. Unterminated strings are left to the parser to report.
TomlScanCounts check_toml_work_bounds(const std::string& text, const std::string& origin);

}  // namespace catena::internal
