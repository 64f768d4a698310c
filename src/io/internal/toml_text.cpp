// SPDX-License-Identifier: MIT
#include "io/internal/toml_text.hpp"

#include <fmt/format.h>

#include "catena/io/file_access.hpp"

namespace catena::internal {
namespace {

bool is_control(unsigned char c) { return c < 0x20 || c == 0x7F; }

}  // namespace

std::string toml_string(const std::string& text) {
  // path_text spells each invalid UTF-8 byte as \xNN and keeps valid text as it is.
  const std::string valid = path_text(std::filesystem::path(text));
  std::string out = "\"";
  for (const char c : valid) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (is_control(byte)) {
      out += fmt::format("\\u{:04X}", byte);
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string toml_comment_text(const std::string& text) {
  const std::string valid = path_text(std::filesystem::path(text));
  std::string out;
  for (const char c : valid) {
    const auto byte = static_cast<unsigned char>(c);
    if (is_control(byte) && c != '\t' && c != '\n') {
      out += fmt::format("\\x{:02X}", byte);
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace catena::internal
