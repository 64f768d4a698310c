// SPDX-License-Identifier: MIT
#include "cli/terminal_style.hpp"

#include <unistd.h>

#include <cstdlib>

namespace catena::cli {

std::string TextStyle::verdict(const std::string& padded, const std::string& verdict) const {
  if (!colour) return padded;
  if (verdict == "FAIL") return "\033[1;31m" + padded + "\033[0m";
  if (verdict == "WARN" || verdict == "SOURCE") return "\033[33m" + padded + "\033[0m";
  return padded;
}

TextStyle style_for(std::FILE* stream) {
  const char* no_colour = std::getenv("NO_COLOR");
  const char* term = std::getenv("TERM");
  TextStyle style;
  style.colour = isatty(fileno(stream)) && (no_colour == nullptr || *no_colour == '\0') &&
                 term != nullptr && std::string(term) != "dumb" && *term != '\0';
  return style;
}

}  // namespace catena::cli
