// SPDX-License-Identifier: MIT
// Mode pairing between two solvers: see mode_pairing.hpp.
#include "verification/internal/mode_pairing.hpp"

#include <algorithm>
#include <complex>
#include <limits>

namespace catena::internal {
namespace {

// The index of the mode of `modes` whose root is nearest `lambda` (the first on a tie).
std::size_t nearest(const std::vector<Mode>& modes, std::complex<double> lambda) {
  std::size_t best = 0;
  double distance = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < modes.size(); ++j) {
    const double d = std::abs(mode_root(modes[j]) - lambda);
    if (d < distance) {
      distance = d;
      best = j;
    }
  }
  return best;
}

}  // namespace

std::complex<double> mode_root(const Mode& mode) {
  return {-mode.decay_rate_1_s, mode.omega_rad_s};
}

ModePairs pair_modes(const ModalResult& a, const ModalResult& b, bool damped) {
  ModePairs out;
  if (!damped) {
    for (std::size_t i = 0; i < std::min(a.modes.size(), b.modes.size()); ++i)
      out.pairs.emplace_back(i, i);
    return out;
  }
  if (a.modes.empty() || b.modes.empty()) {
    for (std::size_t i = 0; i < a.modes.size(); ++i) out.only_a.push_back(i);
    for (std::size_t j = 0; j < b.modes.size(); ++j) out.only_b.push_back(j);
    return out;
  }
  std::vector<bool> paired_b(b.modes.size(), false);
  for (std::size_t i = 0; i < a.modes.size(); ++i) {
    const std::size_t j = nearest(b.modes, mode_root(a.modes[i]));
    if (nearest(a.modes, mode_root(b.modes[j])) == i) {
      out.pairs.emplace_back(i, j);
      paired_b[j] = true;
    } else {
      out.only_a.push_back(i);
    }
  }
  for (std::size_t j = 0; j < b.modes.size(); ++j)
    if (!paired_b[j]) out.only_b.push_back(j);
  return out;
}

}  // namespace catena::internal
