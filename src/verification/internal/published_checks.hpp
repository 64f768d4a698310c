// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Checks against values printed in a source table, and the source-discrepancy rule
/// (docs/reference/verdicts.md, "Published values and the source-discrepancy rule").

#include "verification/internal/check_builder.hpp"

namespace catena::internal {

/// One "published" check per designated solver and printed value of the scene.
void published_checks(CheckBuilder& builder);

}  // namespace catena::internal
