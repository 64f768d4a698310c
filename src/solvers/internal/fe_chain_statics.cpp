// Discrete statics of the fe chain: see fe_chain_statics.hpp and docs/methods/fe.md.
#include "solvers/internal/fe_chain_statics.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace catena::internal {
namespace {

// Fills the per-element forces, lengths and node positions of a chain with support forces (H, V_A).
void build_chain(FeChain& chain, double H, double V_A, double W0) {
  const int N = chain.elements;
  const double l0 = chain.element_length_m;
  chain.horizontal_force_n = H;
  chain.vertical_force_a_n = V_A;
  chain.tension_n.resize(N);
  chain.stretched_length_m.resize(N);
  chain.direction.resize(static_cast<std::size_t>(N));
  chain.node_offset_m.assign(static_cast<std::size_t>(N) + 1, Vec2::Zero());
  for (int j = 0; j < N; ++j) {
    // Half of node 0's weight goes into support a, so element j carries the continuous force at
    // its midpoint s = (j + 1/2) l0.
    const double V = V_A + W0 * l0 * (j + 0.5);
    const double T = std::hypot(H, V);
    chain.tension_n[j] = T;
    chain.direction[static_cast<std::size_t>(j)] = T > 0.0 ? Vec2(H / T, V / T) : Vec2(0.0, 1.0);
    chain.stretched_length_m[j] = l0 * (1.0 + T / chain.axial_stiffness_n);
    chain.node_offset_m[static_cast<std::size_t>(j) + 1] =
        chain.node_offset_m[static_cast<std::size_t>(j)] +
        chain.stretched_length_m[j] * chain.direction[static_cast<std::size_t>(j)];
  }
}

// d(r_N)/d(H, V_A) = sum_j l0 [(I - t t^T)/T + I/EA] (symmetric).
Eigen::Matrix2d closure_jacobian(const FeChain& chain) {
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  const double l0 = chain.element_length_m;
  for (int j = 0; j < chain.elements; ++j) {
    const Vec2& t = chain.direction[static_cast<std::size_t>(j)];
    J += l0 * ((Eigen::Matrix2d::Identity() - t * t.transpose()) / chain.tension_n[j] +
               Eigen::Matrix2d::Identity() / chain.axial_stiffness_n);
  }
  return J;
}

// Newton on the closure r_N(H, V_A) = B - A from the continuous statics' support force, with
// backtracking that keeps H positive and the residual decreasing. Sets `failure` when the chain
// does not close to 1e-9 of its size.
void close_chain(FeChain& chain, const Problem& problem, const StaticSolution& statics) {
  const CableProperties& cable = problem.cable;
  const double W0 = cable.weight_n_per_m;
  const Vec2 chord = problem.supports.chord_m();
  double H = statics.horizontal_force_n();
  double V_A = statics.vertical_force_a_n();
  const bool vertical = H == 0.0;
  const double tolerance = 1e-14 * std::max(cable.length_m, chord.norm());
  build_chain(chain, H, V_A, W0);
  Vec2 residual = chain.node_offset_m.back() - chord;
  int iteration = 0;
  for (; iteration < 100 && residual.norm() > tolerance; ++iteration) {
    const Eigen::Matrix2d J = closure_jacobian(chain);
    const Vec2 step = vertical ? Vec2(0.0, -residual.y() / J(1, 1)) : Vec2(-J.ldlt().solve(residual));
    double alpha = 1.0;
    FeChain trial = chain;
    for (int k = 0; k < 40; ++k, alpha *= 0.5) {
      const double H_trial = H + alpha * step.x();
      if (!vertical && H_trial <= 0.0) continue;
      build_chain(trial, H_trial, V_A + alpha * step.y(), W0);
      if ((trial.node_offset_m.back() - chord).norm() < residual.norm() || k == 39) break;
    }
    H = trial.horizontal_force_n;
    V_A = trial.vertical_force_a_n;
    chain = std::move(trial);
    const Vec2 next = chain.node_offset_m.back() - chord;
    const bool stalled = next.norm() >= residual.norm() && next.norm() > tolerance;
    residual = next;
    // No further progress: accept the rounding floor if it is close, else fail below.
    if (stalled) break;
  }
  chain.newton_iterations = iteration;
  if (!(residual.norm() <= 1e-9 * std::max(cable.length_m, chord.norm()))) {
    chain.failure = fmt::format(
        "discrete statics (N = {}) did not close: |r_N - (B - A)| = {:.3e} m after {} Newton "
        "iterations",
        chain.elements, residual.norm(), iteration);
  }
}

}  // namespace

FeChain solve_chain_statics(const Problem& problem,
                            const StaticSolution& statics,
                            int elements,
                            double axial_stiffness_n) {
  const CableProperties& cable = problem.cable;
  FeChain chain;
  chain.elements = elements;
  chain.element_length_m = cable.length_m / elements;
  chain.axial_stiffness_n = axial_stiffness_n;
  chain.mass_kg_per_m = cable.mass_kg_per_m;
  chain.normal_mass_kg_per_m = cable.normal_mass_kg_per_m();
  if (problem.prescribed_forces) {
    // Tension-specified problems keep their forces: re-solving them from the geometry would
    // determine the tension of a taut cable only to ~ rounding / strain (see Problem).
    build_chain(chain, problem.prescribed_forces->horizontal_n,
                problem.prescribed_forces->vertical_a_n, cable.weight_n_per_m);
  } else {
    close_chain(chain, problem, statics);
    if (!chain.in_equilibrium()) return chain;
  }
  chain.closure_error_m = (chain.node_offset_m.back() - problem.supports.chord_m()).norm();
  for (int j = 0; j < elements; ++j) {
    if (!(chain.tension_n[j] > 0.0) || !std::isfinite(chain.tension_n[j])) {
      chain.failure = fmt::format(
          "discrete statics (N = {}): tension {:.3e} N in element {} is not positive: the chain "
          "is slack there",
          elements, chain.tension_n[j], j);
      return chain;
    }
  }
  return chain;
}

}  // namespace catena::internal
