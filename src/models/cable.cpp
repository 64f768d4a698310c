// SPDX-License-Identifier: MIT
#include "catena/models/cable.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "catena/core/error.hpp"

namespace catena {
namespace {

void require_finite_positive(double value,
                             const char* field,
                             const char* unit,
                             double largest = kMaxCableMagnitude) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InvalidInput(fmt::format("Invalid CableProperties::{} = {}: must be finite and > 0 [{}]",
                                   field, value, unit));
  }
  if (value < kMinCableMagnitude || value > largest) {
    throw InvalidInput(
        fmt::format("Invalid CableProperties::{} = {}: must be in [{:g}, {:g}] [{}] (beyond, the "
                    "statics overflow or underflow)",
                    field, value, kMinCableMagnitude, largest, unit));
  }
}

}  // namespace

bool CableProperties::is_inextensible() const { return std::isinf(axial_stiffness_n); }

void CableProperties::validate() const {
  require_finite_positive(length_m, "length_m", "m");
  require_finite_positive(weight_n_per_m, "weight_n_per_m", "N/m");
  require_finite_positive(mass_kg_per_m, "mass_kg_per_m", "kg/m");
  if (std::isnan(axial_stiffness_n) || axial_stiffness_n <= 0.0 ||
      axial_stiffness_n == -kInfinity) {
    throw InvalidInput(fmt::format(
        "Invalid CableProperties::axial_stiffness_n = {}: must be > 0 or +inf (inextensible) [N]",
        axial_stiffness_n));
  }
  if (!is_inextensible())
    require_finite_positive(axial_stiffness_n, "axial_stiffness_n", "N", kMaxAxialStiffness);
  if (!std::isfinite(added_mass_kg_per_m) || added_mass_kg_per_m < 0.0) {
    throw InvalidInput(fmt::format(
        "Invalid CableProperties::added_mass_kg_per_m = {}: must be finite and >= 0 [kg/m]",
        added_mass_kg_per_m));
  }
  if (added_mass_kg_per_m > 0.0)
    require_finite_positive(added_mass_kg_per_m, "added_mass_kg_per_m", "kg/m");
  validate_damping();
  validate_hydrodynamics();
}

void CableProperties::validate_hydrodynamics() const {
  if (!std::isfinite(added_mass_tangential_kg_per_m) || added_mass_tangential_kg_per_m < 0.0 ||
      added_mass_tangential_kg_per_m > kMaxCableMagnitude) {
    throw InvalidInput(
        fmt::format("Invalid cable.added_mass_tangential = {}: must be finite and >= 0 [kg/m]",
                    added_mass_tangential_kg_per_m));
  }
  validate_drag(drag, "cable.");
}

void Environment::validate() const {
  if (!std::isfinite(water_density_kg_per_m3) || !(water_density_kg_per_m3 > 0.0) ||
      water_density_kg_per_m3 > 1e5) {
    throw InvalidInput(fmt::format(
        "Invalid environment.water_density = {}: must be finite and in (0, 1e5] [kg/m^3]",
        water_density_kg_per_m3));
  }
  if (!std::isfinite(gravity_m_per_s2) || !(gravity_m_per_s2 > 0.0) || gravity_m_per_s2 > 1e3) {
    throw InvalidInput(
        fmt::format("Invalid environment.gravity = {}: must be finite and in (0, 1e3] [m/s^2]",
                    gravity_m_per_s2));
  }
}

void CableProperties::validate_damping() const {
  struct Coefficient {
    double value;
    const char* field;
    const char* unit;
  };
  const Coefficient coefficients[] = {
      {damping.tangential_n_s_per_m2, "damping_tangential", "N s/m per m"},
      {damping.normal_n_s_per_m2, "damping_normal", "N s/m per m"},
      {damping.axial_n_s, "axial_damping", "N s"}};
  for (const Coefficient& c : coefficients) {
    if (!std::isfinite(c.value) || c.value < 0.0) {
      throw InvalidInput(fmt::format("Invalid cable.{} = {}: must be finite and >= 0 [{}]", c.field,
                                     c.value, c.unit));
    }
    if (c.value > 0.0) require_finite_positive(c.value, c.field, c.unit);
  }
  if (is_inextensible() && damping.axial_n_s > 0.0) {
    throw InvalidInput(fmt::format(
        "Invalid cable.axial_damping = {}: an inextensible cable (EA = inf) has no axial strain to "
        "damp; give a finite EA or remove axial_damping [N s]",
        damping.axial_n_s));
  }
}

