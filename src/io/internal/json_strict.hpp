// SPDX-License-Identifier: MIT
#pragma once
// JSON from a file Catena did not write (or may not have: `catena check` results, `report --from`)
// parsed strictly: nlohmann keeps the last of two equal keys silently, and the report's code walks
// the tree recursively, so a duplicate key and a nesting deeper than any file Catena reads are
// refused while parsing (issue 32).

#include <nlohmann/json.hpp>
#include <string>

namespace catena::internal {

/// `text` parsed. InvalidInput naming `file` for text that is not JSON (with the byte where it
/// stops), an object or array nested deeper than `max_depth`, or a key given twice in one object
/// (naming the key).
nlohmann::json parse_json_strict(const std::string& text, const std::string& file, int max_depth);

}  // namespace catena::internal
