// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// `catena check` on a free decay computed by another program (docs/how-to/check-time-series.md):
/// the damped modes identified in the record (include/catena/verification/modal_identification.hpp)
/// against Catena's damped modes of the scene, computed by the exact solvers through the same
/// driver and the same certified-reference choice as the frequency check
/// (include/catena/verification/certified_reference.hpp).
///
/// Planes: a channel sees the modes of one plane. In the linear theory the dynamic tension and the
/// in-plane displacements (MoorDyn's x and z, with the line in the x-z plane) move with the
/// in-plane modes only; out-of-plane displacements (y) with the out-of-plane modes only. The
/// channels of one plane are identified together (they share the poles); a channel whose name says
/// nothing (most CSV columns) needs TimeSeriesCheckOptions::plane.
///
/// Matching: each identified mode goes to the nearest Catena mode of its plane in frequency; no
/// Catena mode takes two identified modes (the farther is "unmatched"). Catena's modes below the
/// highest matched one that the record does not show are listed as not present.
///
/// Verdict of one mode: "agrees" when |f_id - f_catena| <= U_f + e_f and |zeta_id - zeta_catena|
/// <= U_zeta + e_zeta (U: the identification's uncertainty, e: Catena's own error bound); else
/// "disagrees"; "not identifiable" when the identification says so; "unmatched" as above.

#include <optional>
#include <string>
#include <vector>

#include "catena/core/types.hpp"
#include "catena/verification/time_series.hpp"
#include "catena/verification/external_check.hpp"
#include "catena/verification/scene.hpp"

