// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The fields of the frobenius solver (docs/explanation/methods/frobenius.md): the combination of
/// the series basis that meets the boundary conditions (the null vector of the boundary matrix at a
/// natural frequency, or the driven solution of the forced response), and its displacements and
/// dynamic tension along the cable (Gale 1976, eqs. 2.36, 2.37; docs/reference/references.md):
///   U tangential, V = C^2 DU normal, T = (sigma/C) U - [(3 + 4 sigma^2) C + mu Omega^2 C^4] DU
///   - 5 sigma C^3 D^2U - C^5 D^3U, in units of a (displacements) and H (tension); out of plane
///   U is the displacement normal to the plane.

#include <vector>

#include "catena/core/types.hpp"
#include "catena/solvers/modal_result.hpp"
#include "solvers/frobenius/frobenius_boundary.hpp"

namespace catena::internal {

/// The physical units of Gale's variables for one cable.
struct CableUnits {
  /// Catenary parameter a = H/W0 [m]: the unit of length.
  double length_m = 1.0;
  /// Horizontal force H [N]: the unit of tension.
  double tension_n = 1.0;
  /// sqrt(g/a) [rad/s]: the unit of frequency.
  double frequency_rad_s = 1.0;
  /// Tangential (m) and normal (M) mass per length [kg/m].
  double mass_kg_per_m = 1.0;
  double normal_mass_kg_per_m = 1.0;
};

/// Stations along the cable: arc length s [m] and sigma = V(s)/H there.
struct FieldStations {
  Vector s_m;
  std::vector<double> sigma;
};

/// U, V and T (units a and H) of one combination of the basis at one station.
struct FieldValues {
  double u = 0.0, v = 0.0, t = 0.0;
};

/// Coefficients of the mode at Omega = omega (null vector of the boundary matrix, by SVD), in the
/// unscaled basis. Instantiated for double, long double and QuadFloat.
template <class Real>
std::vector<Real> null_vector(const PlaneSetup& setup, double omega);

/// U, V and (when `with_tension`, in plane) T of the combination c of the basis at each sigma.
/// Instantiated for double, long double and QuadFloat.
template <class Real>
std::vector<FieldValues> fields(const PlaneSetup& setup,
                                double omega,
                                const std::vector<Real>& c,
                                const std::vector<double>& sigmas,
                                bool with_tension);

/// The fields of the mode at Omega = omega (null vector and fields in precision `p`).
std::vector<FieldValues> mode_fields(Precision p,
                                     const PlaneSetup& setup,
                                     double omega,
                                     const std::vector<double>& sigmas,
                                     bool with_tension);

/// Which fields a mode carries, and where.
struct ModeFieldRequest {
  bool shapes = false;
  bool tension = false;
  /// The request's stations (shapes are returned there).
  const FieldStations* stations = nullptr;
  /// Dense internal stations, for max |T| when tension is asked without shapes.
  const FieldStations* dense = nullptr;
};

/// Fills the shapes (u, w or v), the dynamic tension and the modal mass of `mode`, whose
/// frequency Omega = omega was found in precision `p`, normalised like every solver's. Without
/// shapes only max |T| is kept. Out of plane the shape is always computed (its interior sign
/// changes are the Sturm check of the count), and returned only when asked. Returns those
/// interior sign changes of the out-of-plane shape (interior_sign_changes), -1 in plane.
int add_mode_fields(Mode& mode,
                    const PlaneSetup& setup,
                    double omega,
                    Precision p,
                    const ModeFieldRequest& request,
                    const CableUnits& units);

/// Sign changes of v between its second and its second-to-last station (the end stations, where
/// the mode vanishes, are left out): n - 1 for the n-th string-like mode (Sturm).
int interior_sign_changes(const Vector& v);

}  // namespace catena::internal
