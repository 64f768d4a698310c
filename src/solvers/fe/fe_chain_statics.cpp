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

// The vertical force at each element's midpoint minus the vertical force at the first node of its
// suspended stretch: half of that node's weight goes into the support (or the seabed), and each
// interior node carries half of each neighbouring element's weight plus the weight of a point
// attachment there (docs/explanation/methods/fe.md). One piece keeps the closed form W0 l0 (j +
// 1/2). Grounded elements get 0 and number the stretches (FeChain::suspended_stretch).
void lump_weights(FeChain& chain, const FeLineMesh& mesh) {
  const int N = chain.elements;
  chain.vertical_offset_n.resize(N);
  chain.suspended_stretch.assign(static_cast<std::size_t>(N), 0);
  if (mesh.is_one_piece()) {
    const double W0 = mesh.pieces.front().section.weight_n_per_m;
    const double l0 = chain.element_length_m[0];
    for (int j = 0; j < N; ++j) chain.vertical_offset_n[j] = W0 * l0 * (j + 0.5);
    return;
  }
  // Within a piece the closed form from the piece's start, so that rounding does not accumulate
  // element by element. With seabed contact the grounded weight (with a point at a touchdown or
  // lift-off node, as in the statics) rests on the seabed: each suspended stretch counts from its
  // first node.
  double before = 0.0;  // weight from the stretch's first node to the start of the piece
  int j = 0;
  int stretch = -1;
  bool after_grounded = true;  // at the start of a stretch
  for (const FeMeshPiece& piece : mesh.pieces) {
    if (piece.grounded) {
      for (int k = 0; k < piece.elements; ++k, ++j) {
        chain.vertical_offset_n[j] = 0.0;
        chain.suspended_stretch[static_cast<std::size_t>(j)] = -1;
      }
      after_grounded = true;
      continue;
    }
    if (after_grounded) {
      ++stretch;
      before = 0.0;
    } else if (piece.point_at_start >= 0) {
      before += mesh.points[static_cast<std::size_t>(piece.point_at_start)].weight_n;
    }
    after_grounded = false;
    const double W0 = piece.section.weight_n_per_m;
    const double l0 = chain.element_length_m[j];
    for (int k = 0; k < piece.elements; ++k, ++j) {
      chain.vertical_offset_n[j] = before + W0 * l0 * (k + 0.5);
      chain.suspended_stretch[static_cast<std::size_t>(j)] = stretch;
    }
    before += W0 * piece.section.length_m;
  }
}

