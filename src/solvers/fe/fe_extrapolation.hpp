// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The `fe` solver's extrapolation (docs/explanation/methods/fe.md): modes paired across levels by
/// their shapes (largest MAC on the common nodes), Richardson in the mesh (order 2, mesh ratio 2:
/// omega = omega_2N + (omega_2N - omega_N) / 3; the error estimate from the three meshes N/2, N,
/// 2N by the observed order of the unextrapolated frequencies, else the correction itself), linear
/// extrapolation in the penalty kappa to 0 for an inextensible cable (2 omega_kappa - omega_2kappa,
/// its error from 4 kappa), and the observed convergence order of the unextrapolated frequencies.

#include <Eigen/Dense>
#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "solvers/fe/fe_levels.hpp"

namespace catena::internal {

/// For each reference mode (column of `reference`), the index of the mode of `other` with the
/// largest modal assurance criterion MAC = (a.b)^2 / (a.a b.b) on the common nodes, assigned
/// greedily from the best pair down (each mode used once). The meshes' element counts must
/// divide one another (they differ by powers of two), so the coarser mesh's nodes are common.
std::vector<int> match_modes(const Eigen::Ref<const Eigen::MatrixXd>& reference,
                             int reference_elements,
                             const Eigen::Ref<const Eigen::MatrixXd>& other,
                             int other_elements,
                             Plane plane);

/// matches[mesh][penalty][i]: the mode of that level paired with mode i of the reference level
/// (the finest main mesh, first penalty), for the lowest `available` modes of `plane`.
using FeModeMatches = std::vector<std::vector<std::vector<int>>>;
FeModeMatches match_level_modes(const FeLevels& levels,
                                const FePlan& plan,
                                Plane plane,
                                int available);

/// omega[mesh][penalty] of reference mode i [rad/s], through the matches.
std::vector<std::vector<double>> level_omegas(const FeLevels& levels,
                                              const FeModeMatches& matches,
                                              Plane plane,
                                              int i);

/// The rounding part of mode i's error estimate, relative to its frequency: the largest bound of
/// its levels' element-wise Rayleigh quotients (FeEigenSolution::rounding, relative on lambda =
/// omega^2, so halved) times what the extrapolations amplify a level's error by (Richardson in
/// the mesh 4/3 + 1/3, linear in kappa 2 + 1). 0 when a level carries no bound.
double rounding_estimate(
    const FePlan& plan, const FeLevels& levels, const FeModeMatches& matches, Plane plane, int i);

/// The error estimate of a Richardson value R(N, 2N) from the frequencies on N/2, N and 2N.
struct FeMeshEstimate {
  /// Absolute [rad/s]: |R(N, 2N) - R(N/2, N)| where the observed order p of the unextrapolated
  /// frequencies is within 0.25 of 2; the Richardson correction |omega_2N - omega_N| / 3 above;
  /// the fine mesh's error at the observed order plus that correction below
  /// (|omega_2N - omega_N| (1 / (2^p - 1) + 1 / 3)); 4/3 of the two differences' sum where they
  /// change sign (fe_extrapolation.cpp says why each bounds the error).
  double error = 0.0;
  /// p (0: the differences do not shrink monotonically).
  double observed_order = 0.0;
  /// True when p is below Richardson's 2 - 0.25 (or undefined): a term of lower order than the
  /// extrapolation assumes, which the estimate accounts for by the observed order.
  bool below_assumed_order = false;
};

/// The estimate from the three meshes (omega on N/2, N and 2N).
FeMeshEstimate mesh_estimate(double half, double coarse, double fine);

/// A frequency extrapolated in the mesh (Richardson, when planned) and in kappa (inextensible).
struct FeExtrapolatedFrequency {
  double omega_rad_s = 0.0;
  /// Absolute error estimate [rad/s]: mesh_estimate's with the estimate mesh N/2, else the
  /// Richardson correction; plus, when penalised, kappa_extrapolation_error (the kappa correction
  /// |w_kappa - w_2kappa| on a plan of two penalties); -1 without a coarse mesh.
  double error_rad_s = -1.0;
  /// mesh_estimate's observed order and flag at the first penalty (-1, false: no estimate mesh).
  double observed_order = -1.0;
  bool below_assumed_order = false;
};

/// Extrapolates one mode from its frequencies on every level, omega[mesh][penalty].
FeExtrapolatedFrequency extrapolate_frequency(const FePlan& plan,
                                              const std::vector<std::vector<double>>& omega);

/// The error estimate of the linear extrapolation 2 a - b to kappa = 0 from the values at kappa,
/// 2 kappa and 4 kappa: twice its distance from the quadratic through the three,
/// |(8 a - 6 b + c) / 3 - (2 a - b)| = |2 a - 3 b + c| / 3, which is the linear value's leading
/// O(kappa^2) error exactly (w = w0 + A kappa + B kappa^2: 2 B kappa^2 both); the factor 2 covers
/// the next term. Before the third penalty the estimate was the correction |a - b| itself, which
/// bounds the unextrapolated error, not the extrapolated one.
double kappa_extrapolation_error(double at_kappa, double at_2kappa, double at_4kappa);

/// Observed order p = log2((coarse - middle) / (middle - fine)) of three frequencies on meshes
/// N, 2N, 4N; 0 when the differences do not shrink monotonically.
double observed_order(double coarse, double middle, double fine);

/// Linear extrapolation to kappa = 0 of two normalised modes (a at kappa, b at 2 kappa): 2 a - b,
/// after aligning b to a by least squares (normalisation may pick a different peak of equal
/// height); renormalised.
void extrapolate_mode_in_kappa(Mode& a, const Mode& b);

}  // namespace catena::internal
