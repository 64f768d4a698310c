// SPDX-License-Identifier: MIT
// MoorDyn lines and chains as Catena scenes (docs/how-to/moordyn-import.md): topology (which lines
// form a chain through free points, which cannot be represented), geometry (the vertical plane
// through the held ends), and the conversion of MoorDyn's quantities.
#include "catena/io/moordyn_import.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <utility>

#include "catena/core/error.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "io/internal/moordyn_free_decay_notes.hpp"
#include "io/internal/moordyn_scene_text.hpp"

namespace catena {
namespace {

using internal::ChainSegment;
using internal::SceneGeometry;

struct Topology {
  const MoorDynDeck& deck;
  std::map<int, const MoorDynPoint*> points;
  std::map<int, std::vector<int>> lines_at_point;  // point id -> line ids
  std::map<int, std::string> reasons;              // line id -> why it cannot be converted

  const MoorDynLine& line(int id) const {
    return *std::find_if(deck.lines.begin(), deck.lines.end(),
                         [&](const MoorDynLine& l) { return l.id == id; });
  }
};

// The point an end names ("4", "P4", "Point4", "C4"), or nullopt with `why` (rod ends, bodies).
// At most 9 digits: point IDs are ints (moordyn_deck.cpp), so stoi cannot overflow.
std::optional<int> end_point(const std::string& end, std::string& why) {
  std::size_t digits = 0;
  while (digits < end.size() && std::isalpha(static_cast<unsigned char>(end[digits]))) ++digits;
  std::string letters = end.substr(0, digits);
  for (char& c : letters) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const std::string rest = end.substr(digits);
  if (letters == "R" || letters == "ROD") {
    why = fmt::format("attached to a rod ({}); Catena has no rods", end);
    return std::nullopt;
  }
  if (!(letters.empty() || letters == "P" || letters == "POINT" || letters == "C" ||
        letters == "CON") ||
      rest.empty() || rest.size() > 9 || !std::all_of(rest.begin(), rest.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c));
      })) {
    why = fmt::format("end '{}' is not a point", end);
    return std::nullopt;
  }
  return std::stoi(rest);
}

void find_reasons(Topology& t) {
  for (const auto& p : t.deck.points) t.points[p.id] = &p;
  for (const auto& line : t.deck.lines) {
    std::string why;
    for (const std::string* end : {&line.end_a, &line.end_b}) {
      const auto id = end_point(*end, why);
      if (id && !t.points.count(*id))
        why = fmt::format("end point {} is not in the POINTS table", *id);
      if (!why.empty()) break;
      t.lines_at_point[*id].push_back(line.id);
    }
    const auto type = std::find_if(t.deck.types.begin(), t.deck.types.end(),
                                   [&](const auto& ty) { return ty.name == line.type; });
    if (why.empty() && type == t.deck.types.end())
      why = fmt::format("line type '{}' is not in LINE TYPES", line.type);
    if (why.empty() && !type->axial_stiffness_n)
      why = fmt::format("EA '{}' is not a constant (nonlinear or Syrope)",
                        type->axial_stiffness_text);
    // Catena's axial damping is one Kelvin-Voigt coefficient; a BA curve or a viscoelastic
    // "BA|BA_D" pair is not one.
    if (why.empty() && !type->axial_damping)
      why = fmt::format("BA '{}' is not a constant (a curve or viscoelastic)",
                        type->axial_damping_text);
    if (why.empty() && *type->axial_damping < 0.0 && line.segments < 1)
      why = fmt::format(
          "BA = {} is a damping ratio, which MoorDyn applies per segment, but "
          "NumSegs = {}",
          type->axial_damping_text, line.segments);
    // Without gravity a line has no weight and no catenary: nothing for Catena's statics.
    if (why.empty() && !(t.deck.gravity() > 0.0))
      why = "g = 0 in the OPTIONS: a weightless line has no catenary statics";
    if (std::count(t.deck.failing_lines.begin(), t.deck.failing_lines.end(), line.id))
      why = "may fail (FAILURE section)";
    if (!why.empty()) t.reasons[line.id] = why;
  }
  for (const auto& [id, lines] : t.lines_at_point) {
    const MoorDynPoint& p = *t.points.at(id);
    std::string why;
    if (p.kind == MoorDynPointKind::Body)
      why = fmt::format("attached to a body at point {} ({})", id, p.attachment);
    if (p.kind == MoorDynPointKind::Other)
      why =
          fmt::format("point {} is held by '{}', which Catena cannot represent", id, p.attachment);
    if (p.kind == MoorDynPointKind::Free && lines.size() >= 3)
      why = fmt::format("{} lines meet at free point {}", lines.size(), id);
    if (p.kind == MoorDynPointKind::Free && lines.size() == 1)
      why = fmt::format("free end at point {} (both ends must be held)", id);
    for (int line : lines) {
      if (!why.empty() && !t.reasons.count(line)) t.reasons[line] = why;
    }
  }
}

