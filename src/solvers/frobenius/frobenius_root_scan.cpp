// SPDX-License-Identifier: MIT
// Root finding of the frobenius solver: see frobenius_root_scan.hpp for the steps.
#include "solvers/frobenius/frobenius_root_scan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "catena/core/types.hpp"

namespace catena::internal {

namespace {

// The root finder of one plane. The scan state (the last three grid points and the brackets found)
// lives here so that the scan can be resumed when a bracket is lost in refinement.
class FrequencyFinder {
 public:
  FrequencyFinder(const PlaneSetup& setup,
                  int count,
                  const RootSettings& settings,
                  WorkMeter* meter)
      : setup_(setup),
        coarse_(setup),
        count_(count),
        settings_(settings),
        spacing_(wkb_mode_spacing(setup)),
        step_(settings.scan_fraction * spacing_),
        meter_(meter) {}

  PlaneRoots run();

 private:
  // Thrown by check_time() when the run's time is up: one determinant at max_terms in quad
  // precision takes up to seconds, and a root's bracket, widening and corrections take dozens,
  // so the budget is checked before each evaluation, not only after each root (a 60-mode Gale
  // scene ran 39 s under --time-limit 5, issue 32).
  struct TimeUp {};
  void check_time() {
    if (meter_ && meter_->expired()) throw TimeUp{};
  }
  double full(double omega) {
    check_time();
    return scaled_determinant(result_.scan_precision, setup_, omega, result_.work);
  }
  double coarse(double omega) {
    check_time();
    return scaled_determinant(result_.scan_precision, coarse_, omega, result_.work);
  }
  PlaneRoots scan_and_refine();

  void choose_scan_precision();
  void choose_coarse_series();
  void scan_more(std::size_t wanted);
  std::optional<double> hidden_crossing(double a, double b, double sign);
  void refine_bracket(std::size_t index, double rtol);
  FoundRoot corrected_root(double omega, double rtol);