// The grounded elements (the mesh's grounded pieces, anywhere along the line) and their static
// tension relative to the continuous H: the tension profile of the statics at each element's
// midpoint (docs/explanation/physics.md, "Seabed contact"), which is linear on a piece, so the
// midpoint value is the element's mean tension.
void lay_out_contact(FeChain& chain, const FeLineMesh& mesh, double continuous_horizontal_force_n) {
  const int N = chain.elements;
  chain.grounded.assign(static_cast<std::size_t>(N), false);
  chain.grounded_tension_offset_n = Vector::Zero(N);
  chain.grounded_elements = 0;
  if (!mesh.seabed) return;
  chain.foundation_vertical_n_per_m2 = mesh.seabed->stiffness_n_per_m2;
  chain.foundation_tangential_n_per_m2 = mesh.seabed->tangential_stiffness_n_per_m2;
  chain.foundation_damping_n_s_per_m2 = mesh.seabed->damping_n_s_per_m2;
  int j = 0;
  for (const FeMeshPiece& piece : mesh.pieces) {
    if (!piece.grounded) {
      j += piece.elements;
      continue;
    }
    const double l0 = piece.section.length_m / piece.elements;
    const double slope = piece.grounded_tension_slope_n_per_m;
    for (int k = 0; k < piece.elements; ++k, ++j) {
      chain.grounded[static_cast<std::size_t>(j)] = true;
      chain.suspended_stretch[static_cast<std::size_t>(j)] = -1;
      chain.grounded_tension_offset_n[j] =
          piece.grounded_tension_begin_n + slope * l0 * (k + 0.5) - continuous_horizontal_force_n;
    }
    chain.grounded_elements += piece.elements;
  }
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

// Element j's tension and unit direction under the horizontal force H and the stretches'
// vertical forces V (FeChain::stretch_vertical_force_n).
std::pair<double, Vec2> element_force(const FeChain& chain, int j, double H, const Vector& V) {
  if (chain.is_grounded(j)) {
    // On the seabed: horizontal, with the tension profile of the statics (lay_out_contact).
    return {std::max(H + chain.grounded_tension_offset_n[j], 0.0), Vec2(1.0, 0.0)};
  }
  // Element j carries the continuous force at its midpoint (see lump_weights).
  const double Vj =
      V[chain.suspended_stretch[static_cast<std::size_t>(j)]] + chain.vertical_offset_n[j];
  const double T = std::hypot(H, Vj);
  return {T, T > 0.0 ? Vec2(H / T, Vj / T) : Vec2(0.0, 1.0)};
}

// Fills the per-element forces, lengths and node positions of a chain with forces (H, V).
void build_chain(FeChain& chain, double H, const Vector& V) {
  const int N = chain.elements;
  chain.horizontal_force_n = H;
  chain.stretch_vertical_force_n = V;
  chain.vertical_force_a_n = V.size() > 0 ? V[0] : 0.0;
  chain.tension_n.resize(N);
  chain.stretched_length_m.resize(N);
  chain.direction.resize(static_cast<std::size_t>(N));
  chain.node_offset_m.resize(static_cast<std::size_t>(N) + 1);
  chain.node_offset_m.front() = Vec2::Zero();
  for (int j = 0; j < N; ++j) {
    const auto [T, t] = element_force(chain, j, H, V);
    chain.tension_n[j] = T;
    chain.direction[static_cast<std::size_t>(j)] = t;
    chain.stretched_length_m[j] =
        chain.element_length_m[j] * (1.0 + T / chain.axial_stiffness_n[j]);
    chain.node_offset_m[static_cast<std::size_t>(j) + 1] =
        chain.node_offset_m[static_cast<std::size_t>(j)] + chain.stretched_length_m[j] * t;
  }
}

// The closure conditions of the discrete statics (docs/explanation/methods/fe.md, "Seabed
// contact"): the last node on support b, and the first node of every grounded stretch that neither
// starts at A (which is on the seabed) nor reaches B (whose height support b fixes) on the seabed.
// With one unknown H and one V per suspended stretch the count matches: each grounded stretch
// between two suspended ones adds one stretch and one condition.
struct Closure {
  std::vector<int> seabed_nodes;
  int stretches = 0;
  bool vertical = false;  // H = 0: the horizontal closure holds by itself, H stays 0
};

Closure closure_of(const FeChain& chain, double H) {
  Closure closure;
  const int N = chain.elements;
  for (int j = 0; j < N; ++j)
    closure.stretches =
        std::max(closure.stretches, chain.suspended_stretch[static_cast<std::size_t>(j)] + 1);
  for (int j = 1; j < N; ++j) {
    if (!chain.is_grounded(j) || chain.is_grounded(j - 1)) continue;
    int end = j;
    while (end < N && chain.is_grounded(end)) ++end;
    if (end < N) closure.seabed_nodes.push_back(j);
  }
  closure.vertical = H == 0.0;
  return closure;
}

// The closure residual under (H, V), computed as build_chain computes the nodes (the same
// operations in the same order, so the same bits) without storing the elements: the line search
// tries steps without copying the chain. Rows: x_N, z_N, then the seabed nodes' heights.
Vector closure_residual(
    const FeChain& chain, const Closure& closure, double H, const Vector& V, const Vec2& chord) {
  Vector residual(2 + closure.seabed_nodes.size());
  Vec2 end = Vec2::Zero();
  std::size_t next = 0;
  for (int j = 0; j < chain.elements; ++j) {
    if (next < closure.seabed_nodes.size() && closure.seabed_nodes[next] == j)
      residual[static_cast<Eigen::Index>(2 + next++)] = end.y() - chain.seabed_offset_z_m;
    const auto [T, t] = element_force(chain, j, H, V);
    end = end + (chain.element_length_m[j] * (1.0 + T / chain.axial_stiffness_n[j])) * t;
  }
  residual.head<2>() = end - chord;
  return residual;
}

// d(residual)/d(H, V_0, .., V_{S-1}) of the built chain: each suspended element adds
// l0_j [(I - t t^T)/T + I/EA_j] (columns H and its stretch's V) to the nodes beyond it; a grounded
// element adds l0_j / EA_j to their x through H (while its tension is positive).
Eigen::MatrixXd closure_jacobian(const FeChain& chain, const Closure& closure) {
  const auto rows = static_cast<Eigen::Index>(2 + closure.seabed_nodes.size());
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(rows, 1 + closure.stretches);
  // d(node)/dH and d(node)/dV_k, in fixed-size vectors (N may be 1e6).
  Vec2 by_H = Vec2::Zero();
  std::vector<Vec2> by_V(static_cast<std::size_t>(closure.stretches), Vec2::Zero());
  auto store = [&](Eigen::Index row, int component) {
    J(row, 0) = by_H[component];
    for (int k = 0; k < closure.stretches; ++k)
      J(row, 1 + k) = by_V[static_cast<std::size_t>(k)][component];
  };
  std::size_t next = 0;
  for (int j = 0; j < chain.elements; ++j) {
    if (next < closure.seabed_nodes.size() && closure.seabed_nodes[next] == j)
      store(static_cast<Eigen::Index>(2 + next++), 1);
    const double l0 = chain.element_length_m[j];
    if (chain.is_grounded(j)) {
      if (chain.tension_n[j] > 0.0) by_H.x() += l0 / chain.axial_stiffness_n[j];
      continue;
    }
    const Vec2& t = chain.direction[static_cast<std::size_t>(j)];
    const Eigen::Matrix2d G =
        l0 * ((Eigen::Matrix2d::Identity() - t * t.transpose()) / chain.tension_n[j] +
              Eigen::Matrix2d::Identity() / chain.axial_stiffness_n[j]);
    by_H += G.col(0);
    by_V[static_cast<std::size_t>(chain.suspended_stretch[static_cast<std::size_t>(j)])] +=
        G.col(1);
  }
  store(0, 0);
  store(1, 1);
  return J;
}

// The Newton step on the active unknowns and conditions: H and the x closure drop out of a
// vertical chain, the z closure (and the V) out of a line lying entirely on the seabed.
Vector newton_step(const Eigen::MatrixXd& J, const Vector& residual, const Closure& closure) {
  std::vector<Eigen::Index> rows, columns;
  if (!closure.vertical) rows.push_back(0), columns.push_back(0);
  if (closure.stretches > 0) rows.push_back(1);
  for (Eigen::Index r = 2; r < residual.size(); ++r) rows.push_back(r);
  for (int k = 0; k < closure.stretches; ++k) columns.push_back(1 + k);
  const auto n = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd A(n, static_cast<Eigen::Index>(columns.size()));
  Vector b(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    b[r] = residual[rows[static_cast<std::size_t>(r)]];
    for (Eigen::Index c = 0; c < A.cols(); ++c)
      A(r, c) = J(rows[static_cast<std::size_t>(r)], columns[static_cast<std::size_t>(c)]);
  }
  // Square by the count of closure_of; the 2 x 2 system of a line without contact is symmetric.
  const Vector active = A.rows() == 2 && closure.seabed_nodes.empty()
                            ? Vector(-Eigen::Matrix2d(A).ldlt().solve(Vec2(b)))
                            : Vector(-A.fullPivLu().solve(b));
  Vector step = Vector::Zero(J.cols());
  for (std::size_t c = 0; c < columns.size(); ++c)
    step[columns[c]] = active[static_cast<Eigen::Index>(c)];
  return step;
}

// The stretches' vertical forces of the continuous statics: V_A for a stretch from a suspended A,
// 0 (tangential) where a stretch leaves the seabed.
Vector initial_vertical_forces(const FeChain& chain,
                               const Closure& closure,
                               const StaticSolution& statics) {
  Vector V = Vector::Zero(closure.stretches);
  if (closure.stretches > 0 && !chain.is_grounded(0)) V[0] = statics.vertical_force_a_n();
  return V;
}

// Newton on the closure (Closure) from the continuous statics' forces, with backtracking that
// keeps H positive and the residual decreasing. Sets `failure` when the chain does not close to
// 1e-9 of its size.
void close_chain(FeChain& chain, const Problem& problem, const StaticSolution& statics) {
  const double L = problem.length_m();
  const Vec2 chord = problem.supports.chord_m();
  double H = statics.horizontal_force_n();
  const Closure closure = closure_of(chain, H);
  Vector V = initial_vertical_forces(chain, closure, statics);
  const double tolerance = 1e-14 * std::max(L, chord.norm());
  build_chain(chain, H, V);
  Vector residual = closure_residual(chain, closure, H, V, chord);
  int iteration = 0;
  for (; iteration < 100 && residual.norm() > tolerance; ++iteration) {
    const Vector step = newton_step(closure_jacobian(chain, closure), residual, closure);
    double alpha = 1.0;
    // The accepted step (the last one tried if none decreases the residual; the chain keeps its
    // forces if every trial had H <= 0).
    double H_next = H;
    Vector V_next = V;
    for (int k = 0; k < 40; ++k, alpha *= 0.5) {
      const double H_trial = H + alpha * step[0];
      if (!closure.vertical && H_trial <= 0.0) continue;
      H_next = H_trial;
      V_next = V + alpha * step.tail(closure.stretches);
      if (closure_residual(chain, closure, H_next, V_next, chord).norm() < residual.norm()) break;
    }
    H = H_next;
    V = V_next;
    build_chain(chain, H, V);
    const Vector next = closure_residual(chain, closure, H, V, chord);
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
  if (mesh.seabed) chain.seabed_offset_z_m = mesh.seabed->z_m - problem.supports.a_m.y();
  if (problem.prescribed_forces) {
    // Tension-specified problems keep their forces: re-solving them from the geometry would
    // determine the tension of a taut cable only to ~ rounding / strain (see Problem).
    const double H = problem.prescribed_forces->horizontal_n;
    Vector V = Vector::Zero(std::max(closure_of(chain, H).stretches, 1));
    V[0] = problem.prescribed_forces->vertical_a_n;
    build_chain(chain, H, V);
  } else {
    close_chain(chain, problem, statics);
    if (!chain.in_equilibrium()) return chain;
  }
  chain.closure_error_m = (chain.node_offset_m.back() - problem.supports.chord_m()).norm();
  // A grounded element may be slack (friction, or a slack line's H = 0): the seabed holds it.
  for (int j = 0; j < elements; ++j) {
    if (chain.is_grounded(j)) continue;
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
  if (i >= 1 && is_grounded(i - 1)) share += 0.5 * element_length_m[i - 1];
  if (i < elements && is_grounded(i)) share += 0.5 * element_length_m[i];
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
