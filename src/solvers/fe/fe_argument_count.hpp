// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The number of roots of det Q(lambda), Q = K + lambda C + lambda^2 M, inside a rectangle of the
/// lambda-plane, by the argument principle (docs/explanation/methods/fe.md, "Damping"): det Q is
/// a polynomial (no poles), so its phase turns by 2 pi per root inside as lambda goes once round
/// the boundary counter-clockwise. Sylvester's inertia, which counts the undamped modes, has no
/// counterpart for this non-Hermitian problem.
///
/// The step is also kept below the distance to the nearest root already known (`known`, the
/// roots the eigensolver found, with their conjugates): along a straight step each root turns the
/// phase by the angle the step subtends at it (less than pi), so a step may not sweep past a
/// cluster of roots whose turns add up to a whole turn and alias. A root that is not known turns
/// the phase by up to pi as the walk passes it, which the pi/4 rule then resolves.
///
/// The phase at a point is the sum of the phases of the pivots of the complex symmetric banded
/// LDL^T of Q(lambda) (fe_complex_banded_ldlt.hpp): det Q = prod D_i, and its derivative
/// d log det Q / dlambda = tr(Q^{-1} Q') from the same factors. Along each edge the step adapts so
/// that the phase changes by less than pi/4 between consecutive points (halved while it does not,
/// doubled after a change below pi/16). A change measured modulo 2 pi is unwrapped to the branch
/// nearest the trapezoid rule on the derivative, and the step is accepted only when the two
/// agree within pi/8: many roots at a moderate distance (a chain with Kelvin-Voigt damping has
/// hundreds of overdamped axial roots near -EA/c_a) turn the phase fast but smoothly, and a
/// sampled phase alone would alias whole turns. What the count rests on is this step rule: a pair
/// of roots closer to the edge than the step, whose contributions cancel within one step in both
/// the phase and its derivative, could still be missed, as in any sampled argument-principle
/// count.

#include <complex>
#include <string>
#include <vector>

#include "solvers/fe/fe_complex_banded_ldlt.hpp"
#include "solvers/fe/fe_operators.hpp"

namespace catena::internal {

struct FeCountRegion {
  double re_min = 0.0, re_max = 0.0, im_min = 0.0, im_max = 0.0;
  std::string describe() const;
};

struct FeArgumentCount {
  bool ok = false;
  int count = -1;
  /// Factorisations of Q along the boundary.
  long evaluations = 0;
  /// Why the count failed (a pivot vanished on the boundary, or the step fell to rounding).
  std::string failure;
};

/// The roots of det(K + lambda C + lambda^2 M) in `region` (header), with the steps kept clear of
/// the `known` roots, factoring into `factor`.
FeArgumentCount count_roots_in_rectangle(const SparseMatrix& K,
                                         const SparseMatrix& C,
                                         const SparseMatrix& M,
                                         const FeCountRegion& region,
                                         const std::vector<std::complex<double>>& known,
                                         ComplexBandedLdlt& factor);

}  // namespace catena::internal