int point_id(const std::string& end) {
  std::string unused;
  return *end_point(end, unused);
}

// Extends `chain` from its last element (forward) or its first (backward) through free points
// joining exactly two lines. False (with `why`) when it meets a line that cannot be converted or
// closes into a loop.
bool extend_chain(const Topology& t,
                  std::vector<ChainSegment>& chain,
                  bool forward,
                  std::string& why) {
  const int start = chain.front().line;
  while (true) {
    const ChainSegment& end = forward ? chain.back() : chain.front();
    const MoorDynLine& line = t.line(end.line);
    // Forward: leave by the far end of the last element; backward: by the near end of the first.
    const bool leave_by_a = forward ? end.reversed : !end.reversed;
    const int joint = point_id(leave_by_a ? line.end_a : line.end_b);
    if (t.points.at(joint)->kind != MoorDynPointKind::Free) return true;
    const auto& pair = t.lines_at_point.at(joint);
    const int next = pair[0] == end.line ? pair[1] : pair[0];
    if (next == start || next == end.line) {
      why = "the lines close into a loop";
      return false;
    }
    if (t.reasons.count(next)) {
      why = fmt::format("joined at free point {} to line {}, which cannot be converted ({})", joint,
                        next, t.reasons.at(next));
      return false;
    }
    // Forward, the next line is walked away from the joint; backward, towards it.
    const bool joint_is_a = point_id(t.line(next).end_a) == joint;
    const ChainSegment segment{next, forward ? !joint_is_a : joint_is_a};
    if (forward)
      chain.push_back(segment);
    else
      chain.insert(chain.begin(), segment);
  }
}

std::vector<ChainSegment> build_chain(const Topology& t, int start, std::string& why) {
  std::vector<ChainSegment> chain{{start, false}};
  if (!extend_chain(t, chain, true, why) || !extend_chain(t, chain, false, why)) return {};
  return chain;
}

// The height of the solved line's lowest point [m].
double lowest_z(const StaticSolution& statics) {
  return statics.position_m(statics.lowest_point_s_m()).y();
}

// A length for the summary: "113.2 m".
std::string metres(double value) { return fmt::format("{:.4g} m", value); }

ImportedScene refused(int line, const std::string& why) {
  ImportedScene scene;
  scene.lines = {line};
  scene.reason = why;
  return scene;
}

// After the statics refused the scene with its seabed: where the line would hang without it, so
// the summary says whether it would pass below the deck's water depth.
void report_without_seabed(internal::ChainDescription d,
                           bool as_line,
                           const std::string& origin,
                           ImportedScene& scene) {
  const double seabed_z = *d.seabed.z_m;
  d.seabed.z_m.reset();
  try {
    const Problem problem =
        parse_scene_text(internal::scene_tables(d, as_line), origin).front().problem;
    const StaticSolution statics = solve_statics(problem);
    if (!statics.converged) return;
    const double z = lowest_z(statics);
    if (z < seabed_z - 1e-9 * (std::abs(seabed_z) + 1.0)) {
      scene.notes.push_back(fmt::format(
          "Without the seabed the line would hang down to z = {:.6g} m, {:.4g} m below the deck's "
          "water depth (seabed z = {:.6g} m): do not solve it without [seabed].",
          z, seabed_z - z, seabed_z));
    } else {
      scene.notes.push_back(fmt::format(
          "Without the seabed the line stays above it (lowest z = {:.6g} m, seabed z = {:.6g} m).",
          z, seabed_z));
    }
  } catch (const Error&) {
    // The line has no equilibrium without the seabed either; the refusal above says why.
  }
}

