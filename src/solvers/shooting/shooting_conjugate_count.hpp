// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Conjugate-point counting for the `shooting` solver (docs/explanation/methods/shooting.md): from
/// the end frame [Phi; F] of the principal solutions and the integrated phase theta = arg det(Phi +
/// i F), the number of conjugate points on (0, L] -- by Morse index theory (Sturm out of plane) the
/// number of eigenfrequencies below the trial frequency -- and the end eigen-angles that make the
/// count a continuous function of the frequency (Atkinson 1964, ch. 10; Pruefer's angle for D = 1).
///
/// For the Hamiltonian system Phi' = B F, F' = -C Phi with B >= 0, C > 0, Z = Phi + i F is
/// invertible, theta decreases monotonically, and the eigenvalues e^{i alpha_j} of the unitary
/// U = conj(Z) Z^{-1} turn counter-clockwise from -1 (alpha_j = pi). A conjugate point is an
/// eigenvalue of U passing -1, so with abar_j = alpha_j mapped into [pi, 3 pi)
///
///     N = [ (2 pi D - 2 theta) - sum_j abar_j ] / (2 pi)
///
/// is exactly an integer. theta is integrated along s (so it needs no unwrapping); only its winding
/// is taken from the integral, the fraction comes from arg det Z at the end.

#include <Eigen/Core>

namespace catena::internal {

template <int D>
using FrameBlock = Eigen::Matrix<double, D, D>;

/// What the end frame says about the trial frequency.
struct ConjugateCount {
  /// Conjugate points on (0, L]: eigenfrequencies below the trial frequency.
  int count = 0;
  /// Smallest and largest eigen-angle of U, in [pi, 3 pi) (shifted down by 1e-12 rad) [rad].
  double angle_min = 0.0;
  double angle_max = 0.0;
  /// |theta_integrated - theta_exact| [rad]: integration error of the phase (must be << pi).
  double phase_defect = 0.0;
  /// det Phi / sqrt(det G), G = Phi^T Phi + F^T F: invariant under Y -> Y R^{-1} (det R > 0), a
  /// smooth function of the frequency in [-1, 1], zero exactly at the natural frequencies.
  double determinant = 0.0;
};

/// theta of the principal solutions at the start, Phi = 0, F = I: arg det(i I).
double initial_phase(int dimension);

/// Eigen-angles of U = conj(Z) Z^{-1}, Z = Phi + i F, in [pi - 1e-12, 3 pi - 1e-12), ascending.
template <int D>
Eigen::Matrix<double, D, 1> unitary_angles(const FrameBlock<D>& Phi, const FrameBlock<D>& F);

/// arg det(Phi + i F) in (-pi, pi].
template <int D>
double frame_phase(const FrameBlock<D>& Phi, const FrameBlock<D>& F);

/// Count, eigen-angles, phase defect and normalised determinant of the end frame; D = 1 or 2.
template <int D>
ConjugateCount count_conjugate_points(const FrameBlock<D>& Phi,
                                      const FrameBlock<D>& F,
                                      double theta_integrated);

/// The count-aware root function of mode n (D = 1: Pruefer's continuous count):
///   h_n = (count - n) + (angle - pi) / (2 pi),
/// with the largest end angle below the n-th eigenvalue and the smallest at or above it. Its sign
/// certifies whether the n-th eigenvalue lies below the trial frequency.
double count_function(int count, double angle_min, double angle_max, int n);

}  // namespace catena::internal
