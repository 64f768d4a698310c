// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Discrete statics of the `fe` chain (docs/explanation/methods/fe.md): N two-node bar elements
/// with the weight lumped on the nodes, in exact equilibrium between the supports. Element j
/// carries the continuous force at its midpoint; the support force (H, V_A) closes the chain on
/// support b by a 2x2 Newton iteration, or is kept as given for a problem stated by its end forces.
/// On a line (fe_line_mesh.hpp) each element has its segment's section, and a point attachment's
/// weight is lumped on its node.

#include <string>
#include <vector>

#include "catena/models/cable.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "solvers/fe/fe_line_mesh.hpp"

namespace catena::internal {

/// The lumped inertia of a point attachment on its node [kg]: structural mass plus added mass
/// along the node tangent, the in-plane normal and out of plane (docs/explanation/physics.md,
/// "General lines").
struct FeNodeInertia {
  double tangential_kg = 0.0;
  double normal_kg = 0.0;
  double outofplane_kg = 0.0;
  /// True where a point attachment sits, even one without inertia (a buoy given by its volume
  /// alone): its weight kinks the static line there (fe_operators.cpp lumps the line's own mass
  /// in each half element's frame at such a node).
  bool attached = false;
};

/// The discrete chain in equilibrium.
struct FeChain {
  int elements = 0;
  /// True when every element has the same section and length (a uniform cable): the node
  /// positions along the line are then s_i = i l0.
  bool equal_elements = true;
  /// Per element j = 0..N-1: unstretched length l0_j [m], axial stiffness used (the penalty
  /// H/kappa where the segment is inextensible) [N], the inertia per unstretched length along the
  /// line m + ma_t (tangential added mass, 0 unless given) and across it M = m + ma [kg/m], and
  /// the support-a-relative vertical force at its midpoint minus V_A [N].
  Vector element_length_m;
  Vector axial_stiffness_n;
  Vector tangential_mass_kg_per_m;
  Vector normal_mass_kg_per_m;
  /// Per element: the section's damping (docs/explanation/physics.md, "Damping"): tangential and
  /// normal drag c_t, c_n [N s/m per m] and Kelvin-Voigt axial damping c_a [N s]; all zero on an
  /// undamped line (only the damped path reads them: fe_damping_operator.hpp).
  Vector tangential_damping_n_s_per_m2;
  Vector normal_damping_n_s_per_m2;
  Vector axial_damping_n_s;
  Vector vertical_offset_n;
  /// Seabed contact (docs/explanation/methods/fe.md, "Seabed contact"), in any number of grounded
  /// stretches anywhere along the line: element j lies on the seabed when grounded[j], horizontal,
  /// with tension max(H + grounded_tension_offset_n[j], 0) (the continuous tension profile at the
  /// element's midpoint, shifted with the chain's own H; 0 on suspended elements). The suspended
  /// elements form stretches, numbered from A (suspended_stretch[j], -1 on grounded elements): a
  /// stretch's vertical force is stretch_vertical_force_n[k] at its first node plus
  /// vertical_offset_n[j] (the weight from that node; the weight of a point on a grounded node
  /// rests on the seabed). The foundation stiffnesses k_s (vertical) and k_t (along and across)
  /// act on the grounded elements [N/m/m].
  std::vector<bool> grounded;
  std::vector<int> suspended_stretch;
  Vector stretch_vertical_force_n;
  Vector grounded_tension_offset_n;
  /// The number of grounded elements (0 without contact).
  int grounded_elements = 0;
  /// Height of the seabed relative to support a [m] (with contact).
  double seabed_offset_z_m = 0.0;
  double foundation_vertical_n_per_m2 = 0.0;
  double foundation_tangential_n_per_m2 = 0.0;
  /// The seabed dashpot c_s under the grounded elements, vertical only [N s/m per m].
  double foundation_damping_n_s_per_m2 = 0.0;
  /// The first element of each mesh piece (fe_line_mesh.hpp), ascending from 0: within a piece the
  /// elements are equal and the response smooth; joints, points and the contact boundaries are
  /// piece boundaries.
  std::vector<int> piece_first_element;
  /// Per node i = 0..N: unstretched arc length s_i [m] and the inertia of a point attachment there.
  Vector node_s_m;
  std::vector<FeNodeInertia> node_inertia;
  /// Support force (H, V_A) of the chain [N]; with seabed contact, H of the suspended parts and the
  /// vertical force at the first node of the first suspended stretch (just beyond the touchdown
  /// node when A rests on the seabed: O(l0^2), the discrete chain's correction).
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
  bool has_contact() const { return grounded_elements > 0; }
  bool is_grounded(int j) const { return has_contact() && grounded[static_cast<std::size_t>(j)]; }
  /// Length of unstretched grounded element next to node i on each side that the node carries:
  /// half of each grounded neighbour's l0 [m] (the foundation is lumped like the mass).
  double grounded_share_m(int i) const;
};

/// Solves the discrete statics on `mesh`, with the axial stiffness `penalty_axial_stiffness_n`
/// (finite) [N] on inextensible segments and each extensible segment's own EA, starting from the
/// shared continuous statics. Never throws for a numerical outcome: see FeChain::failure.
FeChain solve_chain_statics(const Problem& problem,
                            const StaticSolution& statics,
                            const FeLineMesh& mesh,
                            double penalty_axial_stiffness_n);

/// The chain of a uniform cable with N = `elements` equal elements, every one of axial stiffness
/// `axial_stiffness_n` (finite) [N].
FeChain solve_chain_statics(const Problem& problem,
                            const StaticSolution& statics,
                            int elements,
                            double axial_stiffness_n);

}  // namespace catena::internal
