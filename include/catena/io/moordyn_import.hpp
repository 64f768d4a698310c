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
///   seabed: z = -WtrDpth, stiffness = kBot Diam [N/m per m], damping = cBot Diam [N s/m per m],
///           friction 0, under every line when the deck has a depth (catena/io/moordyn_notes.hpp)
///   diameter = Diam, drag_normal = Cd, drag_tangential = CdAx
///   added_mass_tangential = CaAx rho_w pi/4 Diam^2         [kg/m]
///   axial_damping = BA, or for BA = -zeta < 0 MoorDyn's zeta (UnstrLen / NumSegs) sqrt(EA MassDen)
///                                                         [N s]
///   [environment] water_density = rho_w, gravity = g (the deck's options, or MoorDyn's defaults)
/// A single uniform line with positive weight is a `[cable]` scene; chains and buoyant lines are
/// `[line]` scenes. After converting, the importer solves each scene's statics (with its seabed)
/// and reports the result, or the statics' refusal, and whether the line would pass below the
/// deck's water depth. Lines Catena cannot represent get a reason instead. Everything else the
/// deck holds is reported by moordyn_deck_notes() (catena/io/moordyn_notes.hpp).

#include <string>
#include <vector>

#include "catena/io/moordyn_deck.hpp"
#include "catena/io/moordyn_notes.hpp"

namespace catena {

/// One line or chain of the deck, converted or not.
struct ImportedScene {
  /// MoorDyn line numbers, from end A to end B.
  std::vector<int> lines;
  /// File name (no directory) of the scene, e.g. "lines-line-1.toml"; empty when not converted.
  std::string file_name;
  /// The scene's TOML text; empty when not converted.
  std::string toml;
  /// The tables the scene uses, e.g. "[line] 3 segments, 1 point + [seabed]".
  std::string tables;
  /// The statics with the scene's seabed in a few words: "grounded 113.2 m of 850 m", "off the
  /// seabed", "refused (see the notes)", "did not converge (see the notes)"; the notes say why.
  std::string statics;
  /// True when the statics was solved (converged).
  bool statics_solved = false;
  /// What else the importer says about this line: the statics, the water depth, what was
  /// dropped (also in the scene's header comment).
  std::vector<std::string> notes;
  /// Why it was not converted; empty when it was.
  std::string reason;
};

/// Converts every line of `deck`; `stem` prefixes the scene names and files. Throws nothing for
/// lines it cannot convert (their reason says why), nor for a statics that refuses a converted
/// line (its `statics` says why).
std::vector<ImportedScene> convert_moordyn_deck(const MoorDynDeck& deck, const std::string& stem);

}  // namespace catena
