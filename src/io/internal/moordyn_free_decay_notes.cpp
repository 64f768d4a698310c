// SPDX-License-Identifier: MIT
// What makes a MoorDyn free decay non-linear: see moordyn_free_decay_notes.hpp and
// docs/how-to/moordyn-free-decay.md. MoorDyn's terms are those of its source/Line.cpp
// (FloatingArrayDesign/MoorDyn): drag 1/2 rho_w Cd d l |vp| vp and 1/2 rho_w CdAx pi d l |vq| vq,
// segment tension EA strain only while the strain is positive, seabed force (kBot penetration -
// cBot velocity) d l only while a node is below the seabed.
#include "io/internal/moordyn_free_decay_notes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace catena::internal {
namespace {

// Samples of the static line for its extreme values: fine enough that the sampled sag and lowest
// tension are within 1e-6 of their extremes on a smooth catenary (the error is quadratic in the
// spacing near an extremum); the lowest point and every contact boundary are added exactly.
constexpr int kSamples = 2000;

// The segment of the chain at unstretched arc length s (at a joint: the one toward B).
const SegmentProperties& segment_at(const ChainDescription& d, double s) {
  double end = 0.0;
  for (const auto& segment : d.segments) {
    end += segment.length_m;
    if (s < end) return segment;
  }
  return d.segments.back();
}

struct StaticExtremes {
  double sag_m = 0.0;  // largest distance of the line from its chord
  double lowest_tension_n = std::numeric_limits<double>::infinity();
  double lowest_tension_s_m = 0.0;
  double largest_tension_n = 0.0;
};

StaticExtremes extremes(const StaticSolution& statics, double length_m) {
  std::vector<double> stations;
  for (int i = 0; i <= kSamples; ++i) stations.push_back(length_m * i / kSamples);
  stations.push_back(statics.lowest_point_s_m());
  for (const auto& interval : statics.contact_intervals()) {
    stations.push_back(interval.s_begin_m);
    stations.push_back(interval.s_end_m);
  }
  const Vec2 a = statics.position_m(0.0);
  const Vec2 chord = statics.position_m(length_m) - a;
  const Vec2 across = Vec2(-chord.y(), chord.x()).normalized();
  StaticExtremes out;
  for (double s : stations) {
    const double tension = statics.tension_n(s);
    out.sag_m = std::max(out.sag_m, std::abs(across.dot(statics.position_m(s) - a)));
    out.largest_tension_n = std::max(out.largest_tension_n, tension);
    if (tension < out.lowest_tension_n) {
      out.lowest_tension_n = tension;
      out.lowest_tension_s_m = s;
    }
  }
  return out;
}

// The amplitude scale l of the non-linear terms. In the equations of motion about the statics
// (docs/explanation/physics.md) the dynamic strain of a transverse displacement w is y' w' + w'^2
// / 2 (y the static shape): against the linear stiffness, of order EA d^2 / L^4 + H / L^2 per
// metre, the quadratic term is of relative size ~ a d / l^2 and the cubic one ~ a^2 / l^2 with
// l^2 = d^2 + L^2 H / EA. A sagging line (d large) has l ~ d, a taut one l ~ L sqrt(H / EA).
std::string amplitude_note(const ChainDescription& d,
                           const StaticSolution& statics,
                           double length_m,
                           const StaticExtremes& e) {
  double compliance = 0.0;  // sum of L_i / EA_i [m/N]
  for (const auto& segment : d.segments) compliance += segment.length_m / segment.axial_stiffness_n;
  const double H = statics.horizontal_force_n();
  const double stretch = length_m * std::sqrt(H * compliance / length_m);
  const double scale = std::hypot(e.sag_m, stretch);
  return fmt::format(
      "Free decay: small means an amplitude a << l = sqrt(d^2 + L^2 H/EA) = {:.4g} m (sag from "
      "the chord d = {:.4g} m, L sqrt(H/EA) = {:.4g} m with EA the line's series stiffness): the "
      "non-linear terms are of relative size a/l (harmonics at twice the frequencies and a shift "
      "of the mean, in the tension too) and shift the frequencies by about (a/l)^2: a <= {:.3g} m "
      "(a/l = 0.01) keeps the harmonics near 1 % and the frequency shift near 1e-4 "
      "(docs/how-to/moordyn-free-decay.md).",
      scale, e.sag_m, stretch, 0.01 * scale);
}

std::string tension_note(const StaticSolution& statics, const StaticExtremes& e) {
  if (!(statics.horizontal_force_n() > 0.0)) {
    return "Free decay: the line is slack (H = 0, zero tension where it leaves the seabed): "
           "MoorDyn's segments at zero tension carry no compression and fold, so no decay of it "
           "is linear (Catena's solvers decline its dynamics).";
  }
  const double fraction = e.lowest_tension_n / e.largest_tension_n;
  return fmt::format(
      "Free decay: {}lowest static tension {:.4g} N at s = {:.4g} m ({:.3g} % of the largest, "
      "{:.4g} N). MoorDyn's segments carry no compression (a segment whose strain turns negative "
      "goes slack), so a decay is linear only while its dynamic tension stays below {:.4g} N "
      "everywhere{}.",
      fraction < kNearlySlackFraction ? "nearly slack: " : "", e.lowest_tension_n,
      e.lowest_tension_s_m, 100.0 * fraction, e.largest_tension_n, e.lowest_tension_n,
      fraction < kNearlySlackFraction ? " (a release that changes the fairlead tension by more "
                                        "than that slackens the line)"
                                      : "");
}

std::string touchdown_list(const StaticSolution& statics, double length_m) {
  std::string out;
  const double end_tolerance = 1e-9 * length_m;
  for (const auto& interval : statics.contact_intervals()) {
    for (double s : {interval.s_begin_m, interval.s_end_m}) {
      if (s > end_tolerance && s < length_m - end_tolerance)
        out += fmt::format("{}s = {:.4g} m", out.empty() ? "" : ", ", s);
    }
  }
  return out.empty() ? "none" : out;
}

std::string contact_note(const ChainDescription& d,
                         const StaticSolution& statics,
                         double length_m) {
  const double seabed_z = *d.seabed.z_m;
  if (!statics.has_contact()) {
    const double s_low = statics.lowest_point_s_m();
    const double lowest = statics.position_m(s_low).y();
    const bool at_end = s_low <= 1e-9 * length_m || s_low >= (1.0 - 1e-9) * length_m;
    if (at_end && lowest - seabed_z <= 1e-9 * (std::abs(seabed_z) + 1.0)) {
      // An anchor on the seabed with the line rising from it: the held end does not move.
      const double angle = std::abs(statics.angle_rad(s_low)) * 180.0 / kPi;
      return fmt::format(
          "Free decay: the line touches the seabed only at its held end (z = {:.6g} m at s = "
          "{:.4g} m) and rises from it at {:.3g} deg: small motions do not reach the seabed.",
          lowest, s_low, angle);
    }
    return fmt::format(
        "Free decay: the line is off the seabed, its lowest point {:.4g} m above it (z = {:.6g} "
        "m at s = {:.4g} m): a motion that large there touches it, and MoorDyn's contact then "
        "makes the decay non-linear.",
        lowest - seabed_z, lowest, statics.lowest_point_s_m());
  }
  // MoorDyn's grounded node sits below the seabed by its weight over the contact stiffness; it
  // lifts off (the contact force is one-sided) once it rises by more than that.
  const double weight = segment_at(d, statics.contact_intervals().front().s_begin_m).weight_n_per_m;
  const std::string penetration =
      d.seabed_stiffness_n_per_m2 > 0.0
          ? fmt::format("w / (kBot Diam) = {:.3g} mm", 1e3 * weight / d.seabed_stiffness_n_per_m2)
          : std::string("unbounded (kBot = 0)");
  return fmt::format(
      "Free decay: {:.4g} m rest on the seabed (touchdown at {}). MoorDyn's contact is one-sided: "
      "as the line moves its touchdown point moves, and a grounded node lifts off once it rises "
      "by its static penetration, {}. Catena's modes hold the grounded part on the linear spring "
      "kBot Diam and dashpot cBot Diam, which is exact only for motions at the touchdown well "
      "below that penetration; larger ones make the decay non-linear (the suspended length "
      "changes with the motion).",
      statics.grounded_length_m(), touchdown_list(statics, length_m), penetration);
}

}  // namespace

