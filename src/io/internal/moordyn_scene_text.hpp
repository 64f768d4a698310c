// SPDX-License-Identifier: MIT
#pragma once
// A chain of MoorDyn lines described in Catena's terms (docs/how-to/moordyn-import.md), and written
// as a scene: `[cable]` for one uniform line, `[line]` with segments and points otherwise,
// `[seabed]` whenever the deck has a water depth (the statics decides contact).

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "catena/core/types.hpp"
#include "catena/io/moordyn_deck.hpp"
#include "catena/io/moordyn_notes.hpp"

namespace catena::internal {

/// One MoorDyn line in a chain; `reversed` when it is walked from its end B to its end A.
struct ChainSegment {
  int line = 0;
  bool reversed = false;
};

struct SegmentProperties {
  int line = 0;
  std::string type;
  double length_m = 0.0;
  double weight_n_per_m = 0.0;  ///< (MassDen - rho_w pi/4 Diam^2) g
  double axial_stiffness_n = 0.0;
  double mass_kg_per_m = 0.0;
  double added_mass_kg_per_m = 0.0;  ///< Ca rho_w pi/4 Diam^2
  double diameter_m = 0.0;
  double drag_normal = 0.0;                     ///< Cd
  double drag_tangential = 0.0;                 ///< CdAx
  double added_mass_tangential_kg_per_m = 0.0;  ///< CaAx rho_w pi/4 Diam^2
  /// BA [N s], or for BA = -zeta < 0 what MoorDyn makes of it: zeta (UnstrLen / NumSegs)
  /// sqrt(EA MassDen) (moordyn_scene_text.cpp).
  double axial_damping_n_s = 0.0;
  /// zeta when BA was a damping ratio, else -1; and the line's NumSegs.
  double damping_ratio = -1.0;
  int deck_segments = 0;
};

struct PointAttachment {
  int point = 0;
  double s_m = 0.0;
  double mass_kg = 0.0;
  double weight_n = 0.0;       ///< (M - rho_w V) g
  double added_mass_kg = 0.0;  ///< Ca rho_w V
};

/// The line's plane: end A (the lower held end) at x = 0, end B at the horizontal distance.
struct SceneGeometry {
  Vec2 a_m = Vec2::Zero();
  Vec2 b_m = Vec2::Zero();
  const MoorDynPoint* end_a = nullptr;
  const MoorDynPoint* end_b = nullptr;
};

struct ChainDescription {
  std::string deck_file;
  std::vector<ChainSegment> chain;  ///< from end A to end B
  std::vector<SegmentProperties> segments;
  std::vector<PointAttachment> points;
  SceneGeometry geometry;
  /// The deck's seabed (moordyn_seabed()); no z when none can be written.
  MoorDynSeabed seabed;
  double seabed_stiffness_n_per_m2 = 0.0;  ///< kBot times the diameter at end A
  double seabed_damping_n_s_per_m2 = 0.0;  ///< cBot times the diameter at end A
  double bottom_stiffness_pa_per_m = 0.0;  ///< kBot
  double bottom_damping_pa_s_per_m = 0.0;  ///< cBot
  double gravity = 0.0;
  double water_density = 0.0;
};

/// The chain (held end to held end, any direction) described from its lower end.
ChainDescription describe_chain(const MoorDynDeck& deck,
                                std::vector<ChainSegment> chain,
                                const std::map<int, const MoorDynPoint*>& points);

/// The scene's tables: `[cable]` or, when `as_line`, `[line]`; `[environment]`; `[seabed]` when
/// the deck has one; a request for 6 modes per plane.
std::string scene_tables(const ChainDescription& d, bool as_line);

/// The scene's header: a comment (source, conversion, the line's `notes` and the deck's notes),
/// then its name, description and tags. Header + tables is the scene file.
std::string scene_header(const ChainDescription& d,
                         const std::string& name,
                         const std::vector<std::string>& notes,
                         const std::vector<MoorDynNote>& deck_notes);

}  // namespace catena::internal
