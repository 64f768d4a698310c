// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Converting a MoorDyn deck (io/moordyn_deck.hpp) into Catena scenes, one per line or per chain
/// of lines in series joined at free points (docs/how-to/moordyn-import.md). Each line becomes a
/// vertical plane through its two held ends (end A the lower); MoorDyn's quantities become
/// Catena's:
///   weight     = (MassDen - rho_w pi/4 Diam^2) g         [N/m]
///   added_mass = Ca rho_w pi/4 Diam^2                     [kg/m]
///   point weight = (M - rho_w V) g, point added mass = Ca rho_w V
///   seabed: z = -WtrDpth, stiffness = kBot Diam           [N/m per m]
///   diameter = Diam, drag_normal = Cd, drag_tangential = CdAx
///   added_mass_tangential = CaAx rho_w pi/4 Diam^2         [kg/m]
///   axial_damping = BA, or for BA = -zeta < 0 MoorDyn's zeta (UnstrLen / NumSegs) sqrt(EA MassDen)
///                                                         [N s]
///   [environment] water_density = rho_w, gravity = g (the deck's options, or MoorDyn's defaults)
/// A single uniform line with positive weight that stays off the seabed is a `[cable]` scene,
/// which Catena solves today; chains, buoyant lines and lines on the seabed use the `[line]` and
/// `[seabed]` tables of the general-line and seabed capabilities, and each such scene says in its
/// header comment which it needs. Lines Catena cannot represent get a reason instead.

#include <string>
#include <vector>

#include "catena/io/moordyn_deck.hpp"

namespace catena {

/// One line or chain of the deck, converted or not.
struct ImportedScene {
  /// MoorDyn line numbers, from end A to end B.
  std::vector<int> lines;
  /// File name (no directory) of the scene, e.g. "lines-line-1.toml"; empty when not converted.
  std::string file_name;
  /// The scene's TOML text; empty when not converted.
  std::string toml;
  /// Capabilities the scene needs beyond today's `[cable]` (e.g. "[line] (multi-segment)").
  std::vector<std::string> needs;
  /// Why it was not converted; empty when it was.
  std::string reason;
};

/// Converts every line of `deck`; `stem` prefixes the scene names and files. Throws nothing for
/// lines it cannot convert (their reason says why).
std::vector<ImportedScene> convert_moordyn_deck(const MoorDynDeck& deck, const std::string& stem);

}  // namespace catena
