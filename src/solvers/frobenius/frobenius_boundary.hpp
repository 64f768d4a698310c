// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The boundary problem of one plane of the frobenius solver
/// (docs/explanation/methods/frobenius.md): the series basis evaluated at both ends of the cable,
/// as a square matrix whose determinant vanishes exactly at the natural frequencies. In plane the
/// rows are U and DU at sigma1, then at sigma2 (4x4: U = V = 0 at both ends, V = C^2 DU); out of
/// plane the row is U at each end (2x2).
///
/// The columns are divided by the norm of all derivatives D^0..D^(n-1) U_j at both ends. That
/// norm is positive and smooth in omega (the derivatives of a solution cannot all vanish), so the
/// scaled determinant keeps the sign and the zeros of the unscaled one and stays continuous, while
/// its size becomes comparable across omega and precisions: the root scan relies on both.

#include <vector>

#include "solvers/frobenius/frobenius_catenary.hpp"
#include "solvers/frobenius/frobenius_precision.hpp"

namespace catena::internal {

/// What one plane's boundary problem needs, in Gale's units (lengths in a = H/W0).
struct PlaneSetup {
  bool inplane = true;
  /// sigma = V/H at the two ends (sigma1 < sigma2).
  double sigma1 = 0.0;
  double sigma2 = 0.0;
  /// M/m: normal over tangential mass.
  double mu = 1.0;
  /// The largest |xi| the basis must reach (both ends, with a margin).
  double eta_max = 0.0;
  CatenarySeriesSettings settings;
};

/// The scaled boundary matrix and what it cost, in Real.
template <class Real>
struct BoundaryMatrix {
  /// a[row][column], columns divided by column_scale.
  std::vector<std::vector<Real>> a;
  /// Absolute error estimate of each entry of a (same scaling).
  std::vector<std::vector<Real>> error;
  std::vector<Real> column_scale;
  /// max_j (largest series term behind column j) / (column norm): digits lost to cancellation.
  double cancellation = 1.0;
  long terms = 0;
  int centres = 0;
  /// False when some series hit max_terms before its tail was below the term tolerance.
  bool converged = true;
};

/// The boundary matrix of `setup` at Omega = omega. Instantiated for double, long double and
/// QuadFloat.
template <class Real>
BoundaryMatrix<Real> boundary_matrix(const PlaneSetup& setup, const Real& omega);

/// Work done by the determinant evaluations of one plane, for its summary.
struct WorkCounter {
  long determinant_evaluations = 0;
  double cancellation = 1.0;
  long terms = 0;
  int centres = 0;
  bool truncated = false;
};

/// det of the scaled boundary matrix at Omega = omega, computed in precision `p` and rounded to
/// double; `work` gains the evaluation.
double scaled_determinant(Precision p, const PlaneSetup& setup, double omega, WorkCounter& work);

}  // namespace catena::internal
