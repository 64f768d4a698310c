// SPDX-License-Identifier: MIT
#include "cli/solve_units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "catena/core/error.hpp"
#include "core/internal/ascii_lower.hpp"

namespace catena::cli {

std::string frequency_unit_names() { return "rad/s, hz, kl-pi, gale"; }

FrequencyUnit parse_frequency_unit(const std::string& text) {
  const std::string key = internal::ascii_lower(text);
  if (key == "rad/s" || key == "rad-s" || key == "omega") return FrequencyUnit::RadPerSecond;
  if (key == "hz") return FrequencyUnit::Hertz;
  if (key == "kl-pi" || key == "kl/pi") return FrequencyUnit::KLOverPi;
  if (key == "gale") return FrequencyUnit::GaleRatio;
  throw InvalidInput(
      fmt::format("--units {}: unknown unit (choose one of {})", text, frequency_unit_names()));
}

std::string unit_label(FrequencyUnit unit) {
  // The library's unit names, with Gale's ratio spelled out for a column header.
  return unit == FrequencyUnit::GaleRatio ? "w/sqrt(g/a)" : to_string(unit);
}

std::optional<double> in_unit(const Mode& mode, FrequencyUnit unit) {
  switch (unit) {
    case FrequencyUnit::RadPerSecond:
      return mode.omega_rad_s;
    case FrequencyUnit::Hertz:
      return mode.frequency_hz;
    case FrequencyUnit::KLOverPi:
      return mode.k_l_over_pi;
    case FrequencyUnit::GaleRatio:
      return mode.gale_ratio;
  }
  return std::nullopt;
}

}  // namespace catena::cli
