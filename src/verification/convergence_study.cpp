// SPDX-License-Identifier: MIT
// The convergence study of one mode of another program (docs/how-to/check.md, "Convergence study"):
// values f_i at resolutions N_i are fitted, three at a time, by f = f_inf + C h^p with h = 1/N
// (Richardson extrapolation with unequal refinement ratios, the order found, not assumed).
#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "catena/verification/external_check.hpp"

namespace catena {
namespace {

// Successive differences below this fraction of the value are rounding, not discretisation: a code
// that gives the same frequency at every resolution has converged (or is exact).
constexpr double kRoundingLevel = 1e-12;
// Orders searched for the fit; outside [0.5, 10] the fit is not trusted (docs/how-to/check.md).
constexpr double kLowestOrder = 0.01;
constexpr double kHighestOrder = 20.0;
constexpr double kLowestTrustedOrder = 0.5;
constexpr double kHighestTrustedOrder = 10.0;

struct TripleFit {
  double order = 0.0;
  double limit = 0.0;
};

// Fits f = f_inf + C h^p through three points (coarse to fine). With h scaled by the finest h
// (x_i = N_3 / N_i >= 1), the ratio of successive differences is
//   (f2 - f1) / (f3 - f2) = (x1^p - x2^p) / (x2^p - 1),
// increasing in p; p is found by bisection. nullopt (with `why`) when the differences change sign
// or no order in [kLowestOrder, kHighestOrder] fits.
std::optional<TripleFit> fit_triple(const double* n, const double* f, std::string& why) {
  const double d1 = f[1] - f[0];
  const double d2 = f[2] - f[1];
  if (!(d1 * d2 > 0.0)) {
    why = "not monotone: the differences change sign";
    return std::nullopt;
  }
  const double ratio = d1 / d2;
  const double x1 = n[2] / n[0];
  const double x2 = n[2] / n[1];
  auto g = [&](double p) { return (std::pow(x1, p) - std::pow(x2, p)) / (std::pow(x2, p) - 1.0); };
  double low = kLowestOrder;
  double high = kHighestOrder;
  if (ratio < g(low) || ratio > g(high)) {
    why = fmt::format("no order in [{}, {}] fits the differences (ratio {:.6g})", low, high, ratio);
    return std::nullopt;
  }
  for (int i = 0; i < 200 && high - low > 1e-14 * high; ++i) {
    const double mid = 0.5 * (low + high);
    (g(mid) < ratio ? low : high) = mid;
  }
  const double p = 0.5 * (low + high);
  const double c = d2 / (1.0 - std::pow(x2, p));  // f3 - f2 = C (1 - x2^p) in scaled h
  return TripleFit{p, f[2] - c};
}

bool differences_at_rounding(const std::vector<double>& values) {
  const std::size_t n = values.size();
  for (std::size_t i = n - 3; i + 1 < n; ++i) {
    if (std::abs(values[i + 1] - values[i]) > kRoundingLevel * std::abs(values[n - 1]))
      return false;
  }
  return true;
}

// Four or more resolutions: the triple before the finest confirms the order and bounds the
// uncertainty of the limit.
void confirm_with_coarser_triple(const std::vector<double>& n,
                                 const std::vector<double>& f,
                                 const ExternalCheckOptions& options,
                                 ConvergenceStudy& study) {
  const std::size_t k = n.size() - 4;
  std::string why;
  const auto coarse = fit_triple(&n[k], &f[k], why);
  if (!coarse) {
    study.trustworthy = false;
    study.note = "the three resolutions before the finest: " + why;
    return;
  }
  study.coarser_order = coarse->order;
  study.limit_uncertainty_rad_s = std::abs(*study.limit_omega_rad_s - coarse->limit);
  const double p = *study.observed_order;
  if (std::abs(coarse->order - p) > options.order_stability * p) {
    study.trustworthy = false;
    study.note = fmt::format(
        "order not stable: {:.3f} from the finest three resolutions, {:.3f} from "
        "the three before (allowed relative difference {})",
        p, coarse->order, options.order_stability);
    return;
  }
  study.note =
      fmt::format("order {:.3f} confirmed by the coarser triple ({:.3f})", p, coarse->order);
}

}  // namespace

ConvergenceStudy study_convergence(const std::vector<double>& resolutions,
                                   const std::vector<double>& values,
                                   double reference,
                                   const ExternalCheckOptions& options) {
  ConvergenceStudy study;
  const std::size_t n = values.size();
  if (n < 3 || resolutions.size() != n) {
    study.note = "fewer than three resolutions";
    return study;
  }
  if (differences_at_rounding(values)) {
    study.trustworthy = true;
    study.note = "the finest three values agree to rounding: the finest is the limit";
    study.limit_omega_rad_s = values.back();
    study.limit_uncertainty_rad_s = 0.0;
  } else {
    std::string why;
    const auto fine = fit_triple(&resolutions[n - 3], &values[n - 3], why);
    if (!fine) {
      study.note = "the finest three resolutions: " + why;
      return study;
    }
    study.observed_order = fine->order;
    study.limit_omega_rad_s = fine->limit;
    study.trustworthy = fine->order >= kLowestTrustedOrder && fine->order <= kHighestTrustedOrder;
    if (!study.trustworthy) {
      study.note = fmt::format("observed order {:.3f} outside [{}, {}]", fine->order,
                               kLowestTrustedOrder, kHighestTrustedOrder);
    } else if (n >= 4) {
      confirm_with_coarser_triple(resolutions, values, options, study);
    } else {
      study.limit_uncertainty_rad_s = std::abs(fine->limit - values.back());
      study.note =
          "three resolutions: order not confirmed by a fourth; uncertainty = the extrapolation "
          "step";
    }
  }
  study.bias_relative = (*study.limit_omega_rad_s - reference) / reference;
  return study;
}

}  // namespace catena
