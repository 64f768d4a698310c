// SPDX-License-Identifier: MIT
#pragma once
// Where every JSON document catena writes becomes text. nlohmann::json throws on a string that is
// not valid UTF-8 when it is dumped; a scene's error message quoting a UTF-16 file or a 0xFF byte
// then failed `verify`'s report.json and lost every scene's result. Every string (and key) goes
// through the one sanitiser, utf8_text, on its way out.

#include <nlohmann/json.hpp>
#include <string>

namespace catena::internal {

/// `document` with every string and object key made valid UTF-8 (utf8_text: invalid bytes as
/// \xNN); numbers, booleans and nulls as they are.
nlohmann::json utf8_json(const nlohmann::json& document);

/// utf8_json(document) as text: compact when `indent` < 0, else `indent` spaces per level.
std::string json_text(const nlohmann::json& document, int indent = -1);

}  // namespace catena::internal
