// SPDX-License-Identifier: MIT
#include "io/internal/moordyn_scene_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "io/internal/toml_text.hpp"

namespace catena::internal {
namespace {

int end_point_id(const std::string& end) {
  std::size_t first = 0;
  while (first < end.size() && !std::isdigit(static_cast<unsigned char>(end[first]))) ++first;
  return std::stoi(end.substr(first));
}

// The point a chain element is entered by (`entry`) or left by.
int point_of(const MoorDynDeck& deck, const ChainSegment& segment, bool entry) {
  const auto& line = *std::find_if(deck.lines.begin(), deck.lines.end(),
                                   [&](const MoorDynLine& l) { return l.id == segment.line; });
  return end_point_id(entry != segment.reversed ? line.end_a : line.end_b);
}

SegmentProperties segment_of(const MoorDynDeck& deck, int line_id) {
  const auto& line = *std::find_if(deck.lines.begin(), deck.lines.end(),
                                   [&](const MoorDynLine& l) { return l.id == line_id; });
  const auto& type = *std::find_if(deck.types.begin(), deck.types.end(),
                                   [&](const MoorDynLineType& t) { return t.name == line.type; });
  const double area = kPi / 4.0 * type.diameter_m * type.diameter_m;
  const double rho = deck.water_density();
  SegmentProperties segment;
  segment.line = line.id;
  segment.type = type.name;
  segment.length_m = line.length_m;
  segment.weight_n_per_m = (type.mass_kg_per_m - rho * area) * deck.gravity();
  segment.axial_stiffness_n = *type.axial_stiffness_n;
  segment.mass_kg_per_m = type.mass_kg_per_m;
  segment.added_mass_kg_per_m = type.normal_added_mass_coefficient * rho * area;
  segment.diameter_m = type.diameter_m;
  // MoorDyn's drag acts on Diam (normal) and on the perimeter pi Diam (tangential), as Catena's
  // MorisonDrag does (Line.cpp: Dp = 1/2 rho Cdn d l |vp| vp, Dq = 1/2 rho Cdt pi d l |vq| vq);
  // its tangential added mass is rho_w Cat times the volume (Line.cpp: M = m + rho_w V (Can (I -
  // Q) + Cat Q)).
  segment.drag_normal = type.normal_drag_coefficient;
  segment.drag_tangential = type.tangential_drag_coefficient;
  segment.added_mass_tangential_kg_per_m = type.tangential_added_mass_coefficient * rho * area;
  segment.deck_segments = line.segments;
  // BA is the coefficient of MoorDyn's segment strain rate, Td = BA d(eps)/dt [N s]: Catena's
  // Kelvin-Voigt c_a, tau = EA eps + c_a d(eps)/dt. A negative BA is minus a damping ratio zeta,
  // which MoorDyn-C turns into BA = zeta (UnstrLen / N) sqrt(EA rho A) with rho A = MassDen (its
  // Line::initialize, source/Line.cpp, FloatingArrayDesign/MoorDyn): zeta of the critical damping
  // of ONE of its N segments' axial mode. The coefficient therefore depends on the deck's segment
  // count; converting with that count gives the damping MoorDyn actually applies (a continuum
  // line has no segment, so it cannot keep "zeta" itself).
  const double ba = *type.axial_damping;
  if (ba < 0.0) {
    segment.damping_ratio = -ba;
    segment.axial_damping_n_s = -ba * line.length_m / line.segments *
                                std::sqrt(*type.axial_stiffness_n * type.mass_kg_per_m);
  } else {
    segment.axial_damping_n_s = ba;
  }
  return segment;
}

// A TOML float (always with a '.' or an exponent: "400" would be an integer).
std::string number(double value) {
  std::string text = fmt::format("{:.15g}", value);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

}  // namespace

std::string scene_header(const ChainDescription& d,
                         const std::string& name,
                         const std::vector<std::string>& notes,
                         const std::vector<MoorDynNote>& deck_notes) {
  const auto point_text = [](const MoorDynPoint* p) {
    return fmt::format("point {} ({}) at ({}, {}, {}) m", p->id, p->attachment, p->x_m, p->y_m,
                       p->z_m);
  };
  std::string lines;
  for (const auto& s : d.segments)
    lines += fmt::format("{}{} (type {})", lines.empty() ? "" : ", ", s.line, s.type);
  std::string out = fmt::format(
      "# Imported by `catena import moordyn` from {} (docs/how-to/moordyn-import.md).\n",
      d.deck_file);
  out += fmt::format("# MoorDyn line(s) {}, end A = {}, end B = {}.\n", lines,
                     point_text(d.geometry.end_a), point_text(d.geometry.end_b));
  out +=
      "# The vertical plane through the two ends: x = horizontal distance from end A, z = "
      "MoorDyn's z.\n";
  out += fmt::format(
      "# weight = (MassDen - rho_w pi/4 Diam^2) g, added_mass = Ca rho_w pi/4 Diam^2; g = {} "
      "m/s^2, "
      "rho_w = {} kg/m^3.\n",
      d.gravity, d.water_density);
  out += fmt::format(
      "# diameter = Diam, drag_normal = Cd, drag_tangential = CdAx (on pi Diam), "
      "added_mass_tangential = CaAx rho_w pi/4 Diam^2, axial_damping = BA [N s].\n");
  for (const auto& s : d.segments) {
    if (s.damping_ratio < 0.0) continue;
    out += fmt::format(
        "# Line {}: BA = -{} is a damping ratio: axial_damping = {} (UnstrLen / NumSegs) "
        "sqrt(EA MassDen) = {:.6g} N s with the deck's NumSegs = {} (MoorDyn's rule; it depends on "
        "the deck's segment count).\n",
        s.line, s.damping_ratio, s.damping_ratio, s.axial_damping_n_s, s.deck_segments);
  }
  for (const auto& note : notes) out += "# " + note + "\n";
  out += "# What became of the rest of the deck:\n";
  for (const auto& note : deck_notes)
    out += fmt::format("#   {}: {} - {}\n", note.item, note.fate, note.detail);
  // The deck's names and its file name are another program's text: escaped, and made valid
  // UTF-8, before they enter the scene (toml_text.hpp).
  return toml_comment_text(out) +
         fmt::format("name = {}\ndescription = {}\ntags = [\"moordyn-import\"]\n\n",
                     toml_string(name),
                     toml_string(fmt::format("MoorDyn line(s) {} of {}", lines, d.deck_file)));
}

namespace {

// The hydrodynamic and damping keys of a section (docs/reference/scene-format.md); a deck's zero
// diameter gives no drag keys (a diameter in a scene must be > 0).
std::string hydrodynamic_keys(const SegmentProperties& s) {
  std::string out;
  if (s.diameter_m > 0.0) {
    out += fmt::format("diameter = {}\ndrag_normal = {}\ndrag_tangential = {}\n",
                       number(s.diameter_m), number(s.drag_normal), number(s.drag_tangential));
  }
  return out + fmt::format("added_mass_tangential = {}\naxial_damping = {}\n",
                           number(s.added_mass_tangential_kg_per_m), number(s.axial_damping_n_s));
}

std::string cable_table(const ChainDescription& d) {
  const SegmentProperties& s = d.segments.front();
  return fmt::format(
      "[cable]\nlength = {}\nweight = {}\nEA = {}\nmass = {}\nadded_mass = {}\n{}a = [{}, {}]\n"
      "b = [{}, {}]\n\n",
      number(s.length_m), number(s.weight_n_per_m), number(s.axial_stiffness_n),
      number(s.mass_kg_per_m), number(s.added_mass_kg_per_m), hydrodynamic_keys(s),
      number(d.geometry.a_m.x()), number(d.geometry.a_m.y()), number(d.geometry.b_m.x()),
      number(d.geometry.b_m.y()));
}

std::string line_table(const ChainDescription& d) {
  std::string out = fmt::format("[line]\na = [{}, {}]\nb = [{}, {}]\n", number(d.geometry.a_m.x()),
                                number(d.geometry.a_m.y()), number(d.geometry.b_m.x()),
                                number(d.geometry.b_m.y()));
  for (const auto& s : d.segments) {
    out += fmt::format(
        "[[line.segments]]                 # MoorDyn line {}\nlength = {}\nweight = {}\nEA = "
        "{}\nmass = {}\n"
        "added_mass = {}\n{}",
        s.line, number(s.length_m), number(s.weight_n_per_m), number(s.axial_stiffness_n),
        number(s.mass_kg_per_m), number(s.added_mass_kg_per_m), hydrodynamic_keys(s));
  }
  for (const auto& p : d.points) {
    out += fmt::format(
        "[[line.points]]                   # MoorDyn point {}\ns = {}\nmass = {}\nweight = "
        "{}\nadded_mass = {}\n",
        p.point, number(p.s_m), number(p.mass_kg), number(p.weight_n), number(p.added_mass_kg));
  }
  return out + "\n";
}

}  // namespace

ChainDescription describe_chain(const MoorDynDeck& deck,
                                std::vector<ChainSegment> chain,
                                const std::map<int, const MoorDynPoint*>& points) {
  // End A is the lower held end (the anchor): reverse the chain when it starts higher.
  if (points.at(point_of(deck, chain.front(), true))->z_m >
      points.at(point_of(deck, chain.back(), false))->z_m) {
    std::reverse(chain.begin(), chain.end());
    for (auto& segment : chain) segment.reversed = !segment.reversed;
  }
  ChainDescription d;
  d.deck_file = deck.file;
  d.chain = chain;
  d.gravity = deck.gravity();
  d.water_density = deck.water_density();
  d.geometry.end_a = points.at(point_of(deck, chain.front(), true));
  d.geometry.end_b = points.at(point_of(deck, chain.back(), false));
  const MoorDynPoint& a = *d.geometry.end_a;
  const MoorDynPoint& b = *d.geometry.end_b;
  d.geometry.a_m = Vec2(0.0, a.z_m);
  d.geometry.b_m = Vec2(std::hypot(b.x_m - a.x_m, b.y_m - a.y_m), b.z_m);
  double s = 0.0;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    d.segments.push_back(segment_of(deck, chain[i].line));
    s += d.segments.back().length_m;
    if (i + 1 == chain.size()) break;
    const MoorDynPoint& joint = *points.at(point_of(deck, chain[i], false));
    // A joint without mass or volume is only where the properties change: no attachment.
    if (joint.mass_kg != 0.0 || joint.volume_m3 != 0.0) {
      d.points.push_back({joint.id, s, joint.mass_kg,
                          (joint.mass_kg - d.water_density * joint.volume_m3) * d.gravity,
                          joint.added_mass_coefficient * d.water_density * joint.volume_m3});
    }
  }
  d.seabed = moordyn_seabed(deck);
  d.bottom_stiffness_pa_per_m = deck.bottom_stiffness();
  d.bottom_damping_pa_s_per_m = deck.bottom_damping();
  // MoorDyn's contact force per node is (kBot penetration - cBot velocity) Diam l: per unit
  // length kBot Diam and cBot Diam (source/Line.cpp). Catena's seabed has one stiffness, so the
  // diameter is the one at end A (the scene's header says so when the segments differ).
  d.seabed_stiffness_n_per_m2 = d.bottom_stiffness_pa_per_m * d.segments.front().diameter_m;
  d.seabed_damping_n_s_per_m2 = d.bottom_damping_pa_s_per_m * d.segments.front().diameter_m;
  return d;
}

std::string scene_tables(const ChainDescription& d, bool as_line) {
  std::string out = as_line ? line_table(d) : cable_table(d);
  // The deck's water (WtrDnsty/rho, g/gravity; MoorDyn's defaults when silent): the Morison drag's
  // density; the weights above were computed with both.
  out += fmt::format("[environment]\nwater_density = {}\ngravity = {}\n\n", number(d.water_density),
                     number(d.gravity));
  if (d.seabed.z_m) {
    out += fmt::format(
        "[seabed]                          # kBot {} Pa/m, cBot {} Pa s/m times Diam {} m at end "
        "A\nz = {}\nfriction = 0.0\nstiffness = {}\ndamping = {}\n\n",
        number(d.bottom_stiffness_pa_per_m), number(d.bottom_damping_pa_s_per_m),
        number(d.segments.front().diameter_m), number(*d.seabed.z_m),
        number(d.seabed_stiffness_n_per_m2), number(d.seabed_damping_n_s_per_m2));
  }
  return out + "[request]\ninplane_modes = 6\noutofplane_modes = 6\n";
}

}  // namespace catena::internal
