// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The model order of a free decay from the singular values of its Hankel matrix
/// (docs/explanation/methods/identification.md, "Model order").

#include <vector>

#include "catena/core/types.hpp"

namespace catena::internal {

/// The number of singular values above the noise floor: those larger than
/// 2 (1 + sqrt(cols / rows))^2 times the median of the trailing half (the noise's, for white
/// noise), and larger than 1e-12 of the largest (rounding). At most `cap` (> 0) and cols / 3.
int choose_model_order(const std::vector<double>& singular_values, Index rows, Index cols, int cap);

/// The noise floor used by choose_model_order(): the threshold a signal singular value exceeds.
double noise_threshold(const std::vector<double>& singular_values, Index rows, Index cols);

}  // namespace catena::internal
