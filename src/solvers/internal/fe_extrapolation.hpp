#pragma once
/// \file
/// The `fe` solver's extrapolation (docs/methods/fe.md): modes paired across levels by their shapes
/// (largest MAC on the common nodes), Richardson in the mesh (order 2, mesh ratio 2:
/// omega = omega_2N + (omega_2N - omega_N) / 3; the error estimate is the difference from the
/// Richardson value on N/2, N where that mesh was solved and the frequencies show their order 2,
/// else the correction itself), linear
/// extrapolation in the penalty kappa to 0 for an inextensible cable (2 omega_kappa -
/// omega_2kappa), and the observed convergence order of the unextrapolated frequencies.

#include <Eigen/Dense>
#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "solvers/internal/fe_levels.hpp"

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
FeModeMatches match_level_modes(const FeLevels& levels, const FePlan& plan, Plane plane, int available);

/// omega[mesh][penalty] of reference mode i [rad/s], through the matches.
std::vector<std::vector<double>> level_omegas(const FeLevels& levels,
                                              const FeModeMatches& matches,
                                              Plane plane,
                                              int i);

/// A frequency extrapolated in the mesh (Richardson, when planned) and in kappa (inextensible).
struct FeExtrapolatedFrequency {
  double omega_rad_s = 0.0;
  /// Absolute error estimate [rad/s]: |R(N, 2N) - R(N/2, N)| with the estimate mesh N/2 where the
  /// unextrapolated frequencies converge at order 2 (within 0.25), else the Richardson correction;
  /// plus the kappa correction when penalised; -1 without a coarse mesh.
  double error_rad_s = -1.0;
};

/// Extrapolates one mode from its frequencies on every level, omega[mesh][penalty].
FeExtrapolatedFrequency extrapolate_frequency(const FePlan& plan,
                                              const std::vector<std::vector<double>>& omega);

/// Observed order p = log2((coarse - middle) / (middle - fine)) of three frequencies on meshes
/// N, 2N, 4N; 0 when the differences do not shrink monotonically.
double observed_order(double coarse, double middle, double fine);

/// Linear extrapolation to kappa = 0 of two normalised modes (a at kappa, b at 2 kappa): 2 a - b,
/// after aligning b to a by least squares (normalisation may pick a different peak of equal
/// height); renormalised.
void extrapolate_mode_in_kappa(Mode& a, const Mode& b);

}  // namespace catena::internal
