// SPDX-License-Identifier: MIT
#include "verification/internal/identification_order.hpp"

#include <algorithm>
#include <cmath>

namespace catena::internal {

double noise_threshold(const std::vector<double>& singular_values, Index rows, Index cols) {
  // White noise alone fills a rows x cols matrix with singular values within
  // sqrt(rows) sigma (1 +- sqrt(cols / rows)) (Marchenko-Pastur); a Hankel matrix's structure
  // spreads them further: in 20 draws each of 6 shapes (40 x 21 to 11800 x 201, 1 to 3 stacked
  // channels) the largest stayed within 1.15 (1 + sqrt(c))^2 of the trailing half's median. The
  // factor 2 leaves a margin, so that noise alone yields order 0; the median of the trailing half
  // is the noise's as long as the signal's order is below cols / 2 (the order is capped at cols /
  // 3).
  std::vector<double> tail(singular_values.begin() + static_cast<long>(singular_values.size() / 2),
                           singular_values.end());
  std::nth_element(tail.begin(), tail.begin() + static_cast<long>(tail.size() / 2), tail.end());
  const double median = tail[tail.size() / 2];
  const double spread = 1.0 + std::sqrt(static_cast<double>(cols) / static_cast<double>(rows));
  const double rounding = 1e-12 * singular_values.front();
  return std::max(2.0 * spread * spread * median, rounding);
}

int choose_model_order(const std::vector<double>& singular_values,
                       Index rows,
                       Index cols,
                       int cap) {
  const double threshold = noise_threshold(singular_values, rows, cols);
  int order = 0;
  for (double s : singular_values) order += s > threshold ? 1 : 0;
  return std::min({order, cap, static_cast<int>(cols / 3)});
}

}  // namespace catena::internal
