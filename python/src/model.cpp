// SPDX-License-Identifier: MIT
// The building blocks of a problem: Cable (catena::CableProperties), Problem (cable + supports)
// and the request (SolveRequest, ForcedRequest). Every name carries its unit, as in C++.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "catena/core/error.hpp"
#include "catena/models/cable.hpp"
#include "catena/models/line.hpp"
#include "catena/models/seabed.hpp"
#include "catena/solvers/solve_request.hpp"
#include "catena/statics/problem_builders.hpp"
#include "damping.hpp"
#include "hydrodynamics.hpp"

namespace catena::python {
namespace {

using Point = std::pair<double, double>;

Vec2 to_vec2(const Point& point) { return Vec2(point.first, point.second); }
Point to_point(const Vec2& vector) { return {vector.x(), vector.y()}; }

void bind_cable(py::module_& module) {
  py::class_<CableProperties> cable(module, "Cable",
                                    "A uniform cable, per unit unstretched length, in SI units. "
                                    "Validated on construction (catena.InvalidInput names the "
                                    "field).");
  cable
      .def(py::init([](double length_m, double weight_n_per_m, double mass_kg_per_m,
                       double axial_stiffness_n, double added_mass_kg_per_m,
                       double damping_tangential, double damping_normal, double axial_damping,
                       double diameter_m, double drag_normal, double drag_tangential,
                       double added_mass_tangential_kg_per_m) {
             CableProperties properties{length_m,      weight_n_per_m,      axial_stiffness_n,
                                        mass_kg_per_m, added_mass_kg_per_m, {}};
             properties.damping = {damping_tangential, damping_normal, axial_damping};
             properties.drag = {diameter_m, drag_normal, drag_tangential};
             properties.added_mass_tangential_kg_per_m = added_mass_tangential_kg_per_m;
             properties.validate();
             return properties;
           }),
           py::kw_only(), py::arg("length_m"), py::arg("weight_n_per_m"), py::arg("mass_kg_per_m"),
           py::arg("axial_stiffness_n") = kInfinity, py::arg("added_mass_kg_per_m") = 0.0,
           py::arg("damping_tangential_n_s_per_m2") = 0.0,
           py::arg("damping_normal_n_s_per_m2") = 0.0, py::arg("axial_damping_n_s") = 0.0,
           py::arg("diameter_m") = 0.0, py::arg("drag_normal") = 0.0,
           py::arg("drag_tangential") = 0.0, py::arg("added_mass_tangential_kg_per_m") = 0.0)
      .def_readwrite("length_m", &CableProperties::length_m, "unstretched length L [m], > 0")
      .def_readwrite("weight_n_per_m", &CableProperties::weight_n_per_m,
                     "submerged weight per unit unstretched length W0 [N/m], > 0")
      .def_readwrite("axial_stiffness_n", &CableProperties::axial_stiffness_n,
                     "axial stiffness EA [N], > 0; math.inf: inextensible")
      .def_readwrite("mass_kg_per_m", &CableProperties::mass_kg_per_m,
                     "structural mass m [kg/m], > 0")
      .def_readwrite("added_mass_kg_per_m", &CableProperties::added_mass_kg_per_m,
                     "added (hydrodynamic) mass ma [kg/m], >= 0, normal directions only")
      .def_property_readonly("normal_mass_kg_per_m", &CableProperties::normal_mass_kg_per_m,
                             "M = m + ma [kg/m]")
      .def_property_readonly("inextensible", &CableProperties::is_inextensible, "EA = inf");
  bind_section_damping(cable);
  bind_section_hydrodynamics(cable);
  cable
      .def("validate", &CableProperties::validate,
           "Raises catena.InvalidInput naming the bad field.")
      .def("__repr__", [](const CableProperties& c) {
        return fmt::format(
            "Cable(length_m={}, weight_n_per_m={}, mass_kg_per_m={}, axial_stiffness_n={}, "
            "added_mass_kg_per_m={}{}{})",
            c.length_m, c.weight_n_per_m, c.mass_kg_per_m, c.axial_stiffness_n,
            c.added_mass_kg_per_m, damping_repr(c.damping), hydrodynamics_repr(c));
      });
}

// The supports and seabed of a problem, then the whole problem validated.
Problem with_supports(Problem problem,
                      const Point& b_m,
                      const Point& a_m,
                      const std::optional<Seabed>& seabed,
                      const std::optional<Environment>& environment) {
  problem.supports.a_m = to_vec2(a_m);
  problem.supports.b_m = to_vec2(b_m);
  problem.seabed = seabed;
  if (environment) problem.environment = *environment;
  problem.validate();
  return problem;
}

Problem make_problem(const CableProperties& cable,
                     const Point& b_m,
                     const Point& a_m,
                     const std::optional<Seabed>& seabed,
                     const std::optional<Environment>& environment) {
  Problem problem;
  problem.cable = cable;
  return with_supports(problem, b_m, a_m, seabed, environment);
}

Problem make_line_problem(const Line& line,
                          const Point& b_m,
                          const Point& a_m,
                          const std::optional<Seabed>& seabed,
                          const std::optional<Environment>& environment) {
  Problem problem;
  problem.line = line;
  return with_supports(problem, b_m, a_m, seabed, environment);
}

Seabed make_seabed(
    double z_m, double friction, double stiffness, double tangential_stiffness, double damping) {
  Seabed seabed{z_m, friction, stiffness, tangential_stiffness, damping};
  seabed.validate();
  return seabed;
}

void bind_seabed(py::module_& module) {
  py::class_<Seabed>(module, "Seabed",
                     "A flat seabed at height z_m under end A (docs/explanation/physics.md, "
                     "\"Seabed contact\"). Validated "
                     "on construction (catena.InvalidInput names the field).")
      .def(py::init(&make_seabed), py::arg("z_m"), py::kw_only(), py::arg("friction") = 0.0,
           py::arg("stiffness_n_per_m2") = 0.0, py::arg("tangential_stiffness_n_per_m2") = 0.0,
           py::arg("damping_n_s_per_m2") = 0.0)
      .def_readonly("z_m", &Seabed::z_m, "seabed height [m]")
      .def_readonly("friction", &Seabed::friction, "Coulomb coefficient C_B of the statics [-]")
      .def_readonly("stiffness_n_per_m2", &Seabed::stiffness_n_per_m2,
                    "vertical foundation stiffness per unit length k_s [N/m per m]")
      .def_readonly("tangential_stiffness_n_per_m2", &Seabed::tangential_stiffness_n_per_m2,
                    "foundation stiffness along and across the seabed [N/m per m]")
      .def_readonly("damping_n_s_per_m2", &Seabed::damping_n_s_per_m2,
                    "dashpot c_s under the grounded part, in parallel with k_s [N s/m per m]")
      .def("__repr__", [](const Seabed& b) {
        return fmt::format(
            "Seabed(z_m={}, friction={}, stiffness_n_per_m2={}, "
            "tangential_stiffness_n_per_m2={}{})",
            b.z_m, b.friction, b.stiffness_n_per_m2, b.tangential_stiffness_n_per_m2,
            b.damping_n_s_per_m2 > 0.0
                ? fmt::format(", damping_n_s_per_m2={}", b.damping_n_s_per_m2)
                : std::string());
      });
}

void bind_problem(py::module_& module) {
  py::class_<Problem>(
      module, "Problem",
      "A cable between two fixed supports a and b in one vertical plane (x horizontal, "
      "z up) [m]: the input of solve_statics and of every solver.")
      .def(py::init(&make_problem), py::arg("cable"), py::kw_only(), py::arg("b_m"),
           py::arg("a_m") = Point{0.0, 0.0}, py::arg("seabed") = py::none(),
           py::arg("environment") = py::none())
      .def_static("from_line", &make_line_problem, py::arg("line"), py::kw_only(), py::arg("b_m"),
                  py::arg("a_m") = Point{0.0, 0.0}, py::arg("seabed") = py::none(),
                  py::arg("environment") = py::none(),
                  "A general line (catena.Line) between supports a and b [m] "
                  "(docs/explanation/physics.md, \"General lines\").")
      .def_readwrite("cable", &Problem::cable,
                     "the uniform cable (unused when the problem is a general line)")
      .def_property_readonly(
          "line",
          [](const Problem& p) -> std::optional<Line> {
            if (p.is_uniform()) return std::nullopt;
            return p.line;
          },
          "the general line (a copy), or None for a uniform cable")
      .def_readonly("seabed", &Problem::seabed, "the seabed (catena.Seabed), or None")
      .def_property(
          "environment", [](const Problem& p) { return p.environment; },
          [](Problem& p, const Environment& e) {
            e.validate();
            p.environment = e;
          },
          "the water (catena.Environment: density of the Morison drag, gravity); a copy")
      .def_property_readonly("has_drag", &Problem::has_drag,
                             "True when some section has Morison drag")
      .def_property_readonly("is_uniform", &Problem::is_uniform,
                             "True for a uniform cable, False for a general line")
      .def_property_readonly("length_m", &Problem::length_m, "total unstretched length [m]")
      .def_property(
          "a_m", [](const Problem& p) { return to_point(p.supports.a_m); },
          [](Problem& p, const Point& a) { p.supports.a_m = to_vec2(a); }, "support a (x, z) [m]")
      .def_property(
          "b_m", [](const Problem& p) { return to_point(p.supports.b_m); },
          [](Problem& p, const Point& b) { p.supports.b_m = to_vec2(b); }, "support b (x, z) [m]")
      .def_property_readonly(
          "form", [](const Problem& p) { return to_string(p.form); },
          "how it was specified: 'cable', 'taut_inclined', 'gale_xi', 'gale_sag'")
      .def_property_readonly(
          "prescribed_forces_n",
          [](const Problem& p) -> std::optional<Point> {
            if (!p.prescribed_forces) return std::nullopt;
            return Point{p.prescribed_forces->horizontal_n, p.prescribed_forces->vertical_a_n};
          },
          "(H, V_A) [N] when the static state is given by its end forces (builders of taut "
          "cables), else None")
      .def_static(
          "taut_inclined",
          [](double eps, double phi_deg, double lambda2, double mass_ratio, double eta_tangential,
             double eta_normal, double eta_axial) {
            return damped_taut_inclined_problem(eps, phi_deg, lambda2, mass_ratio,
                                                {eta_tangential, eta_normal, eta_axial});
          },
          py::arg("eps"), py::arg("phi_deg"), py::arg("lambda2"), py::arg("mass_ratio") = 1.0,
          py::kw_only(), py::arg("eta_tangential") = 0.0, py::arg("eta_normal") = 0.0,
          py::arg("eta_axial") = 0.0,
          "Grinfogel's taut inclined cable from its dimensionless groups "
          "(docs/explanation/physics.md); damping in the form's units (L = 1 m, T0 = 1 N, "
          "M = 1 kg/m): c_t = eta_tangential, c_n = eta_normal, c_a = eta_axial "
          "(docs/reference/scene-format.md, \"Damping\").")
      .def_static(
          "gale_xi",
          [](double xi1, double xi2, double eta1, double eta2) {
            return with_gale_damping(make_gale_xi_problem(xi1, xi2), eta1, eta2);
          },
          py::arg("xi1"), py::arg("xi2"), py::kw_only(), py::arg("eta1") = 0.0,
          py::arg("eta2") = 0.0,
          "Gale's inextensible catenary between apex coordinates xi1 < xi2 "
          "(docs/explanation/physics.md); eta1, eta2: his tangential and normal drag, "
          "eqs. 2.28e,f.")
      .def_static(
          "gale_sag",
          [](double h_over_b, double sag_param, double eta1, double eta2) {
            return with_gale_damping(make_gale_sag_problem(h_over_b, sag_param), eta1, eta2);
          },
          py::arg("h_over_b"), py::arg("sag_param"), py::kw_only(), py::arg("eta1") = 0.0,
          py::arg("eta2") = 0.0,
          "Gale's inextensible catenary from height/span and sag parameter "
          "(docs/explanation/physics.md); eta1, eta2 as gale_xi.")
      .def_property_readonly("damped", &Problem::is_damped,
                             "True when the line or the seabed has a non-zero damping "
                             "coefficient (complex roots lambda = -delta + i omega_d)")
      .def("validate", &Problem::validate, "Raises catena.InvalidInput naming the bad field.")
      .def("__repr__", [](const Problem& p) {
        return fmt::format(
            "Problem(form='{}'{}, L={} m, a=({}, {}) m, b=({}, {}) m)", to_string(p.form),
            p.is_uniform() ? "" : fmt::format(", line of {} segments", p.line.segments.size()),
            p.length_m(), p.supports.a_m.x(), p.supports.a_m.y(), p.supports.b_m.x(),
            p.supports.b_m.y());
      });
}

ForcingDirection parse_direction(const std::string& text) {
  if (text == "tangential") return ForcingDirection::Tangential;
  if (text == "normal") return ForcingDirection::Normal;
  if (text == "out_of_plane") return ForcingDirection::OutOfPlane;
  throw InvalidInput(
      fmt::format("ForcedRequest.direction = \"{}\": must be \"tangential\", \"normal\", "
                  "\"out_of_plane\" or (x, z)",
                  text));
}

ForcedRequest make_forced(const std::vector<double>& omegas_rad_s,
                          const std::string& end,
                          const py::object& direction,
                          double amplitude_m) {
  ForcedRequest forced;
  forced.omegas_rad_s = omegas_rad_s;
  if (end != "a" && end != "b") {
    throw InvalidInput(fmt::format("ForcedRequest.end = \"{}\": must be \"a\" or \"b\"", end));
  }
  forced.end = end == "a" ? CableEnd::A : CableEnd::B;
  if (py::isinstance<py::str>(direction)) {
    forced.direction = parse_direction(direction.cast<std::string>());
  } else {
    forced.direction = ForcingDirection::GivenVector;
    forced.vector = to_vec2(direction.cast<Point>());
  }
  forced.amplitude_m = amplitude_m;
  return forced;
}

void bind_forced_request(py::module_& module) {
  py::class_<ForcedRequest>(
      module, "ForcedRequest",
      "Harmonic forced response: one end displaced by amplitude_m * direction * "
      "cos(omega t), the other fixed; one solve per forcing frequency [rad/s].")
      .def(py::init(&make_forced), py::arg("omegas_rad_s"), py::kw_only(), py::arg("end") = "b",
           py::arg("direction") = "tangential", py::arg("amplitude_m") = 0.01)
      .def_property_readonly(
          "omegas_rad_s", [](const ForcedRequest& f) { return owned_array(f.omegas_rad_s); },
          "forcing frequencies [rad/s]")
      .def_property_readonly(
          "end", [](const ForcedRequest& f) { return to_string(f.end); }, "'a' or 'b'")
      .def_property_readonly("direction",
                             [](const ForcedRequest& f) { return to_string(f.direction); })
      .def_property_readonly(
          "vector", [](const ForcedRequest& f) { return to_point(f.vector); },
          "the in-plane direction (x, z) when direction is a given vector")
      .def_readonly("amplitude_m", &ForcedRequest::amplitude_m,
                    "displacement amplitude at the driven end [m]");
}

SolveRequest make_request(int inplane_modes,
                          int outofplane_modes,
                          bool shapes,
                          int points,
                          bool tension,
                          std::optional<ForcedRequest> forced,
                          std::optional<MotionRequest> motion) {
  SolveRequest request;
  request.motion = std::move(motion);
  request.inplane_modes = inplane_modes;
  request.outofplane_modes = outofplane_modes;
  request.shapes = shapes;
  request.points = points;
  request.tension = tension;
  request.forced = std::move(forced);
  request.validate();
  return request;
}

void bind_request(py::module_& module) {
  py::class_<SolveRequest>(module, "Request",
                           "What to compute (docs/reference/scene-format.md, [request]).")
      .def(py::init(&make_request), py::kw_only(), py::arg("inplane_modes") = 6,
           py::arg("outofplane_modes") = 0, py::arg("shapes") = false, py::arg("points") = 101,
           py::arg("tension") = false, py::arg("forced") = py::none(),
           py::arg("motion") = py::none())
      .def_readwrite("inplane_modes", &SolveRequest::inplane_modes,
                     "lowest in-plane modes to compute")
      .def_readwrite("outofplane_modes", &SolveRequest::outofplane_modes,
                     "lowest out-of-plane modes")
      .def_readwrite("shapes", &SolveRequest::shapes,
                     "mode shapes on `points` equally spaced stations")
      .def_readwrite("points", &SolveRequest::points,
                     "stations for shapes, tension and forced response")
      .def_readwrite("tension", &SolveRequest::tension, "dynamic tension of each mode")
      .def_readwrite("forced", &SolveRequest::forced, "a ForcedRequest or None")
      .def_readwrite("motion", &SolveRequest::motion,
                     "a MotionRequest (dynamic tension under a motion of end b) or None")
      .def(
          "stations_m",
          [](const SolveRequest& r, double length_m) {
            return owned_array(r.stations_m(length_m));
          },
          py::arg("length_m"), "the stations s_j [m] for a cable of unstretched length length_m")
      .def("validate", &SolveRequest::validate, "Raises catena.InvalidInput naming the bad field.")
      .def("__repr__", [](const SolveRequest& r) {
        return fmt::format(
            "Request(inplane_modes={}, outofplane_modes={}, shapes={}, points={}, tension={}, "
            "forced={}, motion={})",
            r.inplane_modes, r.outofplane_modes, r.shapes ? "True" : "False", r.points,
            r.tension ? "True" : "False", r.forced ? "ForcedRequest(...)" : "None",
            r.motion ? "MotionRequest(...)" : "None");
      });
}

}  // namespace

void bind_model(py::module_& module) {
  bind_cable(module);
  bind_seabed(module);
  bind_problem(module);
  bind_forced_request(module);
  bind_request(module);
}

}  // namespace catena::python
