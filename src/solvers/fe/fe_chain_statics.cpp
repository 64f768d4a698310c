// SPDX-License-Identifier: MIT
// Discrete statics of the fe chain: see fe_chain_statics.hpp and docs/explanation/methods/fe.md.
#include "solvers/fe/fe_chain_statics.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <utility>

namespace catena::internal {
namespace {

// The vertical force at each element's midpoint minus V_A: half of node 0's weight goes into
// support a, and each interior node carries half of each neighbouring element's weight plus the
// weight of a point attachment there (docs/explanation/methods/fe.md). One piece keeps the closed
// form W0 l0 (j + 1/2).
void lump_weights(FeChain& chain, const FeLineMesh& mesh) {
  const int N = chain.elements;
  chain.vertical_offset_n.resize(N);
  if (mesh.is_one_piece()) {
    const double W0 = mesh.pieces.front().section.weight_n_per_m;
    const double l0 = chain.element_length_m[0];
    for (int j = 0; j < N; ++j) chain.vertical_offset_n[j] = W0 * l0 * (j + 0.5);
    return;
  }
  // Within a piece the closed form from the piece's start, so that rounding does not accumulate
  // element by element.
  // With seabed contact the grounded weight (with a point at the touchdown point, as in the
  // statics) rests on the seabed: the suspended part counts from the touchdown node.
  double before = 0.0;  // weight from s = 0 to the start of the piece (after a point there)
  int j = 0;
  bool after_grounded = false;
  for (const FeMeshPiece& piece : mesh.pieces) {
    if (piece.grounded) {
      for (int k = 0; k < piece.elements; ++k, ++j) chain.vertical_offset_n[j] = 0.0;
      after_grounded = true;
      continue;
    }
    if (piece.point_at_start >= 0 && !after_grounded)
      before += mesh.points[static_cast<std::size_t>(piece.point_at_start)].weight_n;
    after_grounded = false;
    const double W0 = piece.section.weight_n_per_m;
    const double l0 = chain.element_length_m[j];
    for (int k = 0; k < piece.elements; ++k, ++j)
      chain.vertical_offset_n[j] = before + W0 * l0 * (k + 0.5);
    before += W0 * piece.section.length_m;
  }
}

// The grounded elements (the mesh's grounded pieces come first) and their static tension relative
// to the continuous H: the friction profile at each element's midpoint
// (docs/explanation/physics.md, "Seabed contact"), which is linear on a piece, so the midpoint
// value is the element's mean tension.
void lay_out_contact(FeChain& chain, const FeLineMesh& mesh, double continuous_horizontal_force_n) {
  chain.grounded_tension_offset_n.resize(0);
  if (!mesh.seabed) return;
  chain.foundation_vertical_n_per_m2 = mesh.seabed->stiffness_n_per_m2;
  chain.foundation_tangential_n_per_m2 = mesh.seabed->tangential_stiffness_n_per_m2;
  chain.foundation_damping_n_s_per_m2 = mesh.seabed->damping_n_s_per_m2;
  std::vector<double> offsets;
  for (const FeMeshPiece& piece : mesh.pieces) {
    if (!piece.grounded) break;
    const double l0 = piece.section.length_m / piece.elements;
    const double slope = piece.grounded_tension_slope_n_per_m;
    for (int k = 0; k < piece.elements; ++k)
      offsets.push_back(piece.grounded_tension_begin_n + slope * l0 * (k + 0.5) -
                        continuous_horizontal_force_n);
  }
  chain.grounded_elements = static_cast<int>(offsets.size());
  chain.grounded_tension_offset_n =
      Eigen::Map<const Vector>(offsets.data(), chain.grounded_elements);
}

// The sections of the elements, the nodes' arc lengths and point inertias, and the lumped weights.
void lay_out_chain(FeChain& chain,
                   const FeLineMesh& mesh,
                   double penalty_axial_stiffness_n,
                   double continuous_h_n) {
  const int N = mesh.elements();
  chain.elements = N;
  chain.equal_elements = mesh.is_one_piece();
  chain.element_length_m.resize(N);
  chain.axial_stiffness_n.resize(N);
  chain.tangential_mass_kg_per_m.resize(N);
  chain.normal_mass_kg_per_m.resize(N);
  chain.tangential_damping_n_s_per_m2.resize(N);
  chain.normal_damping_n_s_per_m2.resize(N);
  chain.axial_damping_n_s.resize(N);
  chain.node_s_m.resize(N + 1);
  chain.node_inertia.assign(static_cast<std::size_t>(N) + 1, FeNodeInertia{});
  int j = 0;
  double s = 0.0;
  chain.piece_first_element.clear();
  for (const FeMeshPiece& piece : mesh.pieces) {
    chain.piece_first_element.push_back(j);
    if (piece.point_at_start >= 0) {
      const PointAttachment& point = mesh.points[static_cast<std::size_t>(piece.point_at_start)];
      chain.node_inertia[static_cast<std::size_t>(j)] = {
          point.mass_kg + point.tangential_added_mass_kg(),
          point.mass_kg + point.normal_added_mass_kg(),
          point.mass_kg + point.outofplane_added_mass_kg(), true};
    }
    const LineSegment& section = piece.section;
    const double l0 = section.length_m / piece.elements;
    for (int k = 0; k < piece.elements; ++k, ++j) {
      chain.element_length_m[j] = l0;
      chain.axial_stiffness_n[j] =
          section.is_inextensible() ? penalty_axial_stiffness_n : section.axial_stiffness_n;
      chain.tangential_mass_kg_per_m[j] = section.tangential_mass_kg_per_m();
      chain.normal_mass_kg_per_m[j] = section.normal_mass_kg_per_m();
      chain.tangential_damping_n_s_per_m2[j] = section.damping.tangential_n_s_per_m2;
      chain.normal_damping_n_s_per_m2[j] = section.damping.normal_n_s_per_m2;
      chain.axial_damping_n_s[j] = section.damping.axial_n_s;
      chain.node_s_m[j] = s + k * l0;
    }
    s += section.length_m;
  }
  chain.node_s_m[N] = s;
  lump_weights(chain, mesh);
  lay_out_contact(chain, mesh, continuous_h_n);
}

// Element j's tension and unit direction under support forces (H, V_A).
std::pair<double, Vec2> element_force(const FeChain& chain, int j, double H, double V_A) {
  if (j < chain.grounded_elements) {
    // On the seabed: horizontal, with the friction profile (lay_out_contact).
    return {std::max(H + chain.grounded_tension_offset_n[j], 0.0), Vec2(1.0, 0.0)};
  }
  // Element j carries the continuous force at its midpoint (see lump_weights).
  const double V = V_A + chain.vertical_offset_n[j];
  const double T = std::hypot(H, V);
  return {T, T > 0.0 ? Vec2(H / T, V / T) : Vec2(0.0, 1.0)};
}

// Fills the per-element forces, lengths and node positions of a chain with support forces (H, V_A).
void build_chain(FeChain& chain, double H, double V_A) {
  const int N = chain.elements;
  chain.horizontal_force_n = H;
  chain.vertical_force_a_n = V_A;
  chain.tension_n.resize(N);
  chain.stretched_length_m.resize(N);
  chain.direction.resize(static_cast<std::size_t>(N));
  chain.node_offset_m.resize(static_cast<std::size_t>(N) + 1);
  chain.node_offset_m.front() = Vec2::Zero();
  for (int j = 0; j < N; ++j) {
    const auto [T, t] = element_force(chain, j, H, V_A);
    chain.tension_n[j] = T;
    chain.direction[static_cast<std::size_t>(j)] = t;
    chain.stretched_length_m[j] =
        chain.element_length_m[j] * (1.0 + T / chain.axial_stiffness_n[j]);
    chain.node_offset_m[static_cast<std::size_t>(j) + 1] =
        chain.node_offset_m[static_cast<std::size_t>(j)] + chain.stretched_length_m[j] * t;
  }
}

// The last node's offset under (H, V_A), computed as build_chain computes it (the same operations
// in the same order, so the same bits) without storing the elements: the line search tries steps
// without copying the chain.
Vec2 closure_end(const FeChain& chain, double H, double V_A) {
  Vec2 end = Vec2::Zero();
  for (int j = 0; j < chain.elements; ++j) {
    const auto [T, t] = element_force(chain, j, H, V_A);
    end = end + (chain.element_length_m[j] * (1.0 + T / chain.axial_stiffness_n[j])) * t;
  }
  return end;
}

// d(r_N)/d(H, V_A) = sum_j l0_j [(I - t t^T)/T + I/EA_j] (symmetric).
Eigen::Matrix2d closure_jacobian(const FeChain& chain) {
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  for (int j = 0; j < chain.elements; ++j) {
    if (j < chain.grounded_elements) {
      // Only the grounded tension's stretch depends on H (while it is positive).
      if (chain.tension_n[j] > 0.0)
        J(0, 0) += chain.element_length_m[j] / chain.axial_stiffness_n[j];
      continue;
    }
    const Vec2& t = chain.direction[static_cast<std::size_t>(j)];
    J += chain.element_length_m[j] *
         ((Eigen::Matrix2d::Identity() - t * t.transpose()) / chain.tension_n[j] +
          Eigen::Matrix2d::Identity() / chain.axial_stiffness_n[j]);
  }
  return J;
}

// Newton on the closure r_N(H, V_A) = B - A from the continuous statics' support force, with
// backtracking that keeps H positive and the residual decreasing. Sets `failure` when the chain
// does not close to 1e-9 of its size.
void close_chain(FeChain& chain, const Problem& problem, const StaticSolution& statics) {
  const double L = problem.length_m();
  const Vec2 chord = problem.supports.chord_m();
  double H = statics.horizontal_force_n();
  double V_A = statics.vertical_force_a_n();
  const bool vertical = H == 0.0;
  // A line lying entirely on the seabed closes in x through H alone.
  const bool all_grounded = chain.grounded_elements == chain.elements;
  const double tolerance = 1e-14 * std::max(L, chord.norm());
  build_chain(chain, H, V_A);
  Vec2 residual = chain.node_offset_m.back() - chord;
  int iteration = 0;
  for (; iteration < 100 && residual.norm() > tolerance; ++iteration) {
    const Eigen::Matrix2d J = closure_jacobian(chain);
    const Vec2 step = vertical       ? Vec2(0.0, -residual.y() / J(1, 1))
                      : all_grounded ? Vec2(-residual.x() / J(0, 0), 0.0)
                                     : Vec2(-J.ldlt().solve(residual));
    double alpha = 1.0;
    // The accepted step (the last one tried if none decreases the residual; the chain keeps its
    // forces if every trial had H <= 0).
    double H_next = H, V_next = V_A;
    for (int k = 0; k < 40; ++k, alpha *= 0.5) {
      const double H_trial = H + alpha * step.x();
      if (!vertical && H_trial <= 0.0) continue;
      H_next = H_trial;
      V_next = V_A + alpha * step.y();
      if ((closure_end(chain, H_next, V_next) - chord).norm() < residual.norm()) break;
    }
    H = H_next;
    V_A = V_next;
    build_chain(chain, H, V_A);
    const Vec2 next = chain.node_offset_m.back() - chord;
    const bool stalled = next.norm() >= residual.norm() && next.norm() > tolerance;
    residual = next;
    // No further progress: accept the rounding floor if it is close, else fail below.
    if (stalled) break;
  }
  chain.newton_iterations = iteration;
  if (!(residual.norm() <= 1e-9 * std::max(L, chord.norm()))) {
    chain.failure = fmt::format(
        "discrete statics (N = {}) did not close: |r_N - (B - A)| = {:.3e} m after {} Newton "
        "iterations",
        chain.elements, residual.norm(), iteration);
  }
}

}  // namespace

FeChain solve_chain_statics(const Problem& problem,
                            const StaticSolution& statics,
                            const FeLineMesh& mesh,
                            double penalty_axial_stiffness_n) {
  FeChain chain;
  lay_out_chain(chain, mesh, penalty_axial_stiffness_n, statics.horizontal_force_n());
  const int elements = chain.elements;
  if (problem.prescribed_forces) {
    // Tension-specified problems keep their forces: re-solving them from the geometry would
    // determine the tension of a taut cable only to ~ rounding / strain (see Problem).
    build_chain(chain, problem.prescribed_forces->horizontal_n,
                problem.prescribed_forces->vertical_a_n);
  } else {
    close_chain(chain, problem, statics);
    if (!chain.in_equilibrium()) return chain;
  }
  chain.closure_error_m = (chain.node_offset_m.back() - problem.supports.chord_m()).norm();
  // A grounded element may be slack (friction): the seabed holds it.
  for (int j = chain.grounded_elements; j < elements; ++j) {
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

double FeChain::grounded_share_m(int i) const {
  double share = 0.0;
  if (i >= 1 && i - 1 < grounded_elements) share += 0.5 * element_length_m[i - 1];
  if (i < grounded_elements) share += 0.5 * element_length_m[i];
  return share;
}

FeChain solve_chain_statics(const Problem& problem,
                            const StaticSolution& statics,
                            int elements,
                            double axial_stiffness_n) {
  FeLineMesh mesh = uniform_cable_mesh(problem.cable, elements);
  mesh.pieces.front().section.axial_stiffness_n = axial_stiffness_n;
  return solve_chain_statics(problem, statics, mesh, axial_stiffness_n);
}

}  // namespace catena::internal
