// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The damped boundary problem of one plane of the frobenius solver
/// (docs/explanation/methods/frobenius.md, "Damping"): Gale's series with complex coefficients at
/// a complex root lambda (units sqrt(g/a)), the catenary in a viscous medium with tangential drag
/// eta1 and normal drag eta2 (Gale's eqs. 2.28e,f: c = eta m sqrt(g/a)). The ODE is the undamped
/// one with the tangential inertia Omega^2 -> -mu1 = -(lambda^2 + eta1 lambda) and the normal
/// inertia mu Omega^2 -> -mu2 = -(mu lambda^2 + eta2 lambda)
/// (verification/tools/frobenius_derive_damped_odes.py). Evaluated in complex long double.

#include <complex>
#include <vector>

#include "solvers/frobenius/frobenius_boundary.hpp"
#include "solvers/frobenius/frobenius_fields.hpp"

namespace catena::internal {

using DampedReal = long double;
using DampedComplex = std::complex<DampedReal>;

/// One plane's boundary problem with its drag, in Gale's units.
struct DampedSetup {
  PlaneSetup plane;
  /// Tangential and normal drag, c / (m sqrt(g/a)).
  double eta1 = 0.0;
  double eta2 = 0.0;
};

/// mu1 = lambda^2 + eta1 lambda (tangential) and mu2 = mu lambda^2 + eta2 lambda (normal).
struct DampedInertia {
  DampedComplex mu1, mu2;
};
DampedInertia damped_inertia(const DampedSetup& setup, const DampedComplex& lambda);

/// The complex boundary matrix (rows as frobenius_boundary.hpp), columns divided by their norm:
/// a positive factor, so the phase of the determinant is the unscaled one's (the argument
/// principle counts its zeros).
struct DampedMatrix {
  std::vector<std::vector<DampedComplex>> a;
  /// Absolute error estimate of each entry (same scaling).
  std::vector<std::vector<DampedReal>> error;
  std::vector<DampedReal> column_scale;
  double cancellation = 1.0;
  long terms = 0;
  int centres = 0;
  bool converged = true;
};

/// The boundary matrix at lambda; `term_scale` multiplies the series' term tolerance (a finer
/// re-evaluation for the error estimates).
DampedMatrix damped_boundary_matrix(const DampedSetup& setup,
                                    const DampedComplex& lambda,
                                    double term_scale = 1.0);

/// Determinant of a small complex matrix.
DampedComplex damped_determinant(const std::vector<std::vector<DampedComplex>>& a);

/// Null vector of the boundary matrix at lambda, in the unscaled basis (complex SVD).
std::vector<DampedComplex> damped_null_vector(const DampedSetup& setup,
                                              const DampedComplex& lambda);

/// Complex U, V and (in plane, `with_tension`) T of the combination c at each sigma: T from
/// Gale's eq. 2.37 with mu Omega^2 -> -mu2.
struct DampedFieldValues {
  DampedComplex u, v, t;
};
std::vector<DampedFieldValues> damped_fields(const DampedSetup& setup,
                                             const DampedComplex& lambda,
                                             const std::vector<DampedComplex>& c,
                                             const std::vector<double>& sigmas,
                                             bool with_tension);

/// Fills the complex shapes (u, w or v with their imaginary parts), the dynamic tension and
/// max |tau| of `mode` at lambda, normalised by normalise_complex_mode (in plane by w, or by u
/// when max|w| <= 1e-6 max|u|; out of plane by v). Without shapes only max |tau| is kept.
void add_damped_mode_fields(Mode& mode,
                            const DampedSetup& setup,
                            const DampedComplex& lambda,
                            const ModeFieldRequest& request,
                            const CableUnits& units);

}  // namespace catena::internal