  const PlaneSetup& setup_;
  PlaneSetup coarse_;
  int count_;
  RootSettings settings_;
  double spacing_;
  double step_;
  PlaneRoots result_;
  std::vector<std::pair<double, double>> brackets_;
  double x0_ = 0.0, f0_ = 0.0, x1_ = 0.0, f1_ = 0.0;
  WorkMeter* meter_;
  long scan_steps_ = 0;
};

// The scan of a few hundred modes takes seconds: once it has bracketed a root, the budget is
// checked every this many grid points (and the brackets found are refined).
constexpr long kScanStepsPerCheck = 10;

// Cancellation (largest series term / column norm) at the top of the expected range decides the
// precision of the scan: double while it leaves 8 digits, then long double, then quad. A
// determinant that overflows double (high Omega on a shallow cable: the series terms grow like
// Omega^n before they decay) needs long double's range at least.
void FrequencyFinder::choose_scan_precision() {
  const double top = (count_ + 1.0) * spacing_;
  WorkCounter probe;
  const bool overflow = !std::isfinite(scaled_determinant(Precision::Double, setup_, top, probe));
  result_.work.determinant_evaluations += probe.determinant_evaluations;
  result_.work.cancellation = probe.cancellation;
  Precision precision = Precision::Double;
  if ((overflow || probe.cancellation * std::numeric_limits<double>::epsilon() > 1e-8) &&
      settings_.extended_precision)
    precision = probe.cancellation * std::numeric_limits<long double>::epsilon() > 1e-8
                    ? Precision::Quad
                    : Precision::LongDouble;
  result_.notes.push_back(fmt::format(
      "cancellation (largest series term / |sum|) at Omega = {:g}: {:g}{}; root scan in {}", top,
      probe.cancellation, overflow ? " (det not finite in double)" : "",
      precision_name(precision)));
  result_.scan_precision = precision;
}

// The scan needs only the sign of det away from its roots: series cut at 1e-9 (fewer terms),
// tightened by the cancellation factor so that the cut stays 1e-4 below the sums. The coarse
// series must reproduce the determinant itself (which can be far smaller than the column norms
// when the basis is nearly dependent): checked at the top of the range, else the scan uses the
// full series.
void FrequencyFinder::choose_coarse_series() {
  coarse_.settings.term_tolerance =
      std::max(setup_.settings.term_tolerance,
               std::min(1e-9, 1e-4 / std::max(1.0, result_.work.cancellation)));
  const double top = (count_ + 1.0) * spacing_;
  const double full_det = full(top);
  const double cut_det = coarse(top);
  if (std::abs(cut_det - full_det) > 1e-2 * std::abs(full_det)) {
    coarse_ = setup_;
    result_.notes.push_back(
        fmt::format("coarse-series scan rejected (det differs by {:g} relative at the top of the "
                    "range): scan with the full series",
                    std::abs(cut_det - full_det) / std::max(std::abs(full_det), 1e-300)));
  }
}

// A sign change inside [a, b] of the coarse determinant (of sign `sign` at both ends and in the
// middle), searched by golden section on the signed value towards its minimum.
std::optional<double> FrequencyFinder::hidden_crossing(double a, double b, double sign) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = sign * coarse(c);
  double fd = sign * coarse(d);
  for (int it = 0; it < 60; ++it) {
    if (fc < 0.0) return c;
    if (fd < 0.0) return d;
    if (fc < fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - g * (b - a);
      fc = sign * coarse(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + g * (b - a);
      fd = sign * coarse(d);
    }
    if (b - a < 1e-14 * b) break;
  }
  return std::nullopt;
}

// Advances the grid until `wanted` brackets are known or the scan limit is reached.
void FrequencyFinder::scan_more(std::size_t wanted) {
  const double limit = (3.0 * count_ + 20.0) * spacing_;
  while (brackets_.size() < wanted && x1_ < limit) {
    if (meter_ && !brackets_.empty() && ++scan_steps_ % kScanStepsPerCheck == 0 &&
        meter_->stop_after(static_cast<long>(result_.roots.size())))
      break;
    const double x2 = x1_ + step_, f2 = coarse(x2);
    if ((f0_ < 0.0) != (f1_ < 0.0)) brackets_.emplace_back(x0_, x1_);
    // A local minimum of |det| without a sign change on either side may hide two close roots.
    const bool same_sign = (f0_ < 0.0) == (f1_ < 0.0) && (f1_ < 0.0) == (f2 < 0.0);
    if (same_sign && std::abs(f1_) < std::abs(f0_) && std::abs(f1_) < std::abs(f2)) {
      ++result_.minima_checked;
      if (const auto crossing = hidden_crossing(x0_, x2, f1_ < 0.0 ? -1.0 : 1.0)) {
        ++result_.hidden_pairs_found;
        brackets_.emplace_back(x0_, *crossing);
        brackets_.emplace_back(*crossing, x2);
        result_.notes.push_back(fmt::format(
            "close pair of roots found inside one scan cell near Omega = {:g}", *crossing));
        x0_ = x2;
        f0_ = f2;
        x1_ = x2 + step_;
        f1_ = coarse(x1_);
        continue;
      }
    }
    x0_ = x1_;
    f0_ = f1_;
    x1_ = x2;
    f1_ = f2;
  }
}

// The roots found when the time is up, with the meter stopped (its message names how many).
PlaneRoots FrequencyFinder::run() {
  try {
    return scan_and_refine();
  } catch (const TimeUp&) {
    meter_->stop_after(static_cast<long>(result_.roots.size()));
    return std::move(result_);
  }
}

PlaneRoots FrequencyFinder::scan_and_refine() {
  choose_scan_precision();
  choose_coarse_series();
  x0_ = 0.02 * spacing_;
  f0_ = coarse(x0_);
  x1_ = x0_ + step_;
  f1_ = coarse(x1_);
  scan_more(static_cast<std::size_t>(count_));
  const double rtol = std::max(settings_.tolerance * 0.1, 4e-16);
  for (std::size_t index = 0;
       index < brackets_.size() && static_cast<int>(result_.roots.size()) < count_; ++index) {
    refine_bracket(index, rtol);
    if (meter_ && meter_->stop_after(static_cast<long>(result_.roots.size()))) break;
  }
  return std::move(result_);
}

// The coarse scan may misplace a root lying within its truncation of a grid point: the bracket is
// widened by a grid step until the accurate determinant changes sign on it. A bracket that never
// does is dropped and the scan resumed for one more.
void FrequencyFinder::refine_bracket(std::size_t index, double rtol) {
  const double lo = brackets_[index].first, hi = brackets_[index].second;
  double a = lo, b = hi;
  double fa = full(a);
  double fb = full(b);
  for (int widen = 0; widen < 4 && (fa < 0.0) == (fb < 0.0); ++widen) {
    a = std::max(0.5 * a, a - step_);
    b += step_;
    fa = full(a);
    fb = full(b);
  }
  if ((fa < 0.0) == (fb < 0.0)) {
    result_.warnings.push_back(
        fmt::format("a sign change of the scan near Omega = {:g} is not confirmed by the full "
                    "series; skipped, scan resumed",
                    lo));
    scan_more(brackets_.size() + 1);
    return;
  }
  int iterations = 0;
  const double omega =
      refine_root([this](double x) { return full(x); }, a, b, fa, fb, rtol, iterations);
  const FoundRoot root = corrected_root(omega, rtol);
  if (!std::isfinite(root.omega) || !std::isfinite(root.relative_error)) {
    // The determinant overflowed or lost every digit (NaN compares as positive, so the scan may
    // even have bracketed it): not a frequency. The plane then has fewer roots than asked.
    result_.warnings.push_back(fmt::format(
        "the root bracketed in [{:g}, {:g}] came out non-finite in {} (series overflow): dropped",
        a, b, precision_name(std::max(result_.scan_precision, Precision::LongDouble))));
    return;
  }
  result_.roots.push_back(root);
}

// A-posteriori check of a root: secant-Newton steps with the series cut finer (1e-3 of the term
// tolerance per level, within the same max_terms: that knob is the user's resolution and is never
// exceeded) and in higher precision (long double, then quad from the third level when allowed).
// Errors carried through the matched expansions and rounding lost to cancellation are both
// caught, which a per-entry tail estimate would miss. The last correction is the reported
// estimate (conservative: the returned root is the one after it).
FoundRoot FrequencyFinder::corrected_root(double omega, double rtol) {
  PlaneSetup fine = setup_;
  Precision check = std::max(result_.scan_precision, Precision::LongDouble);
  double correction = 0.0;
  bool double_was_enough = true;
  // Slope from the scan-precision determinant over h ~ sqrt(tolerance) omega: accurate to ~1e-6,
  // so each Newton correction is accurate to ~1e-6 of itself (one evaluation per level). Later
  // levels (the root needed a correction) use the slope at the check precision.
  const double h = std::max(1e-7, std::sqrt(settings_.tolerance)) * omega;
  const double above = full(omega + h);
  double slope = (above - full(omega - h)) / (2.0 * h);
  for (int level = 0; level < 4 && slope != 0.0; ++level) {
    if (level == 2 && settings_.extended_precision && correction > 0.1 * settings_.tolerance)
      check = Precision::Quad;
    fine.settings.term_tolerance = std::max(fine.settings.term_tolerance * 1e-3, 1e-40);
    check_time();
    const double ga = scaled_determinant(check, fine, omega, result_.work);
    if (level > 0) check_time();
    if (level > 0) slope = (scaled_determinant(check, fine, omega + h, result_.work) - ga) / h;
    if (slope == 0.0) break;
    const double corrected = omega - ga / slope;
    correction = std::abs(corrected - omega) / omega;
    omega = corrected;
    if (level == 0 && correction > 0.1 * settings_.tolerance) double_was_enough = false;
    if (correction <= 0.1 * settings_.tolerance) break;
  }
  FoundRoot root;
  root.omega = omega;
  root.precision = double_was_enough ? result_.scan_precision : check;
  root.precision_difference = correction;
  root.truncation_estimate = correction;
  root.relative_error = std::max(correction, rtol);
  return root;
}

}  // namespace

double wkb_mode_spacing(const PlaneSetup& setup) {
  double integral = 0.0;
  const int panels = 400;
  for (int i = 0; i <= panels; ++i) {
    const double sigma = setup.sigma1 + (setup.sigma2 - setup.sigma1) * i / panels;
    const double weight = (i == 0 || i == panels) ? 0.5 : 1.0;
    integral += weight * std::sqrt(setup.mu / std::sqrt(1.0 + sigma * sigma));
  }
  integral *= (setup.sigma2 - setup.sigma1) / panels;
  return kPi / integral;
}

PlaneRoots find_frequencies(const PlaneSetup& setup,
                            int count,
                            const RootSettings& settings,
                            WorkMeter* meter) {
  return FrequencyFinder(setup, count, settings, meter).run();
}

}  // namespace catena::internal
