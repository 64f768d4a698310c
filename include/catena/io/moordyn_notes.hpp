// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// What `catena import moordyn` made of everything a MoorDyn deck holds besides the lines it
/// converts (docs/how-to/moordyn-import.md, "What becomes of the rest of the deck"): each option
/// (used, ignored, with its value and why), the water depth and seabed, line-type columns Catena
/// has no counterpart for (EI, Cl, ...), free points' initial positions, point drag, output
/// channels, bodies and rods. Nothing a deck holds is dropped without one of these notes.

#include <optional>
#include <string>
#include <vector>

#include "catena/io/moordyn_deck.hpp"

namespace catena {

/// One thing the deck holds and what became of it.
struct MoorDynNote {
  std::string item;    ///< e.g. "option dtM = 0.001", "type chain: EI = 0"
  std::string fate;    ///< "used", "ignored", "dropped", "not used", "default", "none"
  std::string detail;  ///< how it was used or why not
};

/// The seabed the importer writes under every converted line, and why.
struct MoorDynSeabed {
  /// Height of the flat seabed [m]; absent when the deck gives no depth Catena can use (a
  /// bathymetry file): the scenes are then written without `[seabed]`.
  std::optional<double> z_m;
  /// The deepest point of the deck [m] (MoorDyn-C's default depth; also what a line written
  /// without a seabed is compared with).
  std::optional<double> deepest_point_z_m;
  /// Where z_m comes from, e.g. "WtrDpth = 300" or "the deepest point of the deck (MoorDyn-C's
  /// rule when WtrDpth is not given)".
  std::string source;
};

/// The seabed of `deck`: -WtrDpth when the deck gives it as a number, lowered to the deepest point
/// when a point lies below it (MoorDyn-C does the same); else the deepest point (MoorDyn-C's rule;
/// MoorDyn-F takes OpenFAST's depth, which the deck does not hold); none for a bathymetry file.
MoorDynSeabed moordyn_seabed(const MoorDynDeck& deck);

/// The notes on the deck as a whole: options in file order, defaults applied, the seabed, line
/// types' unused columns, points' unused data, lines' unused columns, output channels, bodies,
/// rods and Syrope tables.
std::vector<MoorDynNote> moordyn_deck_notes(const MoorDynDeck& deck);

}  // namespace catena
