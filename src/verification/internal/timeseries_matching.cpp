// SPDX-License-Identifier: MIT
#include "verification/internal/timeseries_matching.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace catena::internal {
namespace {

std::size_t nearest(const std::vector<Mode>& modes, double frequency_hz) {
  std::size_t best = 0;
  for (std::size_t k = 1; k < modes.size(); ++k) {
    if (std::abs(modes[k].frequency_hz - frequency_hz) <
        std::abs(modes[best].frequency_hz - frequency_hz))
      best = k;
  }
  return best;
}

// A mode whose damping ratio is not resolved from zero (its uncertainty exceeds it) still has a
// frequency to compare, and a damping ratio to compare with Catena's within that uncertainty: an
// undamped line's decay is exactly that (issue 33: "the identified zeta is compared to 0 within its
// uncertainty"). Any other reason (no convergence, a singular fit, a frequency not resolved, a
// mode below the noise) leaves it not identifiable (IdentifiedMode::frequency_identifiable).
bool comparable(const IdentifiedMode& id) { return id.frequency_identifiable; }

// The gap from Catena's mode k to its nearest neighbour in the plane [Hz] (infinite when alone).
double neighbour_gap_hz(const std::vector<Mode>& modes, std::size_t k) {
  double gap = std::numeric_limits<double>::infinity();
  if (k > 0) gap = std::min(gap, modes[k].frequency_hz - modes[k - 1].frequency_hz);
  if (k + 1 < modes.size()) gap = std::min(gap, modes[k + 1].frequency_hz - modes[k].frequency_hz);
  return std::abs(gap);
}

void compare(const IdentifiedMode& id,
             const Mode& catena,
             double gap_hz,
             TimeSeriesModeCheck& check) {
  check.mode = catena.index;
  check.catena_frequency_hz = catena.frequency_hz;
  check.catena_damping_ratio = catena.damping_ratio;
  check.catena_frequency_error_hz = frequency_error_hz(catena);
  check.catena_damping_ratio_error = damping_ratio_error(catena);
  check.frequency_error_hz = id.frequency_hz - catena.frequency_hz;
  check.damping_ratio_error = id.damping_ratio - catena.damping_ratio;
  if (!comparable(id)) {
    check.verdict = "not identifiable";
    check.note = id.note;
    return;
  }
  // An uncertainty that reaches halfway to Catena's neighbouring mode cannot say which mode this
  // is: "agrees" would then promise nothing (a fit of noise at 3.6 +- 2.9 Hz once "agreed").
  if (2.0 * check.frequency_uncertainty_hz >= gap_hz) {
    check.verdict = "not identifiable";
    check.note = fmt::format(
        "its frequency uncertainty {:.3e} Hz reaches halfway to Catena's neighbouring mode ({:.3e} "
        "Hz away): the match is ambiguous",
        check.frequency_uncertainty_hz, gap_hz);
    return;
  }
  const double allowed_f = check.frequency_uncertainty_hz + check.catena_frequency_error_hz;
  const double allowed_zeta = check.damping_ratio_uncertainty + check.catena_damping_ratio_error;
  const bool f_ok = std::abs(check.frequency_error_hz) <= allowed_f;
  const bool zeta_ok = std::abs(check.damping_ratio_error) <= allowed_zeta;
  check.verdict = f_ok && zeta_ok ? "agrees" : "disagrees";
  check.note = fmt::format(
      "|f error| {:.3e} Hz {} U_f + Catena's {:.3e} Hz = {:.3e} Hz; |zeta error| {:.3e} {} U_zeta "
      "+ Catena's {:.2e} = {:.3e}",
      std::abs(check.frequency_error_hz), f_ok ? "<=" : ">", check.catena_frequency_error_hz,
      allowed_f, std::abs(check.damping_ratio_error), zeta_ok ? "<=" : ">",
      check.catena_damping_ratio_error, allowed_zeta);
  if (!id.note.empty()) check.note += "; " + id.note;
}

}  // namespace

std::vector<TimeSeriesModeCheck> match_modes(const Identification& identification,
                                             const DampedReference& reference,
                                             std::vector<TimeSeriesModeNotPresent>& not_present) {
  const auto& found = identification.modes;
  std::vector<TimeSeriesModeCheck> checks(found.size());
  for (std::size_t i = 0; i < found.size(); ++i) {
    TimeSeriesModeCheck& c = checks[i];
    c.plane = to_string(reference.plane);
    c.identified_frequency_hz = found[i].frequency_hz;
    c.frequency_uncertainty_hz = found[i].frequency_uncertainty_hz;
    c.identified_damping_ratio = found[i].damping_ratio;
    c.damping_ratio_uncertainty = found[i].damping_ratio_uncertainty;
    c.identified_decay_rate_1_s = found[i].decay_rate_1_s;
    c.signal_to_noise = found[i].signal_to_noise;
  }
  if (reference.modes.empty()) return checks;
  // Identifiable modes first, then by their distance to the nearest Catena mode relative to the
  // uncertainty: the mode that fits best claims its partner; a second claimant is refused.
  std::vector<std::size_t> order(found.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto misfit = [&](std::size_t i) {
    const Mode& m = reference.modes[nearest(reference.modes, found[i].frequency_hz)];
    return std::abs(m.frequency_hz - found[i].frequency_hz) /
           std::max(found[i].frequency_uncertainty_hz, 1e-300);
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (comparable(found[a]) != comparable(found[b])) return comparable(found[a]);
    return misfit(a) < misfit(b);
  });
  std::vector<int> taken_by(reference.modes.size(), -1);
  for (const std::size_t i : order) {
    const std::size_t k = nearest(reference.modes, found[i].frequency_hz);
    if (taken_by[k] >= 0) {
      checks[i].verdict = comparable(found[i]) ? "unmatched" : "not identifiable";
      checks[i].note = fmt::format(
          "Catena's nearest mode, {} {} at {:.6g} Hz, is matched to the identified mode at {:.6g} "
          "Hz: the record shows a mode Catena's linear model does not have (a harmonic of a "
          "non-linear run, the other plane leaking into the channel, or a wrong scene)",
          to_string(reference.plane), reference.modes[k].index, reference.modes[k].frequency_hz,
          found[static_cast<std::size_t>(taken_by[k])].frequency_hz);
      if (!found[i].note.empty()) checks[i].note += "; " + found[i].note;
      continue;
    }
    taken_by[k] = static_cast<int>(i);
    compare(found[i], reference.modes[k], neighbour_gap_hz(reference.modes, k), checks[i]);
  }
  // Not present: Catena's modes below the highest one a comparable mode matched.
  int highest = -1;
  for (std::size_t k = 0; k < taken_by.size(); ++k)
    if (taken_by[k] >= 0 && comparable(found[static_cast<std::size_t>(taken_by[k])]))
      highest = static_cast<int>(k);
  for (int k = 0; k < highest; ++k) {
    if (taken_by[static_cast<std::size_t>(k)] >= 0) continue;
    const Mode& m = reference.modes[static_cast<std::size_t>(k)];
    not_present.push_back({to_string(reference.plane), m.index, m.frequency_hz, m.damping_ratio});
  }
  return checks;
}

}  // namespace catena::internal
