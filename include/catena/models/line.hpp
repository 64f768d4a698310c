// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// A general line (docs/explanation/physics.md, "General lines"): an ordered list of segments from
/// end A to end B, each with its own section, plus point attachments (clump weights, buoys, anchor
/// heads) at given unstretched arc lengths from A.

#include <optional>
#include <string>
#include <vector>

#include "catena/core/types.hpp"

namespace catena {

struct CableProperties;

/// Linear damping of a cable section, per unit *unstretched* length (docs/explanation/physics.md,
/// "Damping"). All zero by default: then the line is undamped and every result is the undamped
/// one, bit for bit.
struct SectionDamping {
  /// Tangential drag c_t (Gale's f1) [N s/m per m]: force -c_t (velocity . t) per unit length.
  /// Finite and >= 0.
  double tangential_n_s_per_m2 = 0.0;
  /// Normal drag c_n (Gale's f2) [N s/m per m], in both normal directions (in plane and out of
  /// plane). Finite and >= 0.
  double normal_n_s_per_m2 = 0.0;
  /// Kelvin-Voigt axial damping c_a [N s]: the dynamic tension is tau = EA eps + c_a d(eps)/dt
  /// (MoorDyn's BA). Finite and >= 0; must be 0 for an inextensible section (no axial strain).
  double axial_n_s = 0.0;
  /// True when every coefficient is 0.
  bool is_zero() const {
    return tangential_n_s_per_m2 == 0.0 && normal_n_s_per_m2 == 0.0 && axial_n_s == 0.0;
  }
};
/// Morison drag of a cable section (docs/explanation/dynamic-tension.md, "Drag"): the quadratic
/// force per unit unstretched length -1/2 rho Cd d |v_n| v_n across the line and
/// -1/2 rho CdAx (pi d) |v_t| v_t along it (MoorDyn's convention: the tangential force acts on
/// the wetted perimeter pi d; MoorPy's dynamicSolve uses d, so give CdAx / pi), linearised about
/// the response to a motion request. It enters only the dynamic tension in waves, never the natural
/// modes. Zero by default: no drag.
struct MorisonDrag {
  /// Hydrodynamic diameter d [m]; 0 when no drag is given. Finite and > 0 when given.
  double diameter_m = 0.0;
  /// Normal drag coefficient Cd [-] (MoorDyn's Cd). Finite and >= 0.
  double normal = 0.0;
  /// Tangential drag coefficient CdAx [-] (MoorDyn's CdAx). Finite and >= 0.
  double tangential = 0.0;
  /// True when the section has no drag.
  bool is_zero() const { return diameter_m == 0.0 || (normal == 0.0 && tangential == 0.0); }
};

/// One segment of a line, per unit *unstretched* length.
struct LineSegment {
  /// Unstretched length [m]. Finite and > 0.
  double length_m = 1.0;
  /// Submerged weight per unit unstretched length [N/m]: > 0 hangs (sagging catenary), 0 is a
  /// straight bar, < 0 is buoyant (hogging catenary). Finite.
  double weight_n_per_m = 1.0;
  /// Axial stiffness EA [N]; +infinity means inextensible.
  double axial_stiffness_n = kInfinity;
  /// Structural mass per unit unstretched length [kg/m]. Finite and > 0.
  double mass_kg_per_m = 1.0;
  /// Added mass per unit unstretched length in the normal directions [kg/m]. Finite and >= 0.
  double added_mass_kg_per_m = 0.0;
  /// Linear drag and axial damping of the segment (zero: undamped).
  SectionDamping damping{};
  /// Added mass per unit unstretched length along the line [kg/m] (MoorDyn's CaAx). Finite, >= 0.
  double added_mass_tangential_kg_per_m = 0.0;
  /// Morison drag (zero: none).
  MorisonDrag drag{};

  double normal_mass_kg_per_m() const { return mass_kg_per_m + added_mass_kg_per_m; }
  /// m + ma_t: the mass that resists tangential motion [kg/m].
  double tangential_mass_kg_per_m() const { return mass_kg_per_m + added_mass_tangential_kg_per_m; }
  bool is_inextensible() const;
};

/// A point attachment at unstretched arc length s from A: a lumped mass with a submerged weight.
struct PointAttachment {
  /// Unstretched arc length from end A [m], strictly inside the line (0 < s < L).
  double s_m = 0.0;
  /// Structural mass [kg]. Finite and >= 0.
  double mass_kg = 0.0;
  /// Submerged weight [N]: > 0 a clump weight, < 0 a buoy. Finite.
  double weight_n = 0.0;
  /// Added mass [kg], the same in every direction unless the per-direction values are given.
  /// Finite and >= 0.
  double added_mass_kg = 0.0;
  /// Optional added mass along the local static tangent, in-plane normal and out of plane [kg];
  /// each defaults to added_mass_kg.
  std::optional<double> added_mass_tangential_kg;
  std::optional<double> added_mass_normal_kg;
  std::optional<double> added_mass_outofplane_kg;

  double tangential_added_mass_kg() const {
    return added_mass_tangential_kg.value_or(added_mass_kg);
  }
  double normal_added_mass_kg() const { return added_mass_normal_kg.value_or(added_mass_kg); }
  double outofplane_added_mass_kg() const {
    return added_mass_outofplane_kg.value_or(added_mass_kg);
  }
};

/// Segments in order from A to B and point attachments in order of s.
struct Line {
  std::vector<LineSegment> segments;
  std::vector<PointAttachment> points;

  /// Total unstretched length [m].
  double length_m() const;
  /// Unstretched arc length of the start of segment `index` (index == size: the total length) [m].
  double segment_start_m(std::size_t index) const;
  /// True when no segment is extensible.
  bool is_inextensible() const;
  /// True when some segment has a non-zero damping coefficient.
  bool is_damped() const;
  /// True when some segment has Morison drag.
  bool has_drag() const;
  /// True when some segment has a tangential added mass.
  bool has_tangential_added_mass() const;

  /// Throws InvalidInput naming the field (`line.segments[2].length`, `line.points[0].s`), its
  /// value and the constraint: non-finite or out-of-range values, points outside (0, L), points
  /// not in increasing order of s or closer than 1e-9 L to each other.
  void validate() const;
};

/// Throws InvalidInput naming `<prefix>diameter`, `<prefix>drag_normal` or
/// `<prefix>drag_tangential` (prefix e.g. "cable." or "line.segments[1].") unless the diameter is
/// 0 (no drag) or finite and > 0, the coefficients are finite and >= 0, and a non-zero coefficient
/// has a diameter.
void validate_drag(const MorisonDrag& drag, const std::string& prefix);

/// The line of one uniform cable (one segment, no points).
Line line_of_cable(const CableProperties& cable);

}  // namespace catena
