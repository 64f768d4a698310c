// SPDX-License-Identifier: MIT
// The fe solver's plan and levels: see fe_levels.hpp and docs/explanation/methods/fe.md.
#include "solvers/fe/fe_levels.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "catena/core/types.hpp"
#include "catena/solvers/fe_solver.hpp"
#include "solvers/fe/fe_rayleigh_quotient.hpp"

namespace catena::internal {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The meshes: N and 2N with Richardson; otherwise N alone, with N/2 for the error estimate when it
// resolves the modes asked. observed_order adds one mesh twice as fine as the finest.
void plan_meshes(FePlan& plan,
                 const FeSolverOptions& options,
                 int max_modes_in_plane,
                 int max_modes_out_of_plane) {
  const int N = options.elements;
  auto fits = [&](int elements) {
    return elements >= 2 &&
           fe_resolvable_modes(elements) >= std::max(max_modes_in_plane, max_modes_out_of_plane);
  };
  if (options.richardson) {
    plan.meshes = {N, 2 * N};
    plan.main_coarse = 0;
    plan.main_fine = 1;
    plan.richardson = true;
    if (options.observed_order) plan.meshes.push_back(4 * N);
  } else {
    if (fits(N / 2)) {
      plan.meshes = {N / 2, N};
      plan.main_coarse = 0;
      plan.main_fine = 1;
    } else {
      plan.meshes = {N};
      plan.main_fine = 0;
    }
    if (options.observed_order) plan.meshes.push_back(2 * N);
  }
}

// The penalty's largest strain (at 2 kappa) and the relative slack it competes with. On a line the
// largest tension may be at a joint or point (a buoy), so every piece's start counts too.
void plan_penalty_strain(FePlan& plan, const Problem& problem, const StaticSolution& statics) {
  const double L = problem.length_m();
  const Vec2 chord = problem.supports.chord_m();
  plan.relative_slack = (L - std::hypot(chord.x(), chord.y())) / L;
  double largest_tension = std::max(statics.tension_n(0.0), statics.tension_n(L));
  for (const StaticPiece& piece : statics.pieces())
    largest_tension = std::max({largest_tension, statics.tension_n(piece.s_begin_m),
                                std::hypot(statics.horizontal_force_n(),
                                           statics.vertical_force_before_n(piece.s_begin_m))});
  plan.penalty_strain = largest_tension / plan.axial_stiffness_n[1];  // at 2 kappa
}

// Each mesh's layout; on a line the counts of the finer meshes are doubled from the coarsest, and
// `meshes` becomes their totals (a piece too short for its share gets one element anyway). With
// Richardson every piece of the coarsest mesh gets an even count, so that the estimate mesh can
// halve it (plan_estimate_mesh: an odd piece, e.g. a seabed layer's, left the estimate at the
// Richardson correction, 1e-7 to 1e-6 for errors near 1e-10).
void plan_layouts(FePlan& plan, const Problem& problem, const StaticSolution& statics) {
  if (meshed_as_one_piece(problem, statics)) {
    for (int elements : plan.meshes)
      plan.mesh_layouts.push_back(uniform_cable_mesh(problem.cable, elements));
    return;
  }
  FeLineMesh coarsest = make_line_mesh(problem, statics, plan.meshes.front());
  if (plan.richardson) coarsest = coarsest.evened();
  for (std::size_t m = 0; m < plan.meshes.size(); ++m) {
    plan.mesh_layouts.push_back(coarsest.refined(1 << m));
    plan.meshes[m] = plan.mesh_layouts.back().elements();
  }
}

// With Richardson, the mesh N/2 in front of N and 2N when it resolves the modes asked and halves
// every piece of N (the result's meshes stay as they were): it makes the error estimate the
// difference of two extrapolated values rather than the Richardson correction, which bounds the
// unextrapolated error and overstated the result's by 3-4 orders (docs/explanation/methods/fe.md).
void plan_estimate_mesh(FePlan& plan, int max_modes) {
  if (!plan.richardson || !plan.has_coarse()) return;
  const auto coarse = static_cast<std::size_t>(plan.main_coarse);
  const std::optional<FeLineMesh> half = plan.mesh_layouts[coarse].halved();
  if (!half || half->elements() < 2 || fe_resolvable_modes(half->elements()) < max_modes) return;
  plan.meshes.insert(plan.meshes.begin(), half->elements());
  plan.mesh_layouts.insert(plan.mesh_layouts.begin(), *half);
  plan.estimate_coarse = 0;
  plan.main_coarse += 1;
  plan.main_fine += 1;
}

// Inextensible: the penalty EA = H / kappa on the inextensible segments, with the larger end
// tension for a vertical chord (H = 0). Extensible: the stiffest segment's EA.
void plan_penalties(FePlan& plan,
                    const Problem& problem,
                    const StaticSolution& statics,
                    double kappa) {
  const Line line = problem.as_line();
  double stiffest = 0.0;
  for (const LineSegment& segment : line.segments) {
    plan.inextensible = plan.inextensible || segment.is_inextensible();
    if (!segment.is_inextensible()) stiffest = std::max(stiffest, segment.axial_stiffness_n);
  }
  if (!plan.inextensible) {
    plan.axial_stiffness_n = {stiffest};
    return;
  }
  plan.stiffest_extensible_n = stiffest;
  double reference = statics.horizontal_force_n();
  if (!(reference > 0.0))
    reference = std::max(statics.tension_n(0.0), statics.tension_n(problem.length_m()));
  // kappa and 2 kappa give the result (linear extrapolation); 4 kappa its error estimate: the
  // quadratic through the three, whose distance from the linear one is the latter's leading
  // O(kappa^2) error (fe_extrapolation.hpp).
  plan.kappas = {kappa, 2.0 * kappa, 4.0 * kappa};
  for (double k : plan.kappas) plan.axial_stiffness_n.push_back(reference / k);
  plan_penalty_strain(plan, problem, statics);
}

}  // namespace

