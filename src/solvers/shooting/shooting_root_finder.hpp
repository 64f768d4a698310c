// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The root finder of the `shooting` solver (docs/explanation/methods/shooting.md): brackets each
/// natural frequency by conjugate-point counts and refines it by safeguarded Newton steps with the
/// shot's frequency derivative (set_slope_shots; docs/explanation/methods/shooting.md, "Newton
/// refinement"), or with Brent's method.
///
/// Mode n is the root of the count-aware function h_n (count_function in
/// shooting_conjugate_count.hpp), bracketed by any two samples with counts < n and >= n: the sign
/// of h_n certifies the count, so no mode can be skipped. New samples inside a count bracket are
/// placed by a phase-extrapolated guess or bisection. For a one-component problem (out of plane,
/// or a straight inextensible cable) h_n is smooth across the eigenvalue and the refinement works
/// on it directly; in plane it works on the normalised end determinant, which changes sign exactly
/// once inside a bracket whose counts are n - 1 and n. Several eigenvalues inside a bracket
/// narrower than the tolerance (an exactly double root, e.g. Irvine's cross-over) are returned as
/// one root of that multiplicity.

#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "solvers/common/work_meter.hpp"
#include "solvers/shooting/shooting_integrator.hpp"
#include "solvers/shooting/shooting_root_prediction.hpp"

namespace catena::internal {

/// The part of the solver's options the root finder uses.
struct RootFinderSettings {
  /// The integrator's relative tolerance [-] (the noise level of the end function).
  double relative_tolerance = 1e-10;
  /// Relative width of the final root bracket [-].
  double root_tolerance = 1e-10;
  /// Estimate each root's integration error by one extra shot at 100x tighter tolerances.
  bool error_estimate = true;
  /// Relative accuracy each root must reach [-]: a root whose estimate exceeds it is found again
  /// at 10x, then 100x tighter tolerances (refine_tighter).
  double target = 1.1e-9;
  /// The smallest estimate reported [-] (the solver sets its target: the measured estimate can fall
  /// short of the error, docs/explanation/methods/shooting.md); 0: none.
  double estimate_floor = 0.0;
};

/// A frequency found (a cluster of `multiplicity` equal frequencies for a multiple root).
struct Root {
  double omega = 0.0;
  int multiplicity = 1;
  double relative_error = 0.0;
  double residual = 0.0;  ///< smaller |determinant| at the final bracket ends
};

/// Shots by purpose (the solver's notes; docs/explanation/methods/shooting.md, "Cost per root").
struct ShotTally {
  long bracketing = 0;     ///< counting samples that bracket a mode (and the upper bound)
  long refining = 0;       ///< root-function samples inside a certified count bracket
  long estimate = 0;       ///< error-estimate shots at 100x tighter tolerances
  long tightening = 0;     ///< re-bracketing at tighter tolerances (estimates above the target)
  long phase_retries = 0;  ///< re-shots of a sample whose integrated phase was off
};

/// One shot at `omega` [rad/s] with the integrator's tolerances scaled by `tolerance_factor`.
using ShotFunction = std::function<Shot(double omega, double tolerance_factor)>;

/// Brackets and refines the lowest eigenfrequencies of one plane.
class ShootingRootFinder {
 public:
  static constexpr long kMaxShots = 20000;
  static constexpr double kMaxPhaseDefect = 0.5;  ///< [rad]: the phase must be right to << pi

  /// `first_guess_rad_s`: a frequency expected above the wanted modes (enlarged until it is).
  /// `scalar`: a one-component problem, whose continuous count is smooth across the eigenvalues.
  ShootingRootFinder(ShotFunction shoot,
                     const RootFinderSettings& settings,
                     double first_guess_rad_s,
                     bool scalar);

  /// The lowest `num_modes` eigenfrequencies (a multiple root counts its multiplicity), with
  /// warnings about counts that did not behave. Throws ShootingFailure when a shot fails or
  /// more than kMaxShots are needed. A `meter` is told each mode found and may stop the search
  /// early (fewer roots, the lowest ones).
  std::vector<Root> find(int num_modes,
                         std::vector<std::string>& warnings,
                         WorkMeter* meter = nullptr);

