// SPDX-License-Identifier: MIT
#pragma once
// The results JSON's text layout: objects one key per line, but each element of an array of
// records (a check, a mode, a forced response; not a scene, which holds records itself), each flat
// object (a summary, the groups) and each array of numbers on ONE line. Within 1% of the compact
// size (a fully indented dump of the suite is half as large again), and a diff still shows which
// check or mode changed.

#include <nlohmann/json.hpp>
#include <string>

namespace catena::internal {

/// `value` in the layout above, `indent` spaces per level.
std::string dump_records(const nlohmann::json& value, int indent);

}  // namespace catena::internal
