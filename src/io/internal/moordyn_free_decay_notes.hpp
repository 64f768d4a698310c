// SPDX-License-Identifier: MIT
#pragma once
// What makes a MoorDyn free decay of an imported line non-linear, so that its identified
// frequencies and damping ratios cannot match Catena's damped modes exactly
// (docs/how-to/moordyn-free-decay.md): quadratic drag, a slack or nearly slack line (MoorDyn's
// segments carry no compression), seabed contact that changes (one-sided contact: the touchdown
// point moves), and an initial offset that is not small against the line's non-linear length
// scale. Each note states the bound in numbers, for the `catena import moordyn` summary and the
// scene's header.

#include <string>
#include <vector>

#include "catena/statics/elastic_catenary.hpp"
#include "io/internal/moordyn_scene_text.hpp"

namespace catena::internal {

/// A damping ratio at most `per_metre` times the amplitude [1/m]: the equivalent linear damping of
/// MoorDyn's quadratic drag 1/2 rho_w C d |v| v over one cycle of amplitude a, (8 / 3 pi) (1/2
/// rho_w C d) omega a, divided by 2 omega times the mass per metre it moves; the modal value is
/// a |phi|^3-weighted mean of it, hence at most its value at the largest amplitude a.
struct DragLinearity {
  double normal_per_metre = 0.0;      ///< (2 / 3 pi) rho_w Cd Diam / (MassDen + Ca rho_w A)
  double tangential_per_metre = 0.0;  ///< (2 / 3 pi) rho_w CdAx pi Diam / (MassDen + CaAx rho_w A)
};
DragLinearity drag_linearity(const SegmentProperties& segment, double water_density);

/// One note per segment of `d` whose drag is not zero (Cd or CdAx > 0): MoorDyn's drag is
/// quadratic, Catena's damped modes do not contain it; with the damping ratio it adds per metre
/// of amplitude. Empty when no segment has drag.
std::vector<std::string> drag_notes(const ChainDescription& d);

/// The notes that need the statics (`statics` converged, of the chain's scene, `length_m` its
/// total unstretched length): the amplitude scale l = sqrt(d^2 + L^2 H / EA) (d the sag from the
/// chord, EA the line's series stiffness; a << l is "small"), the lowest static tension (slack or
/// nearly slack lines), and the seabed contact (touchdown points and the static penetration, or
/// the clearance above the seabed).
std::vector<std::string> free_decay_notes(const ChainDescription& d,
                                          const StaticSolution& statics,
                                          double length_m);

/// Below this fraction of the largest static tension a line's lowest tension makes it "nearly
/// slack" in the notes: a release changing the tension by a tenth of its largest value slackens it.
inline constexpr double kNearlySlackFraction = 0.1;

}  // namespace catena::internal