void Supports::validate() const {
  for (int i = 0; i < 2; ++i) {
    if (!(std::abs(a_m[i]) <= kMaxCableMagnitude) || !(std::abs(b_m[i]) <= kMaxCableMagnitude)) {
      throw InvalidInput(
          fmt::format("Invalid Supports: a = ({}, {}), b = ({}, {}): coordinates must "
                      "be finite and within +-{:g} [m]",
                      a_m.x(), a_m.y(), b_m.x(), b_m.y(), kMaxCableMagnitude));
    }
  }
  // hypot: the squares of large coordinates must not overflow into "coincident" ends.
  const double scale = std::max({1.0, std::hypot(a_m.x(), a_m.y()), std::hypot(b_m.x(), b_m.y())});
  if (std::hypot(chord_m().x(), chord_m().y()) <= 1e-12 * scale) {
    throw InvalidInput(
        fmt::format("Invalid Supports: a = ({}, {}) and b = ({}, {}) coincide; the "
                    "ends must be apart",
                    a_m.x(), a_m.y(), b_m.x(), b_m.y()));
  }
  if (b_m.x() < a_m.x()) {
    throw InvalidInput(fmt::format(
        "Invalid Supports: b.x = {} < a.x = {}: support b must not be left of support a "
        "(s runs from a to b with x increasing; swap a and b)",
        b_m.x(), a_m.x()));
  }
}

std::string to_string(ProblemForm form) {
  switch (form) {
    case ProblemForm::Physical:
      return "cable";
    case ProblemForm::TautInclined:
      return "taut_inclined";
    case ProblemForm::GaleXi:
      return "gale_xi";
    case ProblemForm::GaleSag:
      return "gale_sag";
  }
  return "unknown";
}

bool Problem::is_damped() const {
  const bool line_damped = is_uniform() ? !cable.damping.is_zero() : line.is_damped();
  return line_damped || (seabed && seabed->damping_n_s_per_m2 > 0.0);
}

bool Problem::has_drag() const { return is_uniform() ? !cable.drag.is_zero() : line.has_drag(); }

bool Problem::has_tangential_added_mass() const {
  return is_uniform() ? cable.added_mass_tangential_kg_per_m != 0.0
                      : line.has_tangential_added_mass();
}

Line Problem::as_line() const { return is_uniform() ? line_of_cable(cable) : line; }

void Problem::validate() const {
  if (is_uniform()) {
    cable.validate();
  } else {
    line.validate();
    if (prescribed_forces) {
      throw InvalidInput(
          "Invalid Problem::prescribed_forces: a general line is solved from its geometry only");
    }
  }
  supports.validate();
  environment.validate();
  if (seabed) validate_seabed();
}

// The largest seabed stiffness k against the line's weight W (total |weight|) and length L:
// k L^2 / W <= 1e16. k enters the dynamics beside the tension's stiffness ~ T / L^2 ~ W / L^2
// (fe adds k l to T / l per node; shooting integrates e^(L sqrt(k / T)), L sqrt(k / T) ~
// sqrt(k L^2 / W) e-folds): beyond 1e16 the tension's part is below double precision's rounding of
// the foundation's, and the grounded run's growth beyond the 1e8 e-folds a shot carries. Real
// soils are below 1e9 N/m per m (k L^2 / W ~ 1e10 for a 1000 m chain of 1200 N/m).
constexpr double kMaxFoundationToWeight = 1e16;

void Problem::validate_seabed() const {
  seabed->validate();
  const Line whole = as_line();
  double weight = 0.0;
  for (const LineSegment& segment : whole.segments)
    weight += std::abs(segment.weight_n_per_m) * segment.length_m;
  for (const PointAttachment& point : whole.points) weight += std::abs(point.weight_n);
  const double L = whole.length_m();
  for (const auto& [field, k] :
       {std::pair{"stiffness", seabed->stiffness_n_per_m2},
        std::pair{"tangential_stiffness", seabed->tangential_stiffness_n_per_m2}}) {
    if (weight > 0.0 && k * L * L > kMaxFoundationToWeight * weight) {
      throw InvalidInput(fmt::format(
          "Invalid seabed.{} = {:g}: k L^2 / W = {:.3g} exceeds {:g}, beyond what double precision "
          "carries beside the line's own stiffness (L = {:g} m, total |weight| W = {:g} N): at "
          "most {:.3g} N/m per m for this line",
          field, k, k * L * L / weight, kMaxFoundationToWeight, L, weight,
          kMaxFoundationToWeight * weight / (L * L)));
    }
  }
  const double z = seabed->z_m;
  const double tolerance = 1e-9 * std::max(1.0, std::abs(z));
  if (supports.a_m.y() < z - tolerance) {
    throw InvalidInput(
        fmt::format("Invalid seabed.z = {}: end A must not be below the seabed; a.z = {} [m]", z,
                    supports.a_m.y()));
  }
  if (supports.b_m.y() < z - tolerance) {
    throw InvalidInput(
        fmt::format("Invalid seabed.z = {}: end B (the fairlead) must not be below the seabed; "
                    "b.z = {} [m]",
                    z, supports.b_m.y()));
  }
  if (prescribed_forces) {
    throw InvalidInput(
        "Invalid Problem::prescribed_forces: a line on a seabed is solved from its geometry only");
  }
}

}  // namespace catena
