// SPDX-License-Identifier: MIT
#pragma once
// The section damping of a Cable or a LineSegment (catena::SectionDamping, docs/explanation/
// physics.md "Damping") as three flat attributes named like the scene keys with their units, so
// that a Python cable reads as its [cable] table does.
#include <fmt/format.h>

#include <string>

#include "bindings.hpp"
#include "catena/models/cable.hpp"
#include "catena/models/line.hpp"

namespace catena::python {

/// Adds damping_tangential_n_s_per_m2, damping_normal_n_s_per_m2, axial_damping_n_s (read-write,
/// checked by validate() as the other fields are) and `damped` to a class with a `damping` member.
template <class Section>
void bind_section_damping(py::class_<Section>& section) {
  section
      .def_property(
          "damping_tangential_n_s_per_m2",
          [](const Section& s) { return s.damping.tangential_n_s_per_m2; },
          [](Section& s, double value) { s.damping.tangential_n_s_per_m2 = value; },
          "tangential drag c_t (Gale's f1) [N s/m per m], >= 0; 0: none")
      .def_property(
          "damping_normal_n_s_per_m2", [](const Section& s) { return s.damping.normal_n_s_per_m2; },
          [](Section& s, double value) { s.damping.normal_n_s_per_m2 = value; },
          "normal drag c_n (Gale's f2), in plane and out of plane [N s/m per m], >= 0; 0: none")
      .def_property(
          "axial_damping_n_s", [](const Section& s) { return s.damping.axial_n_s; },
          [](Section& s, double value) { s.damping.axial_n_s = value; },
          "Kelvin-Voigt axial damping c_a [N s], >= 0; must be 0 when EA = inf")
      .def_property_readonly(
          "damped", [](const Section& s) { return !s.damping.is_zero(); },
          "True when a damping coefficient is non-zero");
}

/// ", damping_tangential_n_s_per_m2=..., ..." for a damped section; empty when undamped, so that
/// an undamped repr is unchanged.
inline std::string damping_repr(const SectionDamping& d) {
  if (d.is_zero()) return "";
  return fmt::format(
      ", damping_tangential_n_s_per_m2={}, damping_normal_n_s_per_m2={}, axial_damping_n_s={}",
      d.tangential_n_s_per_m2, d.normal_n_s_per_m2, d.axial_n_s);
}

/// Grinfogel's taut inclined cable (make_taut_inclined_problem) with damping given in the form's
/// units: c_t = eta_tangential sqrt(T0 M) / L, c_n = eta_normal sqrt(T0 M) / L,
/// c_a = eta_axial L sqrt(T0 M), as the scene reader's [taut_inclined] (src/io/scene_reader.cpp).
Problem damped_taut_inclined_problem(
    double eps, double phi_deg, double lambda2, double mass_ratio, const SectionDamping& eta);
/// Gale's catenary (make_gale_xi_problem or make_gale_sag_problem, already built) with his
/// eqs. 2.28e,f: c_t = eta1 m sqrt(g/a), c_n = eta2 m sqrt(g/a), as the reader's [gale].
Problem with_gale_damping(Problem problem, double eta1, double eta2);

}  // namespace catena::python
