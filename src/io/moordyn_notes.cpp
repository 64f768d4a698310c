// SPDX-License-Identifier: MIT
// What the MoorDyn importer made of everything a deck holds besides its lines
// (docs/how-to/moordyn-import.md, "What becomes of the rest of the deck"). The options and their
// effects are MoorDyn's documented ones (docs/inputs.rst of FloatingArrayDesign/MoorDyn) and what
// MoorDyn-C does with them (source/MoorDyn2.cpp, source/Line.cpp).
#include "catena/io/moordyn_notes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace catena {
namespace {

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

bool is_number(const std::string& text) {
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size();
}

struct OptionRule {
  std::vector<const char*> names;  // lower case
  const char* fate;
  const char* detail;
};

// Why each MoorDyn option does or does not reach a scene. Catena computes the statics directly
// and the linear dynamics about it in still water: MoorDyn's time integration, its dynamic
// relaxation to the initial state and its output settings have no counterpart.
const std::vector<OptionRule> kOptionRules = {
    {{"g", "gravity"}, "used", "[environment] gravity and the weights"},
    {{"rho", "rhow", "wtrdnsty"}, "used", "[environment] water_density, buoyancy, added mass"},
    {{"wtrdpth", "depth", "waterdepth"}, "used", "the seabed's z (see 'seabed')"},
    {{"kbot", "kb"}, "used", "[seabed] stiffness = kBot Diam"},
    {{"cbot", "cb"}, "used", "[seabed] damping = cBot Diam"},
    {{"dtm", "dt", "cfl", "tscheme"},
     "ignored",
     "MoorDyn's time integration; no effect on the linear dynamics"},
    {{"dtic", "icdt", "tmaxic", "ictmax", "cdscaleic", "icdfac", "threshic", "icthresh",
      "gendynamicic", "icgendynamic", "fileic", "icfile"},
     "ignored",
     "MoorDyn's search for the initial state; Catena solves the statics directly"},
    {{"dtout", "writelog", "writeunits", "disableoutput", "disableouttime", "outswitch", "echo"},
     "ignored",
     "output setting"},
    {{"wavekin", "currents", "dtwave", "unifycurrentgrid", "waterkin"},
     "ignored",
     "water kinematics: the scenes are in still water (a current's drag would shift the statics; "
     "waves enter only through a [request.motion] you add)"},
    {{"frictioncoefficient", "mu_kt", "mu_ka"},
     "ignored",
     "MoorDyn's seabed friction is a saturated damper on a node's velocity, zero at rest: it holds "
     "nothing in the statics ([seabed] friction = 0) and Catena's seabed has no tangential "
     "damping"},
    {{"fricdamp", "cv", "statdynfricscale", "mc"},
     "ignored",
     "a parameter of MoorDyn's seabed friction (see the friction coefficients)"},
    {{"seafloorfile"}, "not used", "a bathymetry: Catena's seabed is flat (see 'seabed' below)"},
    {{"inertialf", "inertialf_rampt"}, "ignored", "coupling setting of MoorDyn-F"},
};

MoorDynNote option_note(const MoorDynOption& option) {
  const std::string name = lower(option.name);
  MoorDynNote note{fmt::format("option {} = {}", option.name, option.value), "ignored",
                   "not an option Catena knows (MoorDyn warns about unknown options too)"};
  for (const auto& rule : kOptionRules) {
    if (std::find(rule.names.begin(), rule.names.end(), name) == rule.names.end()) continue;
    note.fate = rule.fate;
    note.detail = rule.detail;
  }
  // A zero (or off) kinematics, friction or output switch has nothing to convert.
  if (note.fate == "ignored" && is_number(option.value) && std::atof(option.value.c_str()) == 0.0 &&
      (name == "wavekin" || name == "currents" || name == "frictioncoefficient" ||
       name == "mu_kt" || name == "mu_ka")) {
    note.fate = "none";
    note.detail = "off";
  }
  const bool depth = name == "wtrdpth" || name == "depth" || name == "waterdepth";
  if (depth && !(is_number(option.value) && std::atof(option.value.c_str()) > 0.0)) {
    note.fate = "not used";
    note.detail = lower(option.value) == "default"
                      ? "MoorDyn-F takes OpenFAST's water depth, which the deck does not hold"
                      : "not a positive depth (MoorDyn-F reads a file name as a bathymetry)";
  }
  return note;
}

void default_notes(const MoorDynDeck& deck, std::vector<MoorDynNote>& notes) {
  const auto given = [&](std::initializer_list<const char*> names) {
    return std::any_of(names.begin(), names.end(),
                       [&](const char* n) { return deck.options.count(n) > 0; });
  };
  if (!given({"g", "gravity"}))
    notes.push_back({"g (not given)", "default", "MoorDyn-C's 9.80665 m/s^2"});
  if (!given({"rho", "rhow", "wtrdnsty"}))
    notes.push_back({"rho (not given)", "default", "MoorDyn's 1025 kg/m^3"});
  if (!given({"kbot", "kb"}))
    notes.push_back({"kBot (not given)", "default", "MoorDyn's 3e6 Pa/m"});
  if (!given({"cbot", "cb"}))
    notes.push_back({"cBot (not given)", "default", "MoorDyn's 3e5 Pa s/m"});
}

std::string join(const std::vector<std::pair<std::string, std::string>>& cells) {
  std::string out;
  for (const auto& [name, value] : cells)
    out += fmt::format("{}{} = {}", out.empty() ? "" : ", ", name, value);
  return out;
}

void type_notes(const MoorDynDeck& deck, std::vector<MoorDynNote>& notes) {
  for (const auto& type : deck.types) {
    if (!type.bending_stiffness_text.empty()) {
      const bool zero = is_number(type.bending_stiffness_text) &&
                        std::atof(type.bending_stiffness_text.c_str()) == 0.0;
      notes.push_back({fmt::format("type {}: EI = {}", type.name, type.bending_stiffness_text),
                       zero ? "none" : "dropped",
                       zero ? "no bending stiffness"
                            : "bending stiffness: Catena's lines have none (a cable model)"});
    }
    if (!type.other_columns.empty()) {
      notes.push_back({fmt::format("type {}: {}", type.name, join(type.other_columns)), "ignored",
                       "columns Catena has no counterpart for (e.g. Cl, the VIV lift)"});
    }
  }
}

// Free points' positions are MoorDyn's initial guesses; point drag areas and v1's initial forces
// have no counterpart.
void point_notes(const MoorDynDeck& deck, std::vector<MoorDynNote>& notes) {
  for (const auto& p : deck.points) {
    if (p.kind == MoorDynPointKind::Free) {
      notes.push_back(
          {fmt::format("point {} ({}) at ({}, {}, {}) m", p.id, p.attachment, p.x_m, p.y_m, p.z_m),
           "not used",
           "a free point's position is MoorDyn's initial guess; the statics "
           "places it"});
    }
    std::vector<std::pair<std::string, std::string>> nonzero;
    for (const auto& cell : p.other_columns) {
      if (!(is_number(cell.second) && std::atof(cell.second.c_str()) == 0.0))
        nonzero.push_back(cell);
    }
    if (!nonzero.empty()) {
      notes.push_back({fmt::format("point {}: {}", p.id, join(nonzero)), "dropped",
                       "a point's drag area (CdA) or initial force: Catena's point attachments "
                       "have mass, weight and added mass only"});
    }
  }
}

void line_notes(const MoorDynDeck& deck, std::vector<MoorDynNote>& notes) {
  std::string flags;
  for (const auto& line : deck.lines) {
    for (const auto& cell : line.other_columns) {
      if (cell.second != "-")
        flags += fmt::format("{}{}: {}", flags.empty() ? "" : ", ", line.id, cell.second);
    }
  }
  if (!flags.empty())
    notes.push_back({"line output flags (" + flags + ")", "ignored", "output setting"});
  if (!deck.lines.empty()) {
    notes.push_back({"NumSegs", "not used",
                     "Catena's solvers choose their own meshes; NumSegs enters only a BA given "
                     "as -zeta (see the scene's header)"});
  }
}

void structure_notes(const MoorDynDeck& deck, std::vector<MoorDynNote>& notes) {
  if (!deck.outputs.empty()) {
    std::string channels;
    for (std::size_t i = 0; i < deck.outputs.size() && i < 6; ++i)
      channels += (i ? ", " : "") + deck.outputs[i];
    if (deck.outputs.size() > 6) channels += ", ...";
    notes.push_back({fmt::format("output channels: {} ({})", deck.outputs.size(), channels),
                     "ignored", "Catena writes its own results"});
  }
  if (deck.body_rows > 0 || deck.has_bodies)
    notes.push_back({fmt::format("bodies: {}", deck.body_rows), "not converted",
                     "Catena has no bodies; lines attached to one are listed with the reason"});
  if (deck.rod_rows > 0 || deck.rod_type_rows > 0)
    notes.push_back({fmt::format("rods: {} ({} rod types)", deck.rod_rows, deck.rod_type_rows),
                     "not converted",
                     "Catena has no rods; lines attached to one are listed with the reason"});
  if (deck.syrope_rows > 0)
    notes.push_back({fmt::format("SYROPE IC ({} rows)", deck.syrope_rows), "ignored",
                     "lines with a Syrope EA are not converted"});
}

}  // namespace