DragLinearity drag_linearity(const SegmentProperties& segment, double water_density) {
  constexpr double kFactor = 2.0 / (3.0 * kPi);
  DragLinearity out;
  const double normal_mass = segment.mass_kg_per_m + segment.added_mass_kg_per_m;
  const double tangential_mass = segment.mass_kg_per_m + segment.added_mass_tangential_kg_per_m;
  if (normal_mass > 0.0) {
    out.normal_per_metre =
        kFactor * water_density * segment.drag_normal * segment.diameter_m / normal_mass;
  }
  if (tangential_mass > 0.0) {
    out.tangential_per_metre = kFactor * water_density * segment.drag_tangential * kPi *
                               segment.diameter_m / tangential_mass;
  }
  return out;
}

std::vector<std::string> drag_notes(const ChainDescription& d) {
  std::vector<std::string> notes;
  for (const auto& segment : d.segments) {
    if (!(segment.diameter_m > 0.0) ||
        !(segment.drag_normal > 0.0 || segment.drag_tangential > 0.0))
      continue;
    const DragLinearity drag = drag_linearity(segment, d.water_density);
    notes.push_back(fmt::format(
        "Free decay: line {} (type {}) has quadratic drag, Cd = {:g}, CdAx = {:g}: its damping "
        "grows with the amplitude, at most a damping ratio of {:.3g} per metre of transverse "
        "amplitude ((2/3pi) rho_w Cd Diam / (MassDen + Ca rho_w pi/4 Diam^2); {:.3g} at 1 cm) and "
        "{:.3g} per metre along the line. Catena's damped modes do not contain it (their damping "
        "is BA's and, on the seabed, cBot's): set Cd = CdAx = 0 in the deck for an exact "
        "comparison.",
        segment.line, segment.type, segment.drag_normal, segment.drag_tangential,
        drag.normal_per_metre, 0.01 * drag.normal_per_metre, drag.tangential_per_metre));
  }
  return notes;
}

std::vector<std::string> free_decay_notes(const ChainDescription& d,
                                          const StaticSolution& statics,
                                          double length_m) {
  const StaticExtremes e = extremes(statics, length_m);
  std::vector<std::string> notes = {amplitude_note(d, statics, length_m, e),
                                    tension_note(statics, e)};
  if (d.seabed.z_m) notes.push_back(contact_note(d, statics, length_m));
  return notes;
}

}  // namespace catena::internal
