#pragma once
/// \file
/// Discrete statics of the `fe` chain (docs/methods/fe.md): N two-node bar elements with the weight
/// lumped on the nodes, in exact equilibrium between the supports. Element j carries the
/// continuous force at its midpoint; the support force (H, V_A) closes the chain on support b by a
/// 2x2 Newton iteration, or is kept as given for a problem stated by its end forces.

#include <string>
#include <vector>

#include "catena/models/cable.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::internal {

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
  /// Empty when the chain is in equilibrium with positive tension everywhere; otherwise why not
  /// (Newton did not close, or an element is slack). A numerical outcome: the caller reports it as
  /// a numerical failure, and the chain is not to be used.
  std::string failure;

  bool in_equilibrium() const { return failure.empty(); }
};

/// Solves the discrete statics with N = `elements` elements and axial stiffness EA (finite) [N],
/// starting from the shared continuous statics. Never throws for a numerical outcome: see
/// FeChain::failure.
FeChain solve_chain_statics(const Problem& problem,
                            const StaticSolution& statics,
                            int elements,
                            double axial_stiffness_n);

}  // namespace catena::internal
