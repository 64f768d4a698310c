// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Whether a static solution is the equilibrium of a problem: the check every solver entry point
/// makes on statics given to it (the driver's, docs/contributing/architecture.md, "Solver
/// skeleton"), and the Python module's `statics=` argument (docs/reference/python.md).

#include "catena/models/cable.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {

/// Throws InvalidInput unless `statics` is the equilibrium of `problem`, naming the first field
/// that differs and both values. Compared, exactly: every field of every segment (or of the
/// uniform cable: length, weight, EA, masses, added masses, damping, drag) and of every point
/// attachment, the seabed (present or not, and each field), support a (the statics' r(0)) and,
/// when the problem prescribes its end forces, H and V_A. Support b is compared through the
/// statics' own end, r(L) - r(0) against the chord, within twice the statics' closure error plus
/// rounding: within that the two problems have the same statics. The environment (gravity,
/// water density) does not enter the statics and is not compared.
void check_statics_match(const Problem& problem, const StaticSolution& statics);

}  // namespace catena
