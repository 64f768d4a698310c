// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Helpers every solver uses to fill the common result structs the same way: frequency units,
/// the shape normalisation of modal_result.hpp, and modal mass on the stations.

#include <complex>

#include "catena/solvers/modal_result.hpp"
#include "catena/statics/dimensionless_groups.hpp"

namespace catena::internal {

/// Sets omega, Hz, kL/pi and Gale's ratio (when defined) of `mode`.
void set_mode_frequency(Mode& mode, double omega_rad_s, const DimensionlessGroups& groups);

/// Sets a damped root lambda = -delta + i omega_d (docs/explanation/physics.md, "Damping"):
/// omega_rad_s = omega_d (and its units), decay_rate_1_s = delta, damping_ratio = delta / |lambda|.
/// lambda = i omega gives exactly set_mode_frequency(mode, omega) with delta = zeta = 0; so does a
/// |Re lambda| within 64 ulp of |lambda| (rounding, not damping).
void set_damped_root(Mode& mode, std::complex<double> lambda, const DimensionlessGroups& groups);
/// Normalises a complex (damped) shape held as real parts (u, w, v, tension_n) and imaginary parts
/// (the `_imag` vectors, empty or of the same size): multiplies every component by one complex
/// factor so that the component named by `by` ("w", "u" or "v") has its first entry of largest
/// modulus equal to 1 (real, positive). Sets normalised_by and max_abs_tension_n = max |tau|.
/// With empty `_imag` vectors it is the real normalisation. Returns the modulus of the factor.
double normalise_complex_mode(Mode& mode, const std::string& by);
/// Scales an in-plane mode (u, w and, when present, tension_n) to max|w| = 1 with w > 0 at the
/// first station of largest |w|; a mode with max|w| <= 1e-6 max|u| is scaled by u instead.
/// Sets normalised_by and max_abs_tension_n (when tension_n is present). Returns the factor
/// applied.
double normalise_inplane_mode(Mode& mode);

/// Same for an out-of-plane mode, by v.
double normalise_outofplane_mode(Mode& mode);

/// Clears the shape fields of a mode computed only for its summary (shapes not asked): stations,
/// u, w, v (and their imaginary parts), tension along the cable and modal mass (-1). Keeps the
/// frequency, the estimate, normalised_by and max_abs_tension_n.
void drop_shape_fields(Mode& mode);

/// Integral of f over the stations s (trapezoid on equally or unequally spaced points).
double integrate_on_stations(const Vector& s, const Vector& f);

/// In-plane modal mass int (m u^2 + M w^2) ds on the stations [kg].
double inplane_modal_mass(const Mode& mode, double mass_kg_per_m, double normal_mass_kg_per_m);

/// Out-of-plane modal mass int M v^2 ds [kg].
double outofplane_modal_mass(const Mode& mode, double normal_mass_kg_per_m);

}  // namespace catena::internal