  /// Shots that carry the frequency derivative (ShootingIntegrator::shoot with_slope): given,
  /// each root is refined by safeguarded Newton steps inside its sign bracket (refine_newton)
  /// instead of Brent's method.
  void set_slope_shots(ShotFunction shoot_with_slope) {
    shoot_with_slope_ = std::move(shoot_with_slope);
  }

  long shots() const { return shots_; }
  /// The count at the smallest sample above the top root (-1 when none).
  int proved_count() const { return proved_count_; }
  double max_phase_defect() const { return max_phase_defect_; }
  long phase_retries() const { return tally_.phase_retries; }
  /// Refinements at tighter tolerances (roots whose first estimate exceeded the target).
  long tightened() const { return tightened_; }
  const ShotTally& tally() const { return tally_; }

 private:
  // One evaluation of the end function: the count of eigenvalues below omega, the end
  // eigen-angles (for the count-aware root function) and the smooth end determinant.
  struct Sample {
    int count = 0;
    double angle_min = 0.0;
    double angle_max = 0.0;
    double determinant = 0.0;
    /// d(root function)/d omega when the shot carried the slope, NaN otherwise: the
    /// determinant's in plane, the continuous count's (angle slope / 2 pi) for D = 1.
    double slope = std::numeric_limits<double>::quiet_NaN();
  };
  static double count_function(const Sample& sample, int n);

  std::vector<Root> finish(std::vector<Root>& roots);
  void record(const Root& root, std::vector<Root>& roots);
  void sample_prediction(int n);
  const Sample& evaluate(double omega);
  void raise_to_count(double& top, int num_modes);
  std::pair<double, double> bracket(int n) const;
  double trial_point(int n, double lo, double hi) const;
  Root multiple_root(int n, double lo, double hi, std::vector<std::string>& warnings) const;
  double end_value(const Sample& sample, int n) const;
  Sample shoot_sample(double omega, double factor);
  Root refine_to_target(int n, double lo, double hi, std::vector<std::string>& warnings);
  Root refine(int n, double lo, double hi);
  const Sample& evaluate_with_slope(double omega);
  Sample cached_shot(double omega, const ShotFunction& shoot);
  double newton_start(int n, double a, double b) const;
  struct ModelPoint {
    double x = 0.0;
    double g = 0.0;        ///< the function Newton works on (model_point)
    double dg = 0.0;       ///< its slope
    bool tangent = false;  ///< g = tan(pi h) rather than h
  };
  ModelPoint model_point(double x, double f, double slope) const;
  static double model_step(const ModelPoint& current, const std::optional<ModelPoint>& previous);
  std::optional<Root> tight_newton_root(int n, double lo, double hi, double& x0);
  std::optional<Sample> tight_slope_sample(double omega);
  struct ModelPoint;
  double normal_tolerance_root(
      int n, double lo, double hi, double base, bool hermite, const ModelPoint& tight) const;
  std::optional<double> newton_error_bound(double step, double last_step, double omega) const;
  void close_top_bracket(const std::vector<Root>& roots);
  Sample to_sample(const Shot& shot) const;
  std::optional<Root> refine_newton(int n, double& lo, double& hi);
  Root newton_root(int n, double omega, double step, const Sample& last, double lo, double hi);
  Root root_in_bracket(
      int n, double a, double b, const Sample& sa, const Sample& sb, double factor);
  Root refine_tighter(int n, Root root, double lo, double hi);

  ShotFunction shoot_;
  ShotFunction shoot_with_slope_;
  RootFinderSettings settings_;
  double first_guess_;
  bool scalar_;
  std::map<double, Sample> samples_;
  RootPredictor predictor_;
  long shots_ = 0;
  int proved_count_ = -1;
  double max_phase_defect_ = 0.0;
  long tightened_ = 0;
  ShotTally tally_;
  long* purpose_ = &tally_.bracketing;  ///< where the next shot is counted
};

}  // namespace catena::internal
