// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Checking another program's dynamic tension along a line (docs/how-to/check-dynamic-tension.md)
/// against Catena's for the same scene and excitation: pure data in, comparison out. Reading the
/// other program's file is include/catena/io/external_tension_reader.hpp; solving the scene and
/// choosing Catena's reference is include/catena/verification/scene_tension_check.hpp.
///
/// What is compared:
/// - at each station of the other program's finest result, its tension standard deviation
///   (irregular motion) or amplitude (regular motion) against Catena's, interpolated linearly from
///   Catena's stations to the other program's arc length s;
/// - at the fairlead (s = L) when the other program gives it;
/// - with three or more resolutions, at each station every resolution shares (the fairlead and
///   the anchor of a node-based file, for instance): the convergence study of
///   include/catena/verification/external_check.hpp (observed order, extrapolated limit, bias).
///
/// A difference is a disagreement when it exceeds rtol |Catena| plus Catena's own error estimate
/// plus the other program's uncertainty (stated in the file, or derived by the convergence study).

#include <optional>
#include <string>
#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "catena/verification/external_check.hpp"

namespace catena {

/// Which tension the other program gives.
enum class TensionQuantity {
  StandardDeviation,  ///< `tension_std_n`: sigma of the dynamic tension, irregular motion [N]
  Amplitude           ///< `tension_amplitude_n`: |tau|, regular motion [N]
};
/// "tension_std_n" or "tension_amplitude_n" (the CSV column).
std::string to_string(TensionQuantity quantity);

/// One station of the other program at one resolution. Exactly one of `s_m` and (`node`,
/// `nodes`) is given; a node maps to s = node L / (nodes - 1).
struct ExternalTensionStation {
  std::optional<double> s_m;
  std::optional<int> node;
  std::optional<int> nodes;
  /// The other program's mesh count (larger = finer; element size taken as 1 / resolution).
  std::optional<double> resolution;
  /// The tension standard deviation or amplitude [N], finite and >= 0.
  double tension_n = 0.0;
  /// The other program's own uncertainty of `tension_n` [N] (e.g. the sampling error of a
  /// standard deviation from a finite time series), >= 0; absent: none stated.
  std::optional<double> uncertainty_n;
  /// Where it came from, for messages ("tension.csv row 4 (line 6)").
  std::string origin;
};

/// The other program's tension for one scene and one excitation.
struct ExternalTension {
  TensionQuantity quantity = TensionQuantity::StandardDeviation;
  /// Regular motion: the period it belongs to [s] (`period_s`); absent when the scene asks one.
  std::optional<double> period_s;
  std::vector<ExternalTensionStation> stations;
  /// The file, for messages.
  std::string origin;
};

/// Catena's dynamic tension for the excitation, and which solver gave it.
struct TensionReference {
  /// The solver whose result is the reference ("shooting" or "fe").
  std::string solver;
  /// Why this solver (e.g. "shooting converged with the smaller estimate 1e-9; fe 3e-7").
  std::string reason;
  /// Largest difference between shooting and fe over the stations, relative to the largest
  /// tension (-1 when only one of them computed it): an independent confirmation.
  double cross_check_relative = -1.0;
  DynamicTension tension;
};

/// One station of the other program's finest result, compared.
struct TensionStationComparison {
  double s_m = 0.0;
  double other_n = 0.0;
  /// Catena's value interpolated to s [N].
  double catena_n = 0.0;
  /// Catena's uncertainty at s [N]: its relative error estimate times the value, plus the
  /// estimated error of the linear interpolation (an eighth of the local second difference).
  double catena_uncertainty_n = 0.0;
  /// The other program's uncertainty [N]: stated in the file, else 0.
  double other_uncertainty_n = 0.0;
  /// other - Catena [N], and relative to Catena (absent when Catena's value is 0).
  double difference_n = 0.0;
  std::optional<double> relative_error;
  /// rtol |Catena| + catena_uncertainty_n + other_uncertainty_n [N].
  double allowed_n = 0.0;
  bool within = false;
  std::string origin;
};

/// The convergence study at one station that every resolution gives.
struct TensionStationStudy {
  double s_m = 0.0;
  /// "fairlead", "anchor" or "s = 420 m".
  std::string label;
  std::vector<double> resolutions;
  std::vector<double> values_n;
  double catena_n = 0.0;
  /// As for frequencies; the limit and its uncertainty are in N (the fields named _rad_s of the
  /// shared study hold tensions here).
  ConvergenceStudy study;
  ModeVerdict verdict = ModeVerdict::WithinTolerance;
};

/// The whole comparison.
struct TensionCheck {
  ExternalCheckOptions options;
  TensionQuantity quantity = TensionQuantity::StandardDeviation;
  /// The period compared [s] (0 when irregular).
  double period_s = 0.0;
  /// Catena's reference (solver, reason, cross-check; the tension without its spectra).
  TensionReference reference;
  /// The finest resolution compared (absent without a resolution column).
  std::optional<double> resolution;
  /// The finest result's stations, ascending s.
  std::vector<TensionStationComparison> stations;
  /// The station at s = L, when the other program gives it.
  std::optional<TensionStationComparison> fairlead;
  /// One per station common to every resolution (three or more resolutions).
  std::vector<TensionStationStudy> studies;
  /// max |other - Catena| / max |Catena| over the finest stations.
  double max_relative_difference = 0.0;
  /// The most severe verdict over the stations and studies (converges to a wrong limit, then
  /// beyond tolerance / not yet within tolerance, then converged / within tolerance).
  ModeVerdict verdict = ModeVerdict::WithinTolerance;
  bool any_failure() const { return is_failure(verdict); }
};

/// Checks `tension` on its own, given the line's unstretched length L: at least one station;
/// s_m or (node, nodes) on each row; s in [0, L]; nodes >= 2 and node in [0, nodes - 1] whole
/// numbers; finite tensions and uncertainties >= 0; resolutions finite and > 0, given on every row
/// or none; no two stations at the same s and resolution; a period finite and > 0. Throws
/// InvalidInput naming the row and the column.
void validate_external_tension(const ExternalTension& tension, double length_m);

/// The arc length [m] of a station on a line of unstretched length L.
double station_s_m(const ExternalTensionStation& station, double length_m);

/// Compares `tension` with Catena's `reference` (whose stations span [0, L]). Throws InvalidInput
/// as validate_external_tension, or when the reference has no values of the quantity compared.
TensionCheck check_external_tension(const ExternalTension& tension,
                                    const TensionReference& reference,
                                    const ExternalCheckOptions& options = {});

}  // namespace catena
