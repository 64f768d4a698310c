// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The dimensionless groups of docs/explanation/physics.md ("Dimensionless groups"), computed for
/// any problem, and the frequency conversions between rad/s, kL/pi (Grinfogel) and w / sqrt(g/a)
/// (Gale).

#include <optional>
#include <string>

#include "catena/models/cable.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {

/// Groups of the taut inclined cable (Grinfogel 1984; docs/reference/references.md) and of the
/// suspended catenary (Gale 1976; docs/reference/references.md).
struct DimensionlessGroups {
  /// True for a uniform cable. For a general line (docs/explanation/physics.md, "General lines")
  /// the groups of Grinfogel and Gale mean nothing: only chord_angle_rad, t0_n (the larger end
  /// tension), mass_ratio and taut_frequency_scale_rad_s (with the length-averaged normal mass, so
  /// that kL/pi stays a frequency unit) are set; eps, lambda2 and s_a are 0 and not reported, and
  /// Gale's parameterization is absent.
  bool uniform = true;

  // --- taut inclined cable (Grinfogel 1984) ---
  /// phi_a: inclination of the chord a -> b above the horizontal [rad], in (-pi/2, pi/2].
  double chord_angle_rad = 0.0;
  /// s_a: arc length where the static angle equals phi_a [m].
  double s_at_chord_angle_m = 0.0;
  /// T0: static tension at s_a [N].
  double t0_n = 0.0;
  /// eps = W0 L / T0 [-].
  double eps = 0.0;
  /// lambda^2 = EA eps^2 cos^2(phi_a) / T0 [-]; +inf for an inextensible cable.
  double lambda2 = 0.0;
  /// h = m / M [-].
  double mass_ratio = 1.0;

  // --- Gale's catenary parameterization (Gale 1976), defined when H > 0 ---
  bool has_apex_parameterization = false;
  /// a = H / W0 [m].
  double catenary_parameter_m = 0.0;
  /// sigma = V / H at the ends [-] (sigma = (s - s_apex)/a for an inextensible cable).
  double sigma1 = 0.0;
  double sigma2 = 0.0;
  /// xi = sign(sigma) (sqrt(1 + sigma^2) - 1) at the ends [-].
  double xi1 = 0.0;
  double xi2 = 0.0;
  /// h/b: height difference over span (b = horizontal span) [-]; undefined for a vertical chord.
  std::optional<double> height_over_span;
  /// Sag parameter b / sqrt(L^2 - h^2) with the unstretched L [-]; defined when L > |h|.
  std::optional<double> sag_parameter;

  // --- frequency scales ---
  /// sqrt(T0 / M) / L [1/s]: kL = omega / this.
  double taut_frequency_scale_rad_s = 1.0;
  /// sqrt(g / a) with g = W0 / m [rad/s], defined when H > 0.
  double gale_frequency_scale_rad_s = 0.0;

  /// kL/pi with k = omega / sqrt(T0 / M).
  double k_l_over_pi(double omega_rad_s) const;
  double omega_from_k_l_over_pi(double k_l_over_pi) const;
  /// omega / sqrt(g/a) = omega sqrt(m H) / W0; nullopt when H = 0.
  std::optional<double> gale_ratio(double omega_rad_s) const;
  /// Throws InvalidInput when Gale's scale is undefined (H = 0).
  double omega_from_gale_ratio(double ratio) const;
};

/// Computes every group from the problem and its statics.
DimensionlessGroups compute_dimensionless_groups(const Problem& problem,
                                                 const StaticSolution& statics);

/// Frequency units a user may write (scene files, CLI).
enum class FrequencyUnit { RadPerSecond, Hertz, KLOverPi, GaleRatio };
/// "rad/s", "Hz", "kL/pi", "gale".
std::string to_string(FrequencyUnit unit);
/// Accepts "rad/s", "hz"/"Hz", "kL/pi", "gale". nullopt otherwise.
std::optional<FrequencyUnit> parse_frequency_unit(const std::string& text);
/// Converts a frequency in `unit` to rad/s.
double to_rad_per_second(double value, FrequencyUnit unit, const DimensionlessGroups& groups);
/// Converts rad/s to `unit`.
double from_rad_per_second(double omega_rad_s,
                           FrequencyUnit unit,
                           const DimensionlessGroups& groups);

}  // namespace catena
