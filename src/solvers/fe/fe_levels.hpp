// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The `fe` solver's levels (docs/explanation/methods/fe.md): the plan of meshes (N and 2N for
/// Richardson, N/2 and N for an estimate without it, one finer mesh for an observed order) and
/// penalties (kappa and 2 kappa for an inextensible cable), and for every (mesh, penalty) pair its
/// discrete statics, its operators and its lowest eigenpairs (shift-invert, polish, inertia count).

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "catena/solvers/solver_summary.hpp"
#include "solvers/common/work_meter.hpp"
#include "solvers/fe/fe_chain_statics.hpp"
#include "solvers/fe/fe_eigen.hpp"
#include "solvers/fe/fe_line_mesh.hpp"
#include "solvers/fe/fe_operators.hpp"
#include "solvers/fe/fe_quadratic_eigen.hpp"

namespace catena {
struct FeSolverOptions;
}  // namespace catena

namespace catena::internal {

/// Wall time of each stage of one fe solve, summed over levels and planes [s].
struct FeTimings {
  double statics_s = 0.0;
  double assembly_s = 0.0;
  double factorization_s = 0.0;
  double eigen_iterations_s = 0.0;
  double postprocessing_s = 0.0;
  double forced_s = 0.0;
};

/// The most modes per plane a mesh of `elements` elements resolves: elements / 2. The chain's
/// n-th string mode is omega_n = (2 N c / L) sin(n pi / 2N), relative error 1 - sin(x)/x with
/// x = n pi / 2N: 10 % at n = N/2 (4 elements per wavelength), where Richardson's O(h^2) model
/// still holds, but 36 % at n = N, where the coarse mesh aliases the fine mesh's shapes (pairing
/// across meshes fails) and, for an inextensible cable, where the penalty's axial modes begin.
/// In plane the index counts both branches, so each branch stays within the bound.
int fe_resolvable_modes(int elements);

/// The largest penalty strain r = T/EA at 2 kappa, relative to the relative slack
/// (L - chord) / L, at which the penalised chain stands for an inextensible cable. The penalty
/// stretches the cable by about T/EA = kappa T/H; the sag, hence the tension and every frequency,
/// follows the slack that is left, so the penalty's relative effect is about r. Linear
/// extrapolation in kappa removes the first order; measured on a horizontal inextensible cable
/// (modes 1-2 in plane, 1 out of plane, against shooting) the error left is about 0.14 r^2
/// (r = 2e-3: 6e-7, 2e-2: 5e-5, 0.2: 4e-3) and the reported estimate covers it up to r = 0.7, not
/// at r = 2 (7e-2 and 2e-1 against estimates of 6e-2 and 1e-1) and far from it at r = 2e6
/// (chord = L (1 - 1e-12): 9x too low). 0.1 keeps a margin of 7 below where the estimate fails;
/// the suite's inextensible scenes reach r = 1.2e-2.
constexpr double kMaxPenaltyStrainOverSlack = 0.1;

/// The meshes and penalties of one solve.
struct FePlan {
  std::vector<int> meshes;  // ascending: the element counts of mesh_layouts
  /// Each mesh's pieces and element counts (fe_line_mesh.hpp): one piece for a uniform cable; on
  /// a line, each level doubles every piece's count of the one before.
  std::vector<FeLineMesh> mesh_layouts;
  int main_coarse = -1;  // index in meshes of the pair used for the result (-1: no coarse mesh)
  int main_fine = -1;
  /// With Richardson: index of the mesh half as fine as the main coarse one (-1: none). Its
  /// Richardson value against the main coarse mesh, compared with the result, gives the error
  /// estimate (fe_extrapolation.hpp).
  int estimate_coarse = -1;
  bool richardson = false;
  bool inextensible = false;
  std::vector<double> axial_stiffness_n;  // one per penalty (1 value when extensible)
  /// The largest extensible segment's EA on a line with inextensible segments too (else 0) [N]:
  /// it joins the penalty in the rounding floor.
  double stiffest_extensible_n = 0.0;
  /// The penalties kappa, 2 kappa (the result) and 4 kappa (its error estimate); inextensible only.
  std::vector<double> kappas;
  /// Inextensible only: the largest end tension over the penalty stiffness at 2 kappa,
  /// and the relative slack (L - |chord|) / L (see kMaxPenaltyStrainOverSlack).
  double penalty_strain = 0.0;
  double relative_slack = 0.0;

  bool has_coarse() const { return main_coarse >= 0; }
  bool has_estimate_mesh() const { return estimate_coarse >= 0; }
  int finest_elements() const { return meshes[static_cast<std::size_t>(main_fine)]; }
  std::size_t penalties() const { return axial_stiffness_n.size(); }

