// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// What a scene asks the solvers to compute (docs/reference/scene-format.md, `[request]`). Only
/// what is asked is computed.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "catena/core/types.hpp"

namespace catena {

/// Which support is driven in a forced-response request.
enum class CableEnd { A, B };
std::string to_string(CableEnd end);

/// Direction of the prescribed end displacement.
enum class ForcingDirection {
  Tangential,   ///< along the static tangent at the driven end
  Normal,       ///< along the in-plane normal at the driven end
  GivenVector,  ///< a given in-plane vector (x, z), normalised
  OutOfPlane    ///< normal to the plane of the supports
};
std::string to_string(ForcingDirection direction);

/// Harmonic forced response: one end displaced by `amplitude_m * direction * cos(omega t)`, the
/// other fixed. One solve per forcing frequency.
struct ForcedRequest {
  CableEnd end = CableEnd::B;
  ForcingDirection direction = ForcingDirection::Tangential;
  /// In-plane direction (x, z) when direction == GivenVector; need not be unit.
  Vec2 vector = Vec2(1.0, 0.0);
  /// Displacement amplitude at the driven end [m]. > 0.
  double amplitude_m = 0.01;
  /// Forcing frequencies [rad/s], >= 0.
  std::vector<double> omegas_rad_s;

  /// `vector` / |vector|, computed without overflow or underflow (scaled by its larger component
  /// first: [1e308, 1e308] and [1e-320, 1e-320] give (1, 1) / sqrt 2). Zero for a zero or
  /// non-finite vector (which validate() rejects). Every solver takes the direction from here.
  Vec2 unit_vector() const;
};

/// A table of a one-sided spectral density over circular frequency (docs/reference/scene-format.md,
/// `[request.motion]`): omega [rad/s] strictly increasing, finite and >= 0; density >= 0, finite.
struct SpectrumTable {
  std::vector<double> omega_rad_s;
  /// Motion spectrum of end b along the motion direction [m^2 s/rad].
  std::vector<double> density_m2_s_per_rad;
};

/// JONSWAP wave spectrum (DNV-RP-C205 3.5.5, with the Goda normalisation A_gamma = 1 - 0.287 ln
/// gamma): significant wave height, peak period, peak enhancement.
struct JonswapSpectrum {
  double hs_m = 0.0;   ///< > 0 [m]
  double tp_s = 0.0;   ///< > 0 [s]
  double gamma = 3.3;  ///< in [1, 7] [-] (DNV's range)
};

/// The fairlead's motion response amplitude operator along the motion direction: at each wave
/// frequency, the motion amplitude per unit wave amplitude [m/m] (or per unit wave height when
/// `per_wave_height`) and its phase [deg] (the phase does not enter a single-direction spectrum;
/// it is validated and kept for reports).
struct RaoTable {
  std::vector<double> omega_rad_s;
  std::vector<double> amplitude;
  std::vector<double> phase_deg;
  /// True: amplitude per unit wave *height* H = 2 a (the motion spectrum then gains a factor 4).
  bool per_wave_height = false;
};

/// The motion of end b (the fairlead) whose dynamic tension is asked, with Morison drag linearised
/// about the response (docs/explanation/dynamic-tension.md). Regular: `periods_s` and
/// `amplitude_m`. Irregular: `spectrum`, or `jonswap` with `rao`.
struct MotionRequest {
  /// In-plane vector (x, z) (GivenVector) or OutOfPlane.
  ForcingDirection direction = ForcingDirection::GivenVector;
  Vec2 vector = Vec2(1.0, 0.0);
  /// Regular motion: amplitude [m] (> 0) and periods [s] (> 0), one fixed point per period.
  double amplitude_m = 0.0;
  std::vector<double> periods_s;
  /// Irregular motion: a motion spectrum table, or a JONSWAP sea times an RAO table.
  std::optional<SpectrumTable> spectrum;
  std::optional<JonswapSpectrum> jonswap;
  std::optional<RaoTable> rao;
  /// Frequencies of the grid on which JONSWAP x |RAO|^2 is integrated (equally spaced over the
  /// RAO table's range), in [8, 100000].
  int frequencies = 200;
  /// Duration of the sea state for the most probable maximum [s], > 0.
  double duration_s = 10800.0;
  /// Fixed point: relative residual max_s |V_new - V| / max_s |V_new| to reach, in [1e-14, 0.1],
  /// and the most iterations, in [1, 10000].
  double tolerance = 1e-8;
  int max_iterations = 200;

  bool is_irregular() const { return spectrum.has_value() || jonswap.has_value(); }
  /// `vector` / |vector| (as ForcedRequest::unit_vector).
  Vec2 unit_vector() const;
  /// Throws InvalidInput naming the field (`request.motion.periods`, `request.motion.rao.omega`,
  /// ...) and the constraint.
  void validate() const;
};

/// Most modes a request may ask for in each plane (docs/reference/scene-format.md, "Limits on
/// work"): at the measured cost the largest request takes minutes, not days. Use a time limit
/// (catena/solvers/run_limits.hpp) for less.
inline constexpr int kMaxRequestModes = 1000;
/// Most stations a request may ask for (docs/reference/scene-format.md, "Limits").
inline constexpr int kMaxRequestPoints = 100000;
/// Most values of one shape table: points x (inplane_modes + outofplane_modes) when shapes are
/// asked. Bounds the memory and the size of the results JSON (a few hundred MB at the limit).
inline constexpr long kMaxShapeValues = 1000000;

/// What to compute.
struct SolveRequest {
  /// Most forcing frequencies in one request (docs/reference/scene-format.md, "Limits on work").
  static constexpr std::size_t kMaxForcingFrequencies = 100000;

  /// Number of lowest in-plane modes (0: none).
  int inplane_modes = 6;
  /// Number of lowest out-of-plane modes (0: none).
  int outofplane_modes = 0;
  /// Mode shapes on `points` equally spaced stations s_j = j L / (points - 1).
  bool shapes = false;
  /// Stations for shapes, tension and forced response; in [2, kMaxRequestPoints].
  int points = 101;
  /// Dynamic tension of each mode (along the cable when shapes are asked, else its maximum).
  bool tension = false;
  /// Forced response, when asked.
  std::optional<ForcedRequest> forced;
  /// Dynamic tension under a motion of end b with linearised drag, when asked.
  std::optional<MotionRequest> motion;

  /// Throws InvalidInput naming the field and the constraint.
  void validate() const;
  /// The stations s_j [m] for a cable of unstretched length L.
  Vector stations_m(double length_m) const;
};

}  // namespace catena
