// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The cable and its supports in SI units (docs/explanation/physics.md), and the Problem every
/// solver answers.

#include <optional>
#include <string>

#include "catena/core/types.hpp"
#include "catena/models/line.hpp"
#include "catena/models/seabed.hpp"

namespace catena {

/// Bounds on the magnitude of every cable and support value in SI units (L, W0, EA, m, ma, the
/// support coordinates; docs/reference/scene-format.md, "Limits"). Outside them the statics
/// overflow or underflow: the tension scales as W0 L and Newton's Jacobian as its square and fourth
/// power. EA may also be +inf (inextensible); ma and coordinates may also be 0.
inline constexpr double kMinCableMagnitude = 1e-15;
inline constexpr double kMaxCableMagnitude = 1e15;
/// EA may be larger: a taut string of small static strain needs EA up to ~1e20 N (Grinfogel's
/// groups with eps = 1e-6, lambda2 = 1e4 at 89 deg), and EA enters the statics through its inverse
/// or times a strain. Beyond 1e30 N, write "inf".
inline constexpr double kMaxAxialStiffness = 1e30;

/// Material and section of a uniform cable, per unit *unstretched* length.
struct CableProperties {
  /// Unstretched length L [m]. Must be finite and > 0.
  double length_m = 1.0;
  /// Submerged weight per unit unstretched length W0 (weight minus buoyancy) [N/m].
  /// Must be finite and > 0 (a weightless cable has no catenary; use a tiny value for a string).
  double weight_n_per_m = 1.0;
  /// Axial stiffness EA [N]. Must be > 0; +infinity means inextensible.
  double axial_stiffness_n = kInfinity;
  /// Structural mass per unit unstretched length m [kg/m]. Must be finite and > 0.
  double mass_kg_per_m = 1.0;
  /// Added (hydrodynamic) mass per unit unstretched length ma [kg/m], acting in the normal
  /// directions only. Must be finite and >= 0.
  double added_mass_kg_per_m = 0.0;
  /// Linear drag and axial damping (docs/explanation/physics.md, "Damping"); zero: undamped.
  SectionDamping damping{};
  /// Added mass per unit unstretched length along the cable [kg/m] (MoorDyn's CaAx). Finite, >= 0.
  double added_mass_tangential_kg_per_m = 0.0;
  /// Morison drag (docs/explanation/dynamic-tension.md); zero: none.
  MorisonDrag drag{};

  /// M = m + ma: the mass that resists normal motion [kg/m].
  double normal_mass_kg_per_m() const { return mass_kg_per_m + added_mass_kg_per_m; }
  /// m + ma_t: the mass that resists tangential motion [kg/m].
  double tangential_mass_kg_per_m() const { return mass_kg_per_m + added_mass_tangential_kg_per_m; }
  /// True for EA = inf.
  bool is_inextensible() const;

  /// Throws InvalidInput naming the field, its value and the violated constraint (including the
  /// magnitude bounds kMinCableMagnitude..kMaxCableMagnitude).
  void validate() const;

 private:
  void validate_damping() const;
  void validate_hydrodynamics() const;
};

/// The water the line hangs in (docs/reference/scene-format.md, `[environment]`).
struct Environment {
  /// Water density rho [kg/m^3]: the Morison drag's. Finite and > 0.
  double water_density_kg_per_m3 = 1025.0;
  /// Gravitational acceleration g [m/s^2] (the weights are given directly; g is kept with the
  /// problem for the importer and the reports). Finite and > 0.
  double gravity_m_per_s2 = 9.80665;
  /// Throws InvalidInput naming `environment.water_density` or `environment.gravity`.
  void validate() const;
};

/// End points of the cable in one vertical plane: x horizontal, z up [m]. `s = 0` at `a`.
struct Supports {
  Vec2 a_m = Vec2(0.0, 0.0);
  Vec2 b_m = Vec2(1.0, 0.0);

  /// b - a [m].
  Vec2 chord_m() const { return b_m - a_m; }
  /// Throws InvalidInput for coordinates beyond kMaxCableMagnitude or coincident ends.
  void validate() const;
};

/// How a problem was specified (kept for reports; the physics is always the SI form).
enum class ProblemForm { Physical, TautInclined, GaleXi, GaleSag };

/// "cable", "taut_inclined", "gale_xi", "gale_sag".
std::string to_string(ProblemForm form);

/// The static end forces (H, V_A), when the static state is given by tension rather than by the
/// position of support b (see Problem::prescribed_forces).
struct EndForces {
  /// Horizontal component of the tension, >= 0 [N].
  double horizontal_n = 0.0;
  /// Vertical component of the tension at support a, along the tangent toward b [N].
  double vertical_a_n = 0.0;
};

/// A cable between two fixed supports: the input of statics and of every solver.
/// Either a uniform cable (`cable`, with `line` empty) or a general line (`line`: several
/// segments and point attachments; `cable` is then unused).
struct Problem {
  CableProperties cable;
  /// A general line; empty segments mean the uniform `cable`.
  Line line;
  Supports supports;
  ProblemForm form = ProblemForm::Physical;
  /// When set, the static state is these end forces and `supports.b_m` must be where they put
  /// the end of the cable (builders set both). Needed for taut cables: there the tension is
  /// determined by the chord only to about (rounding / static strain), e.g. 1e-2 relative for
  /// eps = 1e-6, so a tension-specified problem must not be re-solved from its geometry.
  std::optional<EndForces> prescribed_forces;
  /// A flat seabed under the line (docs/explanation/physics.md, "Seabed contact"): end A on or
  /// above it, end B above it. The statics then lays the line on it where it would go below it
  /// (catena/statics/seabed_statics.hpp).
  std::optional<Seabed> seabed;
  /// The water (Morison drag's density).
  Environment environment{};

  /// True when the line (or the cable) or the seabed has a non-zero damping coefficient: the
  /// natural frequencies become complex roots lambda = -delta + i omega_d
  /// (docs/explanation/physics.md, "Damping").
  bool is_damped() const;
  /// True when some section has Morison drag (docs/explanation/dynamic-tension.md).
  bool has_drag() const;
  /// True when some section has a tangential added mass.
  bool has_tangential_added_mass() const;
  /// True for the uniform `cable` (line.segments empty).
  bool is_uniform() const { return line.segments.empty(); }
  /// The line either way: `line`, or the one segment of `cable`.
  Line as_line() const;
  /// Total unstretched length [m].
  double length_m() const { return is_uniform() ? cable.length_m : line.length_m(); }

  /// Validates the cable (or the line) and the supports (not reachability: statics checks that).
  /// A general line cannot have prescribed forces. With a seabed: the seabed is valid, neither end
  /// is below it (within 1e-9 max(1, |z|)), and the forces are not prescribed.
  void validate() const;

 private:
  void validate_seabed() const;
};

}  // namespace catena
