// SPDX-License-Identifier: MIT
#pragma once
// `catena solve --units`: the unit of the frequencies in its tables. Each is a field every solver
// already fills in a Mode (docs/reference/json-layout.md), so the table shows the JSON's values.

#include <optional>
#include <string>

#include "catena/solvers/modal_result.hpp"
#include "catena/statics/dimensionless_groups.hpp"

namespace catena::cli {

// The library's FrequencyUnit (catena/statics/dimensionless_groups.hpp): rad/s, Hz, kL/pi with
// c = sqrt(T0 / (m + ma)), and Gale's omega / sqrt(g/a) (uniform cables only).

/// The names --units accepts, for its help and its error: "rad/s, hz, kl-pi, gale".
std::string frequency_unit_names();
/// Reads a --units value (case-insensitive; "Hz", "kL/pi" also accepted); InvalidInput naming
/// --units and the choices otherwise.
FrequencyUnit parse_frequency_unit(const std::string& text);
/// The column header's unit: "rad/s", "Hz", "kL/pi", "w/sqrt(g/a)".
std::string unit_label(FrequencyUnit unit);
/// The mode's frequency in `unit`; nullopt when the mode has none (Gale's ratio of a line that is
/// not one uniform cable).
std::optional<double> in_unit(const Mode& mode, FrequencyUnit unit);

}  // namespace catena::cli
