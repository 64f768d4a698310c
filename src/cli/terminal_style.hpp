// SPDX-License-Identifier: MIT
#pragma once
// Whether `catena` may colour its text, and the colouring of a verdict: colour only on a
// terminal, never in a pipe or a file, and never when the user or the terminal says no
// (NO_COLOR, https://no-color.org; TERM=dumb).

#include <cstdio>
#include <string>

namespace catena::cli {

struct TextStyle {
  bool colour = false;
  /// `text` (already padded) marked by its verdict: FAIL red, WARN and SOURCE yellow; every other
  /// text unchanged. Padding first keeps the columns aligned (escape codes take no width).
  std::string verdict(const std::string& padded, const std::string& verdict) const;
};

/// Colour when `stream` is a terminal, NO_COLOR is unset or empty and TERM is set and not "dumb".
TextStyle style_for(std::FILE* stream);

}  // namespace catena::cli
