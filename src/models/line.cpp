// SPDX-License-Identifier: MIT
#include "catena/models/line.hpp"

#include <fmt/format.h>

#include <cmath>

#include "catena/core/error.hpp"
#include "catena/models/cable.hpp"

namespace catena {
namespace {

// Throws InvalidInput naming `line.<field>` unless `value` is finite and within the magnitude
// bounds of a cable value (docs/reference/scene-format.md, "Limits"); `sign` > 0: must be > 0, 0:
// >= 0, any other: any sign.
void require_value(double value,
                   const std::string& field,
                   const char* unit,
                   int sign,
                   double largest = kMaxCableMagnitude) {
  const char* rule = sign > 0 ? "finite and > 0" : sign == 0 ? "finite and >= 0" : "finite";
  const bool sign_ok = sign > 0 ? value > 0.0 : sign == 0 ? value >= 0.0 : true;
  if (!std::isfinite(value) || !sign_ok) {
    throw InvalidInput(
        fmt::format("Invalid line.{} = {}: must be {} [{}]", field, value, rule, unit));
  }
  const double magnitude = std::abs(value);
  if (magnitude != 0.0 && (magnitude < kMinCableMagnitude || magnitude > largest)) {
    throw InvalidInput(
        fmt::format("Invalid line.{} = {}: its magnitude must be in [{:g}, {:g}] [{}] "
                    "(beyond, the statics overflow or underflow)",
                    field, value, kMinCableMagnitude, largest, unit));
  }
}

}  // namespace

void validate_drag(const MorisonDrag& drag, const std::string& prefix) {
  const double d = drag.diameter_m;
  if (!std::isfinite(d) || d < 0.0 || (d > 0.0 && d < kMinCableMagnitude) ||
      d > kMaxCableMagnitude) {
    throw InvalidInput(
        fmt::format("Invalid {}diameter = {}: must be finite and > 0 [m]", prefix, d));
  }
  const std::pair<double, const char*> coefficients[] = {{drag.normal, "drag_normal"},
                                                         {drag.tangential, "drag_tangential"}};
  for (const auto& [value, key] : coefficients) {
    if (!std::isfinite(value) || value < 0.0 || value > 1e6) {
      throw InvalidInput(
          fmt::format("Invalid {}{} = {}: must be finite and in [0, 1e6] [-]", prefix, key, value));
    }
    if (value > 0.0 && d == 0.0) {
      throw InvalidInput(
          fmt::format("Invalid {}{} = {}: a drag coefficient needs the hydrodynamic diameter; give "
                      "{}diameter [m]",
                      prefix, key, value, prefix));
    }
  }
}

namespace {

void validate_segment(const LineSegment& segment, std::size_t index) {
  const std::string name = fmt::format("segments[{}].", index);
  require_value(segment.length_m, name + "length", "m", 1);
  require_value(segment.weight_n_per_m, name + "weight", "N/m", -1);
  require_value(segment.mass_kg_per_m, name + "mass", "kg/m", 1);
  require_value(segment.added_mass_kg_per_m, name + "added_mass", "kg/m", 0);
  const double ea = segment.axial_stiffness_n;
  if (std::isnan(ea) || ea <= 0.0) {
    throw InvalidInput(
        fmt::format("Invalid line.{}EA = {}: must be > 0 or \"inf\" (inextensible) [N]", name, ea));
  }
  if (!segment.is_inextensible()) require_value(ea, name + "EA", "N", 1, kMaxAxialStiffness);
  require_value(segment.damping.tangential_n_s_per_m2, name + "damping_tangential", "N s/m per m",
                0);
  require_value(segment.damping.normal_n_s_per_m2, name + "damping_normal", "N s/m per m", 0);
  require_value(segment.damping.axial_n_s, name + "axial_damping", "N s", 0);
  require_value(segment.added_mass_tangential_kg_per_m, name + "added_mass_tangential", "kg/m", 0);
  validate_drag(segment.drag, "line." + name);
  if (segment.is_inextensible() && segment.damping.axial_n_s > 0.0) {
    throw InvalidInput(fmt::format(
        "Invalid line.{}axial_damping = {}: an inextensible segment (EA = inf) has no axial "
        "strain to damp; give a finite EA or remove axial_damping [N s]",
        name, segment.damping.axial_n_s));
  }
}

void validate_point(const PointAttachment& point,
                    std::size_t index,
                    double length,
                    double previous_s) {
  const std::string name = fmt::format("points[{}].", index);
  require_value(point.s_m, name + "s", "m", 0);
  if (!(point.s_m > 1e-9 * length && point.s_m < length * (1.0 - 1e-9))) {
    throw InvalidInput(
        fmt::format("Invalid line.{}s = {}: must be strictly inside the line, 0 < s < L = {} [m] "
                    "(a load at an end is carried by the support)",
                    name, point.s_m, length));
  }
  if (!(point.s_m > previous_s + 1e-9 * length)) {
    throw InvalidInput(
        fmt::format("Invalid line.{}s = {}: points must be in increasing order of s and apart "
                    "(the previous point is at s = {} m); merge points at the same place",
                    name, point.s_m, previous_s));
  }
  require_value(point.mass_kg, name + "mass", "kg", 0);
  require_value(point.weight_n, name + "weight", "N", -1);
  require_value(point.added_mass_kg, name + "added_mass", "kg", 0);
  const std::optional<double>* directional[] = {&point.added_mass_tangential_kg,
                                                &point.added_mass_normal_kg,
                                                &point.added_mass_outofplane_kg};
  const char* keys[] = {"added_mass_tangential", "added_mass_normal", "added_mass_outofplane"};
  for (int i = 0; i < 3; ++i) {
    if (*directional[i]) require_value(**directional[i], name + keys[i], "kg", 0);
  }
}

}  // namespace

bool LineSegment::is_inextensible() const { return std::isinf(axial_stiffness_n); }

double Line::length_m() const { return segment_start_m(segments.size()); }

double Line::segment_start_m(std::size_t index) const {
  double s = 0.0;
  for (std::size_t i = 0; i < index && i < segments.size(); ++i) s += segments[i].length_m;
  return s;
}

bool Line::is_inextensible() const {
  for (const LineSegment& segment : segments) {
    if (!segment.is_inextensible()) return false;
  }
  return true;
}

void Line::validate() const {
  if (segments.empty())
    throw InvalidInput("Invalid line.segments: a line needs at least one segment");
  for (std::size_t i = 0; i < segments.size(); ++i) validate_segment(segments[i], i);
  const double length = length_m();
  double previous_s = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    validate_point(points[i], i, length, previous_s);
    previous_s = points[i].s_m;
  }
}

bool Line::is_damped() const {
  for (const LineSegment& segment : segments) {
    if (!segment.damping.is_zero()) return true;
  }
  return false;
}

bool Line::has_drag() const {
  for (const LineSegment& segment : segments) {
    if (!segment.drag.is_zero()) return true;
  }
  return false;
}

bool Line::has_tangential_added_mass() const {
  for (const LineSegment& segment : segments) {
    if (segment.added_mass_tangential_kg_per_m != 0.0) return true;
  }
  return false;
}

Line line_of_cable(const CableProperties& cable) {
  Line line;
  line.segments.push_back({cable.length_m, cable.weight_n_per_m, cable.axial_stiffness_n,
                           cable.mass_kg_per_m, cable.added_mass_kg_per_m, cable.damping,
                           cable.added_mass_tangential_kg_per_m, cable.drag});
  return line;
}

}  // namespace catena
