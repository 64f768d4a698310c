// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Root finding of the frobenius solver (docs/explanation/methods/frobenius.md): the natural
/// frequencies of one plane as the zeros of the scaled boundary determinant
/// (frobenius_boundary.hpp).
///
///  1. Scan: a grid in Omega `scan_fraction` of the asymptotic (WKB) mode spacing apart, with the
///     series cut coarser (only signs are needed). A sign change brackets a root; a local minimum
///     of |det| without a sign change may hide a close pair and is searched by golden section.
///  2. Refinement: each bracket, confirmed by the full series, is refined by Illinois regula
///     falsi (refine_root).
///  3. A-posteriori correction: secant-Newton steps with the series cut 1e-3 finer per step and
///     in long double (quad from the third step); the last correction is the root's error
///     estimate.
/// The scan runs in long double or quad when the largest series term exceeds the sum by more than
/// 1e8 in double (1e11 in long double). The count of the roots is checked independently elsewhere
/// (frobenius_conjugate_points.hpp in plane, Sturm oscillation of the shapes out of plane).

#include <cmath>
#include <string>
#include <vector>

#include "solvers/common/work_meter.hpp"
#include "solvers/frobenius/frobenius_boundary.hpp"

namespace catena::internal {

/// The solver options that steer the root finding.
struct RootSettings {
  /// Target relative accuracy of each root.
  double tolerance = 1e-12;
  /// Scan grid as a fraction of the asymptotic mode spacing.
  double scan_fraction = 0.2;
  /// Whether the scan and the correction may use long double and quad.
  bool extended_precision = true;
};

/// One frequency (Gale's ratio Omega) with its error estimate and the precision it needed.
struct FoundRoot {
  double omega = 0.0;
  double relative_error = -1.0;
  Precision precision = Precision::Double;
  /// The last a-posteriori correction (relative).
  double precision_difference = 0.0;
  double truncation_estimate = 0.0;
};

/// The frequencies of one plane and how they were found.
struct PlaneRoots {
  std::vector<FoundRoot> roots;
  std::vector<std::string> notes;
  std::vector<std::string> warnings;
  WorkCounter work;
  int hidden_pairs_found = 0;
  int minima_checked = 0;
  Precision scan_precision = Precision::Double;
};

/// Asymptotic spacing of the modes in Omega, pi / int sqrt(mu / C) dsigma (WKB of the string with
/// tension C = sqrt(1 + sigma^2) and mass mu), by the trapezoid rule on 400 panels.
double wkb_mode_spacing(const PlaneSetup& setup);

/// The `count` lowest roots of the scaled boundary determinant of `setup` (fewer when the scan
/// reaches (3 count + 20) mode spacings first), ascending. A `meter` is told each root found and
/// may stop the refinement early (fewer roots, the lowest ones).
PlaneRoots find_frequencies(const PlaneSetup& setup,
                            int count,
                            const RootSettings& settings,
                            WorkMeter* meter = nullptr);

/// Root of f in [lo, hi] (f(lo) f(hi) < 0) by Illinois regula falsi, bisecting every fourth step
/// so that the bracket shrinks at least geometrically. Stops when hi - lo <= relative_tolerance
/// |hi| (or after 200 steps); `iterations` receives the steps taken.
template <class F>
double refine_root(F&& f,
                   double lo,
                   double hi,
                   double flo,
                   double fhi,
                   double relative_tolerance,
                   int& iterations) {
  int side = 0;
  for (iterations = 0; iterations < 200; ++iterations) {
    if (hi - lo <= relative_tolerance * std::abs(hi)) break;
    double x = (lo * fhi - hi * flo) / (fhi - flo);
    if (!(x > lo && x < hi) || iterations % 4 == 3) x = 0.5 * (lo + hi);
    const double fx = f(x);
    if (fx == 0.0) return x;
    if ((fx < 0.0) == (flo < 0.0)) {
      lo = x;
      flo = fx;
      if (side == -1) fhi *= 0.5;  // Illinois: halve the stale end so that it gets replaced
      side = -1;
    } else {
      hi = x;
      fhi = fx;
      if (side == 1) flo *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace catena::internal
