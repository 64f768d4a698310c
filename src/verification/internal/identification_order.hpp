// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The model order of a free decay from the singular values of its Hankel matrix
/// (docs/explanation/methods/identification.md, "Model order").

#include <vector>

#include "catena/core/types.hpp"

namespace catena::internal {

/// The number of singular values above the noise floor: those larger than
/// 2 (1 + sqrt(cols / rows))^2 times the noise level, and larger than 1e-12 of the largest
/// (rounding). At most `cap` (> 0) and cols / 3. The noise level is the median of the singular
/// values ranked between w cols / 2 and w cols, w = `white_fraction` in (0, 1]: the noise's own
/// when it is white over the share w of the band from 0 (a low-passed record's noise is white
/// in the pass band and fades above it: its trailing singular values are below the floor).
int choose_model_order(const std::vector<double>& singular_values,
                       Index rows,
                       Index cols,
                       int cap,
                       double white_fraction);

/// The noise floor used by choose_model_order(): the threshold a signal singular value exceeds.
double noise_threshold(const std::vector<double>& singular_values,
                       Index rows,
                       Index cols,
                       double white_fraction);

}  // namespace catena::internal
