// SPDX-License-Identifier: MIT
#pragma once
// The one sanitiser for text that reaches a message or a JSON document: file names, scene text
// quoted in an error, a MoorDyn deck's names. Any byte sequence becomes valid UTF-8, so a file in
// another encoding (UTF-16, Latin-1, a stray 0xFF) can be named and reported, never fail the write.

#include <string>
#include <string_view>

namespace catena::internal {

/// `bytes` as valid UTF-8: each byte that does not start a valid sequence (RFC 3629: no overlong
/// forms, surrogates or code points above U+10FFFF) is written as the four characters \xNN; valid
/// sequences are kept as they are.
std::string utf8_text(std::string_view bytes);

/// True when `bytes` is valid UTF-8 (utf8_text would return it unchanged).
bool is_utf8(std::string_view bytes);

}  // namespace catena::internal
