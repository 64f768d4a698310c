// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Which modes of two solvers' results in one plane are compared (docs/reference/verdicts.md,
/// "Damped scenes"). Undamped: by index, which the counted spectra (Sylvester inertia, conjugate
/// points, Sturm) make the same mode. Damped: by the root lambda = -delta + i omega_d, each mode
/// with the other's mode nearest in the complex plane when that one's nearest is it in turn
/// (mutual): a mode one solver has and the other does not reach (a heavily damped root of a
/// seabed dashpot outside the other's counted region, or a mode beyond the other's top) stays
/// unpaired instead of shifting every later pair.

#include <complex>
#include <cstddef>
#include <utility>
#include <vector>

#include "catena/solvers/modal_result.hpp"

namespace catena::internal {

struct ModePairs {
  /// Indices into a.modes and b.modes, ascending in a.
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  /// Damped only: the modes of a (of b) without a partner (empty when undamped).
  std::vector<std::size_t> only_a;
  std::vector<std::size_t> only_b;
};

/// The pairs of a and b (header): by index when `damped` is false, by mutual nearest lambda
/// otherwise.
ModePairs pair_modes(const ModalResult& a, const ModalResult& b, bool damped);

/// The root lambda = -delta + i omega_d of a mode.
std::complex<double> mode_root(const Mode& mode);

}  // namespace catena::internal
