// SPDX-License-Identifier: MIT
// MoorDyn lines and chains as Catena scenes (docs/how-to/moordyn-import.md): topology (which lines
// form a chain through free points, which cannot be represented), geometry (the vertical plane
// through the held ends), and the conversion of MoorDyn's quantities.
#include "catena/io/moordyn_import.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "catena/core/error.hpp"
#include "catena/statics/elastic_catenary.hpp"
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
      rest.empty() || !std::all_of(rest.begin(), rest.end(), [](char c) {
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

// Whether a uniform line with the given geometry, solved without a seabed, goes below it.
bool uniform_line_touches(const internal::SegmentProperties& segment,
                          const SceneGeometry& geometry,
                          double seabed_z,
                          std::string& why) {
  Problem problem;
  problem.cable.length_m = segment.length_m;
  problem.cable.weight_n_per_m = segment.weight_n_per_m;
  problem.cable.axial_stiffness_n = segment.axial_stiffness_n;
  problem.cable.mass_kg_per_m = segment.mass_kg_per_m;
  problem.cable.added_mass_kg_per_m = segment.added_mass_kg_per_m;
  problem.supports.a_m = geometry.a_m;
  problem.supports.b_m = geometry.b_m;
  try {
    const StaticSolution statics = solve_statics(problem);
    if (!statics.converged) {
      why = "statics did not converge: " + statics.message;
      return false;
    }
    for (int j = 0; j <= 2000; ++j) {
      const double z = statics.position_m(segment.length_m * j / 2000.0).y();
      if (z < seabed_z - 1e-9 * (std::abs(seabed_z) + 1.0)) return true;
    }
  } catch (const InvalidInput& error) {
    why = error.what();
  }
  return false;
}

ImportedScene convert_chain(const Topology& t,
                            const std::vector<ChainSegment>& chain,
                            const std::string& stem) {
  ImportedScene scene;
  internal::ChainDescription d = internal::describe_chain(t.deck, chain, t.points);
  for (const auto& segment : d.chain) scene.lines.push_back(segment.line);
  const bool general = d.segments.size() > 1 || d.segments[0].weight_n_per_m <= 0.0;
  bool touches = false;
  if (d.seabed_z) {
    if (general) {
      touches = std::abs(d.geometry.a_m.y() - *d.seabed_z) <= 1e-6 * (std::abs(*d.seabed_z) + 1.0);
    } else {
      std::string why;
      touches = uniform_line_touches(d.segments[0], d.geometry, *d.seabed_z, why);
      if (!why.empty()) {
        scene.reason = why;
        return scene;
      }
    }
  }
  if (d.segments.size() > 1) scene.needs.push_back("[line] with segments (general lines)");
  if (!d.points.empty()) scene.needs.push_back("[[line.points]] point attachments (general lines)");
  if (d.segments.size() == 1 && d.segments[0].weight_n_per_m <= 0.0)
    scene.needs.push_back("[line] with zero or negative weight (general lines)");
  if (touches) scene.needs.push_back("[seabed] (seabed contact)");
  std::string ids;
  for (int id : scene.lines) ids += (ids.empty() ? "" : "-") + std::to_string(id);
  const std::string name = fmt::format("{}-line-{}", stem, ids);
  scene.file_name = name + ".toml";
  scene.toml = internal::scene_text(d, name, scene.needs, touches, general);
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
      out.push_back({{line.id}, "", "", {}, topology.reasons.at(line.id)});
      done.insert(line.id);
      continue;
    }
    std::string why;
    const std::vector<ChainSegment> chain = build_chain(topology, line.id, why);
    if (chain.empty()) {
      out.push_back({{line.id}, "", "", {}, why});
      done.insert(line.id);
      continue;
    }
    for (const auto& segment : chain) done.insert(segment.line);
    out.push_back(convert_chain(topology, chain, stem));
  }
  return out;
}

}  // namespace catena