int fe_resolvable_modes(int elements) { return elements / 2; }

std::optional<std::string> fe_penalty_not_applicable(const FePlan& plan) {
  if (!plan.inextensible) return std::nullopt;
  const double ratio = plan.penalty_strain / plan.relative_slack;
  if (plan.relative_slack > 0.0 && ratio <= kMaxPenaltyStrainOverSlack) return std::nullopt;
  return fmt::format(
      "inextensible cable too close to taut for the penalty: the penalty strain T/EA = {:.3g} (at "
      "2 kappa = {:.3g}) "
      "is not small against the relative slack (L - chord)/L = {:.3g} (ratio {:.3g} > {:g}), so "
      "the penalised "
      "chain's sag and tension are not the inextensible cable's; a kappa below {:.3g} would be "
      "needed, where the "
      "stiff penalty springs' rounding error grows like 1/kappa",
      plan.penalty_strain, plan.kappas[1], plan.relative_slack, ratio, kMaxPenaltyStrainOverSlack,
      plan.kappas.front() * kMaxPenaltyStrainOverSlack / std::max(ratio, 1e-300));
}

double FePlan::statics_floor(double t0_n) const {
  const double stiffness_ratio =
      std::max(axial_stiffness_n[0], stiffest_extensible_n) / std::max(t0_n, 1e-300);
  return 0.5 * std::numeric_limits<double>::epsilon() * stiffness_ratio *
         static_cast<double>(finest_elements());
}

double FePlan::rounding_floor(double t0_n, int mode_number) const {
  const double stiffness_ratio =
      std::max(axial_stiffness_n[0], stiffest_extensible_n) / std::max(t0_n, 1e-300);
  return normwise_rounding_floor(stiffness_ratio, finest_elements(), mode_number);
}

double normwise_rounding_floor(double stiffness_ratio, int elements, int mode_number) {
  const double n = static_cast<double>(mode_number);
  const auto N = static_cast<double>(elements);
  return 0.5 * std::numeric_limits<double>::epsilon() * stiffness_ratio * N * N /
         (kPi * kPi * n * n);
}

FePlan make_fe_plan(const Problem& problem,
                    const StaticSolution& statics,
                    const FeSolverOptions& options,
                    int max_modes_in_plane,
                    int max_modes_out_of_plane) {
  FePlan plan;
  plan_meshes(plan, options, max_modes_in_plane, max_modes_out_of_plane);
  plan_layouts(plan, problem, statics);
  plan_estimate_mesh(plan, std::max(max_modes_in_plane, max_modes_out_of_plane));
  plan_penalties(plan, problem, statics, options.kappa);
  return plan;
}

FeLevels solve_level_statics(const Problem& problem,
                             const StaticSolution& statics,
                             const FePlan& plan,
                             FeTimings& timings,
                             std::string& failure) {
  FeLevels levels(plan.meshes.size(), std::vector<FeLevel>(plan.penalties()));
  for (std::size_t m = 0; m < plan.meshes.size(); ++m) {
    for (std::size_t k = 0; k < plan.penalties(); ++k) {
      const auto start = Clock::now();
      levels[m][k].chain =
          solve_chain_statics(problem, statics, plan.mesh_layouts[m], plan.axial_stiffness_n[k]);
      timings.statics_s += seconds_since(start);
      if (!levels[m][k].chain.in_equilibrium()) {
        failure = levels[m][k].chain.failure;
        return levels;
      }
    }
  }
  return levels;
}

