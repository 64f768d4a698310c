// SPDX-License-Identifier: MIT
#pragma once
// Text from another program's file (a MoorDyn deck's names, its file name) written into a TOML
// scene: TOML text must be valid UTF-8 and a basic string must escape '"', '\' and control
// characters, so every such string goes through these two writers (issue 32, item 3).

#include <string>

namespace catena::internal {

/// `text` as a TOML basic string, quotes included: '"' and '\' escaped, control characters as
/// \uXXXX, and each byte that is not part of valid UTF-8 spelled out as the four characters \xNN
/// (so the scene reads back, and the reader sees which byte it was).
std::string toml_string(const std::string& text);

/// `text` made safe inside TOML comments: invalid UTF-8 bytes and control characters other than
/// tab and line feed spelled out as \xNN. The caller starts each line with '#'.
std::string toml_comment_text(const std::string& text);

}  // namespace catena::internal