// Catena's seabed has one stiffness: the importer uses the diameter at end A; say so when the
// chain's segments differ.
void seabed_diameter_note(const internal::ChainDescription& d, ImportedScene& scene) {
  if (!d.seabed.z_m) return;
  for (const auto& segment : d.segments) {
    if (segment.diameter_m != d.segments.front().diameter_m) {
      scene.notes.push_back(fmt::format(
          "[seabed] stiffness and damping use Diam = {} m of the segment at end A; other segments "
          "have other diameters (Catena's seabed has one stiffness).",
          d.segments.front().diameter_m));
      return;
    }
  }
}

// What this line's types hold that its scene cannot: a bending stiffness (Catena's lines are
// cables). Also among the deck's notes; repeated per line so each scene's summary row has it.
void dropped_type_notes(const MoorDynDeck& deck,
                        const internal::ChainDescription& d,
                        ImportedScene& scene) {
  for (const auto& segment : d.segments) {
    const auto type =
        std::find_if(deck.types.begin(), deck.types.end(),
                     [&](const MoorDynLineType& t) { return t.name == segment.type; });
    const std::string& ei = type->bending_stiffness_text;
    char* end = nullptr;
    const double value = std::strtod(ei.c_str(), &end);
    if (ei.empty() || (end == ei.c_str() + ei.size() && value == 0.0)) continue;
    scene.notes.push_back(fmt::format(
        "Line {} (type {}): EI = {} N m^2 dropped: Catena's lines have no bending stiffness.",
        segment.line, segment.type, ei));
  }
}

// The statics of the scene's tables (what `catena solve` will solve), with its seabed when it has
// one: the summary's words and the notes, including whether the line would pass below the deck's
// water depth. A refusal (InvalidInput) is reported with its message, never thrown.
void report_statics(const internal::ChainDescription& d,
                    bool as_line,
                    const std::string& origin,
                    ImportedScene& scene) {
  const double tolerance = 1e-9 * (std::abs(d.seabed.z_m.value_or(0.0)) + 1.0);
  Problem problem;
  try {
    problem = parse_scene_text(internal::scene_tables(d, as_line), origin).front().problem;
    const StaticSolution statics = solve_statics(problem);
    if (!statics.converged) {
      scene.statics = "did not converge (see the notes)";
      scene.notes.push_back("The statics did not converge: " + statics.message);
      return;
    }
    scene.statics_solved = true;
    const double z = lowest_z(statics);
    const auto intervals = statics.contact_intervals();
    if (!d.seabed.z_m) {
      scene.statics = fmt::format("lowest z = {}", metres(z));
    } else if (intervals.empty()) {
      scene.statics = "off the seabed";
    } else {
      scene.statics = fmt::format("grounded {} of {}", metres(statics.grounded_length_m()),
                                  metres(problem.length_m()));
      if (intervals.size() > 1) scene.statics += fmt::format(" ({} stretches)", intervals.size());
    }
    scene.notes.push_back(fmt::format(
        "Statics{}: H = {:.6g} N, fairlead tension {:.6g} N, lowest point z = {:.6g} m; {}.",
        d.seabed.z_m ? " with the seabed" : "", statics.horizontal_force_n(),
        statics.tension_n(problem.length_m()), z, scene.statics));
    if (d.seabed.z_m && z < *d.seabed.z_m - tolerance) {
      scene.notes.push_back(
          fmt::format("The solved line passes below the seabed: lowest z = {:.6g} m < {:.6g} m.", z,
                      *d.seabed.z_m));
    }
    if (!d.seabed.z_m && d.seabed.deepest_point_z_m && z < *d.seabed.deepest_point_z_m) {
      scene.notes.push_back(fmt::format(
          "No seabed is written, and the solved line's lowest point z = {:.6g} m is below the "
          "deepest point of the deck ({:.6g} m): check where the deck's seabed is.",
          z, *d.seabed.deepest_point_z_m));
    }
    // What would make a MoorDyn free decay of this line non-linear
    // (docs/how-to/moordyn-free-decay.md).
    for (std::string& note : internal::free_decay_notes(d, statics, problem.length_m()))
      scene.notes.push_back(std::move(note));
  } catch (const Error& error) {
    // InvalidInput from the scene reader's or the statics' checks (e.g. a case the seabed model
    // does not support): reported, not thrown, so the other lines are still imported.
    scene.statics = "refused (see the notes)";
    scene.notes.push_back(std::string("Statics refused: ") + error.what());
    if (d.seabed.z_m) report_without_seabed(d, as_line, origin, scene);
  }
}

