// SPDX-License-Identifier: MIT
#pragma once
// The Morison drag and the tangential added mass of a Cable or a LineSegment (catena::MorisonDrag,
// docs/explanation/dynamic-tension.md) as flat attributes named like the scene keys with their
// units, as damping.hpp does for the section damping: diameter_m, drag_normal, drag_tangential,
// added_mass_tangential_kg_per_m. They enter only the dynamic tension of a motion request.
#include <fmt/format.h>

#include <string>

#include "bindings.hpp"
#include "catena/models/line.hpp"

namespace catena::python {

/// Adds diameter_m, drag_normal, drag_tangential, added_mass_tangential_kg_per_m (read-write,
/// checked by validate() as the other fields are), tangential_mass_kg_per_m and `has_drag` to a
/// class with `drag` and `added_mass_tangential_kg_per_m` members.
template <class Section>
void bind_section_hydrodynamics(py::class_<Section>& section) {
  section
      .def_property(
          "diameter_m", [](const Section& s) { return s.drag.diameter_m; },
          [](Section& s, double value) { s.drag.diameter_m = value; },
          "hydrodynamic (drag) diameter d [m], > 0 when a drag coefficient is given; 0: no drag")
      .def_property(
          "drag_normal", [](const Section& s) { return s.drag.normal; },
          [](Section& s, double value) { s.drag.normal = value; },
          "normal drag coefficient Cd [-] (MoorDyn's Cd), >= 0")
      .def_property(
          "drag_tangential", [](const Section& s) { return s.drag.tangential; },
          [](Section& s, double value) { s.drag.tangential = value; },
          "tangential drag coefficient CdAx [-] (MoorDyn's CdAx, on the wetted perimeter pi d), "
          ">= 0")
      .def_readwrite("added_mass_tangential_kg_per_m", &Section::added_mass_tangential_kg_per_m,
                     "added mass along the line ma_t [kg/m] (MoorDyn's CaAx), >= 0")
      .def_property_readonly("tangential_mass_kg_per_m", &Section::tangential_mass_kg_per_m,
                             "m + ma_t [kg/m]: the mass that resists tangential motion")
      .def_property_readonly(
          "has_drag", [](const Section& s) { return !s.drag.is_zero(); },
          "True when the section has Morison drag (a diameter and a coefficient > 0)");
}

/// ", diameter_m=..., drag_normal=..., ..." for a repr, empty without drag or tangential added
/// mass.
template <class Section>
std::string hydrodynamics_repr(const Section& s) {
  std::string out;
  if (!s.drag.is_zero()) {
    out += fmt::format(", diameter_m={}, drag_normal={}, drag_tangential={}", s.drag.diameter_m,
                       s.drag.normal, s.drag.tangential);
  }
  if (s.added_mass_tangential_kg_per_m != 0.0)
    out += fmt::format(", added_mass_tangential_kg_per_m={}", s.added_mass_tangential_kg_per_m);
  return out;
}

}  // namespace catena::python
