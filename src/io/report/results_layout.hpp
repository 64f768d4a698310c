// SPDX-License-Identifier: MIT
#pragma once
// The layout of a results JSON that `catena report` reads (issue 32, item 9): checked once, before
// anything is written, so that a file that is JSON but not what `catena verify` writes is refused
// naming the first place that differs, instead of failing half-way (nlohmann's const operator[]
// on a missing key is undefined behaviour, not an exception).

#include <string>

#include "io/report/report_data.hpp"

namespace catena::internal {

/// ParseError naming `file` and the JSON path (e.g. scenes[3].solvers.fe.summary) where the
/// document is not in the layout the report reads: the keys it reads without asking must be
/// there, with the type it reads them as. Checks are read as records (expand_check_tables first).
void check_results_layout(const json& document, const std::string& file);

}  // namespace catena::internal
