#pragma once
/// \file
/// Building blocks of the `fe` solver (see include/catena/solvers/fe_solver.hpp for the method):
/// the discrete chain's statics, the sparse stiffness and mass matrices, and the shift-invert
/// eigen solve with its Sylvester-inertia mode count. Exposed for the tests and benchmarks.

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <string>
#include <vector>

#include "catena/models/cable.hpp"
#include "catena/solvers/solver_summary.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::internal {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// The discrete chain in equilibrium.
struct FeChain {
  int elements = 0;
  /// Unstretched element length l0 = L/N [m].
  double element_length_m = 0.0;
  /// Axial stiffness used (the penalty H/kappa for an inextensible cable) [N].
  double axial_stiffness_n = 0.0;
  double mass_kg_per_m = 0.0;
  double normal_mass_kg_per_m = 0.0;
  /// Support force (H, V_A) of the chain [N].
  double horizontal_force_n = 0.0;
  double vertical_force_a_n = 0.0;
  /// Per element j = 0..N-1: tension T_j [N], unit direction t_j, stretched length l_j [m].
  Vector tension_n;
  std::vector<Vec2> direction;
  Vector stretched_length_m;
  /// Node positions relative to support a, N + 1 of them [m].
  std::vector<Vec2> node_offset_m;
  /// Newton iterations of the discrete statics (0 for prescribed forces) and the closure error
  /// |r_N - (B - A)| [m].
  int newton_iterations = 0;
  double closure_error_m = 0.0;
};

/// Solves the discrete statics with N elements and axial stiffness EA (finite) [N].
/// Throws std::runtime_error when Newton fails or a tension is not positive (the caller reports it
/// as a numerical failure).
FeChain solve_chain_statics(const Problem& problem,
                            const StaticSolution& statics,
                            int elements,
                            double axial_stiffness_n);

/// Stiffness and mass of one plane on the free (interior) nodes.
struct FeMatrices {
  /// Unknowns per node: 2 in plane (x, z), 1 out of plane.
  int dofs_per_node = 2;
  SparseMatrix stiffness;
  SparseMatrix mass;
  /// Coupling K_ib of the free unknowns to the end node's unknowns (columns: node a then node b,
  /// dofs_per_node each), for the forced response.
  SparseMatrix boundary_coupling;
};

FeMatrices assemble_inplane(const FeChain& chain);
FeMatrices assemble_outofplane(const FeChain& chain);

/// The lowest eigenpairs of K phi = lambda M phi, lambda = omega^2.
struct FeEigenSolution {
  Termination termination = Termination::NumericalFailure;
  std::string message;
  /// Ascending eigenvalues lambda [rad^2/s^2] and M-orthonormal eigenvectors (columns).
  Vector eigenvalues;
  Eigen::MatrixXd eigenvectors;
  /// Negative pivots of LDLT(K - sigma_top M) with sigma_top just above the top eigenvalue.
  int inertia_count = -1;
  double inertia_shift = 0.0;
  /// max_i ||K phi_i - lambda_i M phi_i|| / ||K phi_i|| and max_{i != j} |phi_i^T M phi_j| for the
  /// M-normalised vectors.
  double max_residual = 0.0;
  double max_orthogonality_error = 0.0;
  /// Normwise backward error max_i ||K phi_i - lambda_i M phi_i|| / ((||K||_1 + lambda_i ||M||_1)
  /// ||phi_i||): unlike the relative residual above, whose rounding floor is
  /// eps ||K|| / ||K phi|| ~ eps (EA/T) (2N/pi n)^2 for a stiff chain, this one reaches ~eps.
  double max_backward_error = 0.0;
  long restarts = 0;
  long operations = 0;
  /// Wall time of the factorisation (including the inertia one) and of the iterations [s].
  double factorization_time_s = 0.0;
  double iteration_time_s = 0.0;
  std::vector<std::string> warnings;
};

/// Lowest `modes` eigenpairs. `modes` must be < number of unknowns (the caller validates).
FeEigenSolution solve_lowest_modes(const FeMatrices& matrices,
                                   int modes,
                                   double tolerance,
                                   int max_restarts);

/// Number of eigenvalues of K phi = lambda M phi below `shift` (negative pivots of
/// LDLT(K - shift M)); -1 when the factorisation fails.
int count_eigenvalues_below(const FeMatrices& matrices, double shift);

}  // namespace catena::internal

namespace catena {
struct FeSolverOptions;
struct SolverOutput;
struct SolveRequest;
struct DimensionlessGroups;
}  // namespace catena

namespace catena::internal {

/// Wall time of each stage of one solve_fe call, summed over meshes and planes [s].
struct FeTimings {
  double statics_s = 0.0;
  double assembly_s = 0.0;
  double factorization_s = 0.0;
  double eigen_iterations_s = 0.0;
  double postprocessing_s = 0.0;
  double forced_s = 0.0;
};

/// solve_fe, also returning the time split (benchmarks).
SolverOutput solve_fe_timed(const Problem& problem,
                            const StaticSolution& statics,
                            const DimensionlessGroups& groups,
                            const SolveRequest& request,
                            const FeSolverOptions& options,
                            FeTimings& timings);

}  // namespace catena::internal