ImportedScene convert_chain(const Topology& t,
                            const std::vector<ChainSegment>& chain,
                            const std::string& stem) {
  ImportedScene scene;
  internal::ChainDescription d = internal::describe_chain(t.deck, chain, t.points);
  for (const auto& segment : d.chain) scene.lines.push_back(segment.line);
  const bool general = d.segments.size() > 1 || d.segments[0].weight_n_per_m <= 0.0;
  scene.tables = general ? fmt::format("[line] {} segment{}", d.segments.size(),
                                       d.segments.size() > 1 ? "s" : "")
                         : "[cable]";
  if (!d.points.empty())
    scene.tables += fmt::format(", {} point{}", d.points.size(), d.points.size() > 1 ? "s" : "");
  if (d.seabed.z_m) scene.tables += " + [seabed]";
  dropped_type_notes(t.deck, d, scene);
  seabed_diameter_note(d, scene);
  std::string ids;
  for (int id : scene.lines) ids += (ids.empty() ? "" : "-") + std::to_string(id);
  const std::string name = fmt::format("{}-line-{}", stem, ids);
  scene.file_name = name + ".toml";
  report_statics(d, general, scene.file_name, scene);
  for (std::string& note : internal::drag_notes(d)) scene.notes.push_back(std::move(note));
  scene.toml = internal::scene_header(d, name, scene.notes, moordyn_deck_notes(t.deck)) +
               internal::scene_tables(d, general);
  // A scene Catena's own reader refuses (a deck value beyond the scene format's ranges, e.g. a
  // coordinate of 1e20 m or a negative drag coefficient) is not written: the line is listed as not
  // converted, with the reader's reason.
  try {
    parse_scene_text(scene.toml, scene.file_name);
  } catch (const Error& error) {
    ImportedScene not_converted;
    not_converted.lines = scene.lines;
    not_converted.reason = std::string("the scene would not read: ") + error.what();
    return not_converted;
  }
  return scene;
}

}  // namespace

std::vector<ImportedScene> convert_moordyn_deck(const MoorDynDeck& deck, const std::string& stem) {
  Topology topology{deck, {}, {}, {}};
  find_reasons(topology);
  std::vector<ImportedScene> out;
  std::set<int> done;
  for (const auto& line : deck.lines) {
    if (done.count(line.id)) continue;
    if (topology.reasons.count(line.id)) {
      out.push_back(refused(line.id, topology.reasons.at(line.id)));
      done.insert(line.id);
      continue;
    }
    std::string why;
    const std::vector<ChainSegment> chain = build_chain(topology, line.id, why);
    if (chain.empty()) {
      out.push_back(refused(line.id, why));
      done.insert(line.id);
      continue;
    }
    for (const auto& segment : chain) done.insert(segment.line);
    out.push_back(convert_chain(topology, chain, stem));
  }
  return out;
}

}  // namespace catena