MoorDynSeabed moordyn_seabed(const MoorDynDeck& deck) {
  MoorDynSeabed seabed;
  if (!deck.points.empty()) {
    seabed.deepest_point_z_m =
        std::min_element(deck.points.begin(), deck.points.end(), [](const auto& a, const auto& b) {
          return a.z_m < b.z_m;
        })->z_m;
  }
  const std::string bathymetry = deck.bathymetry_file();
  if (!bathymetry.empty()) {
    seabed.source = fmt::format(
        "none written: the deck's seabed is the bathymetry '{}', and Catena's seabed is flat",
        bathymetry);
    return seabed;
  }
  if (const auto depth = deck.water_depth()) {
    seabed.z_m = -*depth;
    seabed.source = fmt::format("z = -WtrDpth = {:g} m", -*depth);
    if (seabed.deepest_point_z_m && *seabed.deepest_point_z_m < -*depth) {
      seabed.z_m = seabed.deepest_point_z_m;
      seabed.source = fmt::format(
          "z = {:g} m: WtrDpth = {:g} m, but a point lies deeper; MoorDyn-C lowers the seabed to "
          "the deepest point, and so does the importer",
          *seabed.z_m, *depth);
    }
    return seabed;
  }
  if (seabed.deepest_point_z_m) {
    seabed.z_m = seabed.deepest_point_z_m;
    seabed.source = fmt::format(
        "z = {:g} m, the deepest point of the deck: no usable WtrDpth (MoorDyn-C's rule; "
        "MoorDyn-F would take OpenFAST's depth)",
        *seabed.z_m);
  } else {
    seabed.source = "none written: no WtrDpth and no points";
  }
  return seabed;
}

std::vector<MoorDynNote> moordyn_deck_notes(const MoorDynDeck& deck) {
  std::vector<MoorDynNote> notes;
  for (const auto& option : deck.option_rows) notes.push_back(option_note(option));
  default_notes(deck, notes);
  const MoorDynSeabed seabed = moordyn_seabed(deck);
  notes.push_back({"seabed", seabed.z_m ? "used" : "none",
                   seabed.source + (seabed.z_m ? "; written under every converted line (the "
                                                 "statics decides contact), friction 0"
                                               : "")});
  type_notes(deck, notes);
  point_notes(deck, notes);
  line_notes(deck, notes);
  structure_notes(deck, notes);
  return notes;
}

}  // namespace catena
