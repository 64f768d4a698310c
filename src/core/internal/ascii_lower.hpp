// SPDX-License-Identifier: MIT
// ASCII lower case, for names matched without regard to case in other programs' files (channel
// names, column headers, command-line words).
#pragma once

#include <cctype>
#include <string>
#include <string_view>

namespace catena::internal {

inline std::string ascii_lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace catena::internal
