// SPDX-License-Identifier: MIT
#include "verification/internal/identification_order.hpp"

#include <algorithm>
#include <cmath>

namespace catena::internal {

double noise_threshold(const std::vector<double>& singular_values,
                       Index rows,
                       Index cols,
                       double white_fraction) {
  // White noise alone fills a rows x cols matrix with singular values within
  // sqrt(rows) sigma (1 +- sqrt(cols / rows)) (Marchenko-Pastur); a Hankel matrix's structure
  // spreads them further: in 20 draws each of 6 shapes (40 x 21 to 11800 x 201, 1 to 3 stacked
  // channels) the largest stayed within 1.15 (1 + sqrt(c))^2 of the trailing half's median. The
  // factor 2 leaves a margin, so that noise alone yields order 0; the median of the trailing half
  // of the white part is the noise's while the signal's order is below cols / 3 (its cap).
  const auto size = static_cast<double>(singular_values.size());
  const auto last = static_cast<long>(std::clamp(white_fraction, 0.0, 1.0) * size);
  const long first = std::min(last / 2, std::max(0L, last - 1));
  std::vector<double> tail(singular_values.begin() + first,
                           singular_values.begin() + std::max(last, first + 1));
  std::nth_element(tail.begin(), tail.begin() + static_cast<long>(tail.size() / 2), tail.end());
  const double median = tail[tail.size() / 2];
  const double spread = 1.0 + std::sqrt(static_cast<double>(cols) / static_cast<double>(rows));
  const double rounding = 1e-12 * singular_values.front();
  return std::max(2.0 * spread * spread * median, rounding);
}

int choose_model_order(const std::vector<double>& singular_values,
                       Index rows,
                       Index cols,
                       int cap,
                       double white_fraction) {
  const double threshold = noise_threshold(singular_values, rows, cols, white_fraction);
  int order = 0;
  for (double s : singular_values) order += s > threshold ? 1 : 0;
  return std::min({order, cap, static_cast<int>(cols / 3)});
}

}  // namespace catena::internal