namespace catena {

/// Settings of the time-series check.
struct TimeSeriesCheckOptions {
  /// Channels to use, by name (TimeSeries::channel_index()); at least one.
  std::vector<std::string> channels;
  /// The free decay [s]: from the release (after any transient) to the end of the record. Absent:
  /// the start, or the end, of the record. Must lie within the record, start < end, and span two
  /// periods of Catena's lowest mode of each plane used.
  std::optional<double> window_start_s;
  std::optional<double> window_end_s;
  /// The plane every channel sees, overriding what the names say (needed for channels whose name
  /// does not tell, and for a MoorDyn line not in the x-z plane). Absent: from the names.
  std::optional<Plane> plane;
  /// Several runs: the resolution of each (e.g. MoorDyn's NumSegs; larger = finer), in the order
  /// of the runs. Empty: each run's TimeSeries::num_segments (a MoorDyn line file).
  std::vector<double> resolutions;
  /// Band of the identification [Hz] (0: no lower bound; 0: up to 0.8 Nyquist).
  double min_frequency_hz = 0.0;
  double max_frequency_hz = 0.0;
  /// Uncertainties are this many standard deviations (IdentificationOptions). > 0.
  double confidence_sigmas = 3.0;
  /// Throws InvalidInput naming the field.
  void validate() const;
};

/// The convergence study of one matched mode over several runs (ExternalCheck's study on the
/// identified frequencies).
struct TimeSeriesStudy {
  /// Ascending resolution; the identified frequency [Hz] and its uncertainty at each.
  std::vector<double> resolutions;
  std::vector<double> frequencies_hz;
  std::vector<double> frequency_uncertainties_hz;
  /// The study (limit in rad/s as the shared code holds it; bias relative to Catena).
  ConvergenceStudy study;
  /// "converges to Catena", "converges to a wrong limit" or "inconclusive" (note says why).
  std::string verdict;
};

/// One identified mode compared with Catena.
struct TimeSeriesModeCheck {
  /// "in-plane" or "out-of-plane".
  std::string plane;
  /// Catena's mode number within the plane (1-based); 0 when unmatched.
  int mode = 0;
  double identified_frequency_hz = 0.0;
  double frequency_uncertainty_hz = 0.0;
  double identified_damping_ratio = 0.0;
  double damping_ratio_uncertainty = 0.0;
  double identified_decay_rate_1_s = 0.0;
  double signal_to_noise = 0.0;
  /// Catena's damped frequency and damping ratio (0 when unmatched) and its own error bounds on
  /// them (from the solver's estimates of omega and of the decay rate).
  double catena_frequency_hz = 0.0;
  double catena_damping_ratio = 0.0;
  double catena_frequency_error_hz = 0.0;
  double catena_damping_ratio_error = 0.0;
  /// identified - Catena.
  double frequency_error_hz = 0.0;
  double damping_ratio_error = 0.0;
  /// "agrees", "disagrees", "not identifiable" or "unmatched".
  std::string verdict;
  /// Why (the numbers of the verdict, the identification's note).
  std::string note;
  /// Several runs: the convergence study of this mode.
  std::optional<TimeSeriesStudy> study;
};

/// A Catena mode below the highest matched one that the record does not show.
struct TimeSeriesModeNotPresent {
  std::string plane;
  int mode = 0;
  double catena_frequency_hz = 0.0;
  double catena_damping_ratio = 0.0;
};

/// How one plane was identified and which Catena solver is its reference.
struct TimeSeriesPlane {
  std::string plane;
  std::vector<std::string> channels;
  /// Identification summary (of the finest run when there are several).
  std::string method;
  int model_order = 0;
  double noise_rms = 0.0;
  double sample_interval_s = 0.0;
  /// The largest singular values of the data matrix (at most 20), for the order choice.
  std::vector<double> singular_values;
  /// Catena's reference: the solver and why (certified_reference()), and the shooting-fe
  /// cross-check (-1 when only one converged).
  std::string reference_solver;
  std::string reference_reason;
  double cross_check_relative = -1.0;
  /// True when the scene has no damping: Catena's zeta is 0 for every mode.
  bool undamped = false;
};

/// The whole check.
struct TimeSeriesCheck {
  /// Identified modes, in-plane first, by ascending frequency.
  std::vector<TimeSeriesModeCheck> modes;
  std::vector<TimeSeriesModeNotPresent> not_present;
  std::vector<TimeSeriesPlane> planes;
  /// The window used [s] (of the finest run).
  double window_start_s = 0.0;
  double window_end_s = 0.0;
  /// Runs compared (1, or several resolutions) and their resolutions (empty for one run).
  int runs = 1;
  std::vector<double> resolutions;
  /// What makes the comparison not exact (non-linearity of the scene: drag, seabed contact) and
  /// other remarks.
  std::vector<std::string> notes;
  /// Verdict counts.
  int agrees = 0;
  int disagrees = 0;
  int not_identifiable = 0;
  int unmatched = 0;
  /// Non-empty when Catena could not compute its reference (the statics failed numerically, or
  /// neither exact solver converged in a plane used): there is no comparison (`catena check`
  /// exits 3).
  std::string error;
  /// True when `error` is set, a mode disagrees or is unmatched, a study converges to a wrong
  /// limit, or no mode agrees (nothing was verified): `catena check` then exits 1.
  bool any_failure() const;
};

/// Identifies the modes of `series` in the window and compares them with Catena's damped modes of
/// `scene`. Throws InvalidInput for bad input: options, a missing channel (close names listed),
/// NaN samples (row and channel named), a window outside the record or shorter than two periods of
/// Catena's lowest mode, non-uniform sampling beyond the file's rounding (identification needs
/// uniform samples: it refuses rather than resamples, since interpolation would bias the damping
/// by an amount the uncertainty does not include), a channel whose plane is unknown. When Catena
/// could not compute its reference, TimeSeriesCheck::error says why (never an exception).
TimeSeriesCheck check_time_series(const Scene& scene,
                                  const TimeSeries& series,
                                  const TimeSeriesCheckOptions& options);

/// Several runs of the same decay at different resolutions (e.g. MoorDyn NumSegs 20, 40, 80): each
/// is identified, the finest is compared as check_time_series() does, and each matched mode gets
/// the convergence study of its identified frequencies. The resolutions come from
/// options.resolutions or the runs' num_segments (InvalidInput when neither, or when two runs have
/// the same resolution).
TimeSeriesCheck check_time_series_runs(const Scene& scene,
                                       const std::vector<TimeSeries>& runs,
                                       const TimeSeriesCheckOptions& options);

/// The plane a channel name says it sees ("FAIRTEN1", "Seg3Te": in-plane; "L1N5PY": out of
/// plane), or nullopt when the name does not tell.
std::optional<Plane> channel_plane(const std::string& name);

}  // namespace catena
