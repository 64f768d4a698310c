// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The matrix pencil method (Hua & Sarkar 1990) on the stacked Hankel matrices of several channels
/// that share their poles (docs/explanation/methods/identification.md, "Matrix pencil").

#include <complex>
#include <vector>

#include "catena/core/types.hpp"

namespace catena::internal {

struct PencilPoles {
  std::vector<std::complex<double>>
      poles_1_s;                        // lambda = log(z) / dt, all of them (conjugates too)
  std::vector<double> singular_values;  // of the stacked Hankel matrix, descending
  int order = 0;                        // poles found (the singular values kept)
  int pencil_parameter = 0;             // L: the Hankel matrix has L + 1 columns
};

/// The poles of the channels (each of the same length >= 20, sampled every dt seconds), at most
/// `max_order` of them (0: no cap). The pencil parameter L is N / 3 (Hua & Sarkar's best for
/// noise) capped at 250, and the rows thinned to bound the cost: the least-squares refinement,
/// not the pencil, reaches the final accuracy. `white_fraction`: the share of the band, from 0,
/// where the noise is white (1 unless low-passed; see choose_model_order()).
PencilPoles matrix_pencil(const std::vector<Vector>& channels,
                          double dt,
                          int max_order,
                          double white_fraction);

}  // namespace catena::internal