namespace {

// Above this normwise floor of mode 1 (FePlan::rounding_floor, from the level's own chain) the
// vectors get a last Rayleigh-Ritz step with the element-wise projected stiffness: the normwise
// one leaves them mixed with the neighbouring modes by about floor x lambda / gap, which shows in
// the quotients at second order (docs/explanation/methods/fe.md, "Rounding"; stress-eps at eps =
// 1e-4: 6e-8).
constexpr double kStructuredRitzFloor = 1e-7;

bool needs_structured_ritz(const FeChain& chain, Plane plane) {
  if (plane != Plane::InPlane) return false;           // no axial springs out of plane
  if (!(chain.horizontal_force_n > 0.0)) return true;  // no tension scale
  const double stiffness_ratio = chain.axial_stiffness_n.maxCoeff() / chain.horizontal_force_n;
  return normwise_rounding_floor(stiffness_ratio, chain.elements, 1) > kStructuredRitzFloor;
}

// Each eigenvalue of a converged level replaced by its mode's element-wise Rayleigh quotient,
// whose rounding is bounded without the normwise floor (fe_rayleigh_quotient.hpp), after the
// structured Rayleigh-Ritz step where the chain is stiff.
void use_element_rayleigh_quotients(const FeChain& chain,
                                    Plane plane,
                                    const FeMatrices& matrices,
                                    FeEigenSolution& eigen) {
  if (needs_structured_ritz(chain, plane))
    element_rayleigh_ritz(chain, plane, eigen.eigenvectors, matrices.mass);
  eigen.rounding.resize(eigen.eigenvalues.size());
  for (Eigen::Index i = 0; i < eigen.eigenvalues.size(); ++i) {
    const RayleighQuotient q =
        element_rayleigh_quotient(chain, plane, eigen.eigenvectors.col(i), matrices.mass);
    eigen.eigenvalues[i] = q.value;
    eigen.rounding[i] = q.relative_rounding;
  }
}

}  // namespace

FePlaneEigenReport solve_level_modes(FeLevels& levels,
                                     Plane plane,
                                     int modes,
                                     const FeSolverOptions& options,
                                     FeTimings& timings,
                                     WorkMeter* meter) {
  FePlaneEigenReport report;
  long solved = 0;
  FeEigenWorkspace workspace;                 // one banded factor for every level of this plane
  const FeEigenSolution* previous = nullptr;  // the last converged level: its modes start the next
  if (meter) workspace.should_stop = [meter] { return meter->expired(); };
  for (auto& row : levels) {
    for (FeLevel& level : row) {
      const auto start = Clock::now();
      level.matrices[plane] = assemble(plane, level.chain);
      timings.assembly_s += seconds_since(start);
      const FeMatrices& matrices = level.matrices[plane];
      const Vector guess = previous ? mode_sum_guess(previous->eigenvectors, matrices.dofs_per_node,
                                                     matrices.mass.rows())
                                    : Vector();
      FeEigenSolution eigen =
          solve_lowest_modes(matrices, modes, options.eigen_tolerance, options.max_restarts,
                             &workspace, guess.size() > 0 ? &guess : nullptr);
      timings.factorization_s += eigen.factorization_time_s;
      timings.eigen_iterations_s += eigen.iteration_time_s;
      report.restarts += eigen.restarts;
      report.operations += eigen.operations;
      const int N = level.chain.elements;
      for (const auto& warning : eigen.warnings)
        report.warnings.push_back(fmt::format("N = {}: {}", N, warning));
      if (eigen.termination != Termination::Converged) {
        // A numerical failure on any level outweighs a level that did not converge.
        if (report.termination != Termination::NumericalFailure)
          report.termination = eigen.termination;
        report.warnings.push_back(fmt::format("N = {}: {}", N, eigen.message));
      } else {
        report.max_residual = std::max(report.max_residual, eigen.max_residual);
        report.max_orthogonality_error =
            std::max(report.max_orthogonality_error, eigen.max_orthogonality_error);
        report.max_backward_error = std::max(report.max_backward_error, eigen.max_backward_error);
      }
      if (eigen.termination == Termination::Converged)
        use_element_rayleigh_quotients(level.chain, plane, matrices, eigen);
      level.eigen[plane] = std::move(eigen);
      if (level.eigen[plane].termination == Termination::Converged) previous = &level.eigen[plane];
      if (meter && meter->stop_after(++solved)) return report;
    }
  }
  return report;
}

long level_count(const FeLevels& levels) {
  long count = 0;
  for (const auto& row : levels) count += static_cast<long>(row.size());
  return count;
}

void assemble_missing(FeLevels& levels, Plane plane, const std::vector<std::size_t>& meshes) {
  for (std::size_t m : meshes) {
    for (FeLevel& level : levels[m]) {
      if (!level.matrices.count(plane)) level.matrices[plane] = assemble(plane, level.chain);
    }
  }
}

int modes_on_every_level(const FeLevels& levels, Plane plane, int modes) {
  int available = modes;
  for (const auto& row : levels)
    for (const FeLevel& level : row)
      available = std::min(available, static_cast<int>(level.eigen.at(plane).eigenvalues.size()));
  return available;
}

bool inertia_proved_on_every_level(const FeLevels& levels, Plane plane) {
  bool all_proved = true;
  for (const auto& row : levels)
    for (const FeLevel& level : row)
      all_proved = all_proved && level.eigen.at(plane).inertia_count ==
                                     static_cast<int>(level.eigen.at(plane).eigenvalues.size());
  return all_proved;
}

}  // namespace catena::internal
