// SPDX-License-Identifier: MIT
// Roots of the Airy boundary determinant: scan in kL, sign changes and |det| minima, TOMS 748.
#include "solvers/airy/airy_root_scan.hpp"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>

#include "solvers/airy/airy_boundary_system.hpp"

namespace catena::internal {
namespace {

// One sample of the scan: det at kL.
struct Sample {
  double kl = 0.0;
  double det = 0.0;
};

bool same_sign(double a, double b) { return (a > 0.0) == (b > 0.0); }

// The scan's state: determinant calls are counted, roots collected into `scan`.
class RootScanner {
 public:
  RootScanner(const AiryModel& model,
              const DimensionlessGroups& groups,
              int tolerance_bits,
              AiryRootScan& scan)
      : model_(model), groups_(groups), tolerance_(tolerance_bits), scan_(scan) {}

  double det(double kl) {
    ++scan_.evaluations;
    return airy_determinant_at(model_, groups_, kl);
  }

  // What lies between the last samples: a zero, a sign change, or (at a grid minimum of |det|)
  // perhaps a pair of close roots. `before` is null for the first step.
  void examine(const Sample* before, const Sample& previous, const Sample& current) {
    if (current.det == 0.0) {
      scan_.roots.push_back(current.kl);
      ++scan_.sign_changes;
    } else if (previous.det != 0.0 && !same_sign(current.det, previous.det)) {
      refine(previous, current);
      ++scan_.sign_changes;
    } else if (before && before->det != 0.0 && same_sign(before->det, previous.det) &&
               std::abs(previous.det) < std::abs(before->det) &&
               std::abs(previous.det) < std::abs(current.det)) {
      search_pair(*before, previous, current);
    }
  }

 private:
  // The root between two samples of opposite sign, by TOMS 748.
  void refine(const Sample& a, const Sample& b) {
    boost::uintmax_t iterations = 100;
    const auto bracket = boost::math::tools::toms748_solve(
        [this](double kl) { return det(kl); }, a.kl, b.kl, a.det, b.det, tolerance_, iterations);
    scan_.roots.push_back(0.5 * (bracket.first + bracket.second));
  }

  // |det| has a grid minimum without a sign change: Brent's minimum of sign * det on
  // [before, current]; where it crosses zero, the two roots on either side of it.
  void search_pair(const Sample& before, const Sample& previous, const Sample& current) {
    const double sign = previous.det > 0.0 ? 1.0 : -1.0;
    boost::uintmax_t iterations = 80;
    const auto minimum = boost::math::tools::brent_find_minima(
        [&](double x) { return sign * det(x); }, before.kl, current.kl, 40, iterations);
    if (minimum.second < 0.0) {
      const Sample lowest{minimum.first, sign * minimum.second};
      refine(before, lowest);
      refine(lowest, current);
      ++scan_.pairs_from_minima;
    }
  }

  const AiryModel& model_;
  const DimensionlessGroups& groups_;
  boost::math::tools::eps_tolerance<double> tolerance_;
  AiryRootScan& scan_;
};

}  // namespace

double spurious_root_cutoff_k_l(const AiryModel& model,
                                const StaticSolution& statics,
                                const DimensionlessGroups& groups,
                                double cutoff_fraction) {
  const double L = model.length;
  const double V_A = statics.vertical_force_n(0.0);
  const double V_B = statics.vertical_force_n(L);
  // The smallest tension is H where the cable has a horizontal tangent inside, else at an end.
  const double t_min = (V_A <= 0.0 && V_B >= 0.0)
                           ? statics.horizontal_force_n()
                           : std::min(statics.tension_n(0.0), statics.tension_n(L));
  const double stiffness_min = t_min / (1.0 + t_min * model.inverse_ea);
  return cutoff_fraction * kPi * std::sqrt(stiffness_min / groups.t0_n);
}

AiryRootScan scan_airy_roots(const AiryModel& model,
                             const DimensionlessGroups& groups,
                             const StaticSolution& statics,
                             int count,
                             const AirySolverOptions& options,
                             WorkMeter* meter) {
  // A step costs one determinant (microseconds): the budget is checked once per chunk of steps.
  constexpr long kStepsPerCheck = 1000;
  AiryRootScan scan;
  scan.cutoff_kl = spurious_root_cutoff_k_l(model, statics, groups, options.cutoff_fraction);
  const double limit_over_pi =
      options.max_k_l_over_pi > 0.0 ? options.max_k_l_over_pi : 2.0 * count + 20.0;
  scan.limit_kl = limit_over_pi * kPi;
  const double step = options.scan_step_k_l_over_pi * kPi;
  RootScanner scanner(model, groups, options.tolerance_bits, scan);
  Sample before;  // two samples back (valid when have_before)
  bool have_before = false;
  Sample previous{scan.cutoff_kl, scanner.det(scan.cutoff_kl)};
  long steps = 0;
  for (double kl = previous.kl + step;
       kl <= scan.limit_kl + 0.5 * step && static_cast<int>(scan.roots.size()) < count;
       kl += step) {
    const Sample current{kl, scanner.det(kl)};
    scanner.examine(have_before ? &before : nullptr, previous, current);
    before = previous;
    have_before = true;
    previous = current;
    if (++steps % kStepsPerCheck == 0 && meter &&
        meter->stop_after(static_cast<long>(scan.roots.size())))
      break;
  }
  std::sort(scan.roots.begin(), scan.roots.end());
  if (static_cast<int>(scan.roots.size()) > count)
    scan.roots.resize(static_cast<std::size_t>(count));
  return scan;
}

}  // namespace catena::internal
