// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// A flat horizontal seabed under a line (docs/explanation/physics.md, "Seabed contact"): its
/// height, the Coulomb friction of the statics and the foundation stiffnesses of the linear
/// dynamics.

namespace catena {

/// The seabed at height z (x horizontal, z up), under the line (end A on it or above it).
struct Seabed {
  /// Height of the seabed [m]. Finite.
  double z_m = 0.0;
  /// Coulomb coefficient C_B of the statics [-]: along the grounded part the tension drops
  /// towards the anchor by C_B times the weight resting on the seabed, down to zero. Finite, >= 0.
  double friction = 0.0;
  /// Vertical stiffness per unit length k_s of the Winkler foundation under the grounded part in
  /// the linear dynamics [N/m per m]. Finite, >= 0.
  double stiffness_n_per_m2 = 0.0;
  /// Stiffness per unit length along and across the seabed in the linear dynamics [N/m per m]
  /// (0: frictionless). Finite, >= 0.
  double tangential_stiffness_n_per_m2 = 0.0;

  /// Dashpot per unit unstretched length c_s under the grounded part, in parallel with the
  /// vertical stiffness k_s, in the linear dynamics [N s/m per m] (MoorPy's cbot). Finite, >= 0.
  double damping_n_s_per_m2 = 0.0;

  /// Throws InvalidInput naming the field (`seabed.z`, `seabed.friction`, `seabed.stiffness`,
  /// `seabed.tangential_stiffness`, `seabed.damping`), its value and the constraint.
  void validate() const;
};

}  // namespace catena
