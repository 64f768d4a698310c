// SPDX-License-Identifier: MIT
#pragma once
// A scene's checks in report.json as one table: the field names once, then one row per check
// (docs/reference/json-layout.md). The suite has about 25,000 checks; their eleven key names,
// repeated in every record, were a fifth of the file.

#include <nlohmann/json.hpp>

namespace catena::internal {

/// The check records `records` (an array of objects with the check fields) as
/// {"fields": [...], "rows": [[...], ...]}.
nlohmann::json check_table(const nlohmann::json& records);

/// Every scene's check table in `document` back into an array of records, in place (readers of
/// report.json work on records). A document whose checks are already records is left as it is.
void expand_check_tables(nlohmann::json& document);

}  // namespace catena::internal