  /// Rounding floor of the in-plane chain, relative, for mode `mode_number`: K holds axial springs
  /// EA/l0 beside geometric ones T/l0, so an eigenvalue's backward error eps_mach ||K|| is,
  /// relative to omega_n^2, about eps_mach (EA/T0) N^2 / (pi n)^2 (half of that in omega), with EA
  /// the first penalty's stiffness. The frequencies are free of it (element-wise Rayleigh
  /// quotients: fe_rayleigh_quotient.hpp); it bounds the forced solve's rounding and decides when
  /// the in-plane plane is declined.
  double rounding_floor(double t0_n, int mode_number) const;
  /// Rounding of the discrete statics, relative, in every mode of both planes: the chain's closure
  /// sums N element chords, so its length is known to about eps L N at worst, which moves the
  /// tension by (EA/T0) eps N relative and every frequency by half that. Measured on a taut
  /// two-segment line (EA/T = 1e3, N = 2000): H off by 2e-11, the frequencies by 1.0e-11, bound
  /// 2.2e-10. Added to every estimate once the estimate mesh can make it the largest term, unless
  /// the end forces are prescribed (kept exactly: the chain's tension has no closure error).
  double statics_floor(double t0_n) const;
};

/// The normwise rounding floor of mode `mode_number` on a chain of `elements` elements whose
/// stiffest axial spring is `stiffness_ratio` times the tension scale: 1/2 eps (EA/T) N^2 / (pi
/// n)^2 (docs/explanation/methods/fe.md, "Rounding").
double normwise_rounding_floor(double stiffness_ratio, int elements, int mode_number);

/// Why the penalised chain cannot stand for this inextensible cable (its penalty strain is not
/// small against the slack); nullopt when it can, or when the cable is extensible.
std::optional<std::string> fe_penalty_not_applicable(const FePlan& plan);

/// The plan for `options`, with the modes asked per plane (the N/2 estimate mesh is used only
/// when it resolves them, fe_resolvable_modes). On a line, the coarsest mesh shares its elements
/// among the pieces (make_line_mesh) and the finer ones double each piece's count.
FePlan make_fe_plan(const Problem& problem,
                    const StaticSolution& statics,
                    const FeSolverOptions& options,
                    int max_modes_in_plane,
                    int max_modes_out_of_plane);

/// Everything computed for one (mesh, penalty) pair.
struct FeLevel {
  FeChain chain;
  std::map<Plane, FeMatrices> matrices;
  std::map<Plane, FeEigenSolution> eigen;
  /// Damped lines only (fe_damped_modes.hpp): the damping matrix and the damped eigenpairs.
  std::map<Plane, FeDampingMatrix> damping;
  std::map<Plane, FeDampedEigenSolution> damped;
};

/// levels[mesh][penalty], in the plan's order.
using FeLevels = std::vector<std::vector<FeLevel>>;

/// The discrete statics of every level. The first chain not in equilibrium (mesh-major order)
/// ends the work: `failure` gets its reason and the levels are incomplete.
FeLevels solve_level_statics(const Problem& problem,
                             const StaticSolution& statics,
                             const FePlan& plan,
                             FeTimings& timings,
                             std::string& failure);

/// What the eigen solves of one plane on every level add up to.
struct FePlaneEigenReport {
  Termination termination = Termination::Converged;
  long restarts = 0;
  long operations = 0;
  /// Over the converged levels: the largest relative residual (-1: none), mass-orthogonality error
  /// and normwise backward error.
  double max_residual = -1.0;
  double max_orthogonality_error = 0.0;
  double max_backward_error = 0.0;
  /// Each level's warnings and failures, prefixed "N = <elements>: ".
  std::vector<std::string> warnings;
};

/// Assembles the operators of `plane` and solves its lowest `modes` eigenpairs on every level.
/// A `meter` counts the levels solved; when it stops, the later levels are left unsolved.
FePlaneEigenReport solve_level_modes(FeLevels& levels,
                                     Plane plane,
                                     int modes,
                                     const FeSolverOptions& options,
                                     FeTimings& timings,
                                     WorkMeter* meter = nullptr);
/// Number of levels (eigen solves per plane).
long level_count(const FeLevels& levels);

/// The operators of `plane` on the levels that do not hold them yet, for mesh indices `meshes`.
void assemble_missing(FeLevels& levels, Plane plane, const std::vector<std::size_t>& meshes);

/// The number of modes every level delivered in `plane` (at most `modes`).
int modes_on_every_level(const FeLevels& levels, Plane plane, int modes);

/// True when, on every level, the inertia count equals the number of modes returned.
bool inertia_proved_on_every_level(const FeLevels& levels, Plane plane);

}  // namespace catena::internal
