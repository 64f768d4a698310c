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

  /// Throws InvalidInput naming the field and the constraint.
  void validate() const;
  /// The stations s_j [m] for a cable of unstretched length L.
  Vector stations_m(double length_m) const;
};

}  // namespace catena
