// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Displacement and tension along the cable from one shot of the `shooting` solver: a
/// combination of the shot's final basis evaluated at the recorded stations, in physical units
/// (u = Phi . t, w = Phi . n, tau = t . F in plane; v out of plane). Shared by the mode shapes
/// and the forced response.

#include <Eigen/Core>
#include <vector>

#include "catena/core/types.hpp"
#include "solvers/shooting/shooting_coefficients.hpp"
#include "solvers/shooting/shooting_damped_integrator.hpp"
#include "solvers/shooting/shooting_integrator.hpp"

namespace catena::internal {

/// Displacements [m] and dynamic tension [N] at the stations (the vectors of the other plane
/// are empty).
struct Profile {
  Vector u, w, v, tension;
};

/// The profile of the combination `c` of the final basis of `shot`, which recorded
/// `stations_m` (in reverse order when it was shot from b, `reversed`).
Profile evaluate_profile(const Shot& shot,
                         const Eigen::VectorXd& c,
                         const ShootingCoefficients& k,
                         const Vector& stations_m,
                         bool reversed,
                         Plane plane);

/// The real and imaginary parts of the profile of the complex combination `c` of the final basis
/// of a damped shot (evaluate_profile is linear in the basis).
struct ComplexProfile {
  Profile real, imag;
};
ComplexProfile evaluate_damped_profile(const DampedShot& shot,
                                       const Eigen::VectorXcd& c,
                                       const ShootingCoefficients& k,
                                       const Vector& stations_m,
                                       bool reversed,
                                       Plane plane);

/// The out-of-plane profile of the transverse string re-labelled as the in-plane normal motion
/// (a straight inextensible cable): w = v, u = 0, tension 0.
Profile string_as_inplane(const Profile& string);

/// The stations as x = s/L in the order of integration (from b: x = 1 - s/L, reversed).
std::vector<double> scaled_stations(const Vector& stations_m, double length_m, bool reversed);

}  // namespace catena::internal
