// SPDX-License-Identifier: MIT
// The general line (catena::Line, docs/explanation/physics.md "General lines"): segments from end A
// to end B and point attachments (clump weights, buoys). Every name carries its unit, as in C++.
#include "catena/models/line.hpp"

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "damping.hpp"
#include "hydrodynamics.hpp"

namespace catena::python {
namespace {

LineSegment make_segment(double length_m,
                         double weight_n_per_m,
                         double mass_kg_per_m,
                         double axial_stiffness_n,
                         double added_mass_kg_per_m,
                         double damping_tangential,
                         double damping_normal,
                         double axial_damping,
                         double diameter_m,
                         double drag_normal,
                         double drag_tangential,
                         double added_mass_tangential_kg_per_m) {
  LineSegment segment{
      length_m,      weight_n_per_m,      axial_stiffness_n,
      mass_kg_per_m, added_mass_kg_per_m, {damping_tangential, damping_normal, axial_damping}};
  segment.drag = {diameter_m, drag_normal, drag_tangential};
  segment.added_mass_tangential_kg_per_m = added_mass_tangential_kg_per_m;
  // A one-segment line validates the segment with the same messages as the scene reader.
  Line{{segment}, {}}.validate();
  return segment;
}

void bind_segment(py::module_& module) {
  py::class_<LineSegment> segment(module, "LineSegment",
                                  "One segment of a line, per unit unstretched length, in SI "
                                  "units. Validated on construction (catena.InvalidInput names "
                                  "the field).");
  segment
      .def(py::init(&make_segment), py::kw_only(), py::arg("length_m"), py::arg("weight_n_per_m"),
           py::arg("mass_kg_per_m"), py::arg("axial_stiffness_n") = kInfinity,
           py::arg("added_mass_kg_per_m") = 0.0, py::arg("damping_tangential_n_s_per_m2") = 0.0,
           py::arg("damping_normal_n_s_per_m2") = 0.0, py::arg("axial_damping_n_s") = 0.0,
           py::arg("diameter_m") = 0.0, py::arg("drag_normal") = 0.0,
           py::arg("drag_tangential") = 0.0, py::arg("added_mass_tangential_kg_per_m") = 0.0)
      .def_readwrite("length_m", &LineSegment::length_m, "unstretched length [m], > 0")
      .def_readwrite(
          "weight_n_per_m", &LineSegment::weight_n_per_m,
          "submerged weight per unit unstretched length [N/m]: > 0 hangs, 0 straight, < 0 buoyant")
      .def_readwrite("axial_stiffness_n", &LineSegment::axial_stiffness_n,
                     "EA [N], > 0; math.inf: inextensible")
      .def_readwrite("mass_kg_per_m", &LineSegment::mass_kg_per_m, "structural mass [kg/m], > 0")
      .def_readwrite("added_mass_kg_per_m", &LineSegment::added_mass_kg_per_m,
                     "added mass in the normal directions [kg/m], >= 0")
      .def_property_readonly("inextensible", &LineSegment::is_inextensible, "EA = inf");
  bind_section_damping(segment);
  bind_section_hydrodynamics(segment);
  segment.def("__repr__", [](const LineSegment& s) {
    return fmt::format(
        "LineSegment(length_m={}, weight_n_per_m={}, mass_kg_per_m={}, axial_stiffness_n={}, "
        "added_mass_kg_per_m={}{}{})",
        s.length_m, s.weight_n_per_m, s.mass_kg_per_m, s.axial_stiffness_n, s.added_mass_kg_per_m,
        damping_repr(s.damping), hydrodynamics_repr(s));
  });
}

PointAttachment make_point(double s_m,
                           double mass_kg,
                           double weight_n,
                           double added_mass_kg,
                           std::optional<double> tangential_kg,
                           std::optional<double> normal_kg,
                           std::optional<double> outofplane_kg) {
  return PointAttachment{s_m,           mass_kg,   weight_n,     added_mass_kg,
                         tangential_kg, normal_kg, outofplane_kg};
}

void bind_point(py::module_& module) {
  using P = PointAttachment;
  py::class_<P>(
      module, "PointAttachment",
      "A lumped mass with a submerged weight at unstretched arc length s_m from end A: a clump "
      "weight (weight_n > 0) or a buoy (weight_n < 0). Validated with its Line.")
      .def(py::init(&make_point), py::kw_only(), py::arg("s_m"), py::arg("mass_kg") = 0.0,
           py::arg("weight_n") = 0.0, py::arg("added_mass_kg") = 0.0,
           py::arg("added_mass_tangential_kg") = py::none(),
           py::arg("added_mass_normal_kg") = py::none(),
           py::arg("added_mass_outofplane_kg") = py::none())
      .def_readwrite("s_m", &P::s_m, "unstretched arc length from end A [m], in (0, L)")
      .def_readwrite("mass_kg", &P::mass_kg, "structural mass [kg], >= 0")
      .def_readwrite("weight_n", &P::weight_n, "submerged weight [N]: > 0 clump weight, < 0 buoy")
      .def_readwrite("added_mass_kg", &P::added_mass_kg,
                     "added mass in every direction not given [kg], >= 0")
      .def_property_readonly("tangential_added_mass_kg", &P::tangential_added_mass_kg, "[kg]")
      .def_property_readonly("normal_added_mass_kg", &P::normal_added_mass_kg, "[kg]")
      .def_property_readonly("outofplane_added_mass_kg", &P::outofplane_added_mass_kg, "[kg]")
      .def("__repr__", [](const P& p) {
        return fmt::format("PointAttachment(s_m={}, mass_kg={}, weight_n={}, added_mass_kg={})",
                           p.s_m, p.mass_kg, p.weight_n, p.added_mass_kg);
      });
}

Line make_line(std::vector<LineSegment> segments, std::vector<PointAttachment> points) {
  Line line{std::move(segments), std::move(points)};
  line.validate();
  return line;
}

void bind_line_class(py::module_& module) {
  py::class_<Line>(
      module, "Line",
      "A general line: segments in order from end A to end B and point attachments in order "
      "of s (docs/explanation/physics.md, \"General lines\"). Validated on construction.")
      .def(py::init(&make_line), py::arg("segments"), py::kw_only(),
           py::arg("points") = std::vector<PointAttachment>{})
      .def_readonly("segments", &Line::segments, "the segments from A to B (a copy)")
      .def_readonly("points", &Line::points, "the point attachments in order of s (a copy)")
      .def_property_readonly("length_m", &Line::length_m, "total unstretched length [m]")
      .def("segment_start_m", &Line::segment_start_m, py::arg("index"),
           "unstretched arc length of the start of segment `index` (len(segments): the total) [m]")
      .def_property_readonly("inextensible", &Line::is_inextensible, "no segment is extensible")
      .def_property_readonly("damped", &Line::is_damped, "some segment has non-zero damping")
      .def("validate", &Line::validate, "Raises catena.InvalidInput naming the bad field.")
      .def("__repr__", [](const Line& line) {
        return fmt::format("Line({} segments, {} points, L={} m)", line.segments.size(),
                           line.points.size(), line.length_m());
      });
}

}  // namespace

void bind_line(py::module_& module) {
  bind_segment(module);
  bind_point(module);
  bind_line_class(module);
}

}  // namespace catena::python
