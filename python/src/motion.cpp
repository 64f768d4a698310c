// SPDX-License-Identifier: MIT
// The inputs of the dynamic tension in waves (docs/explanation/dynamic-tension.md): the water
// (catena::Environment) and the motion of end b (catena::MotionRequest), built from keyword
// arguments and dicts spelt like the scene's [environment] and [request.motion] tables, so that a
// Python request reads as its TOML does. Bad input raises catena.InvalidInput (a ValueError)
// naming the field (`request.motion.rao.omega`, `environment.water_density`, ...).
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <set>

#include "bindings.hpp"
#include "catena/core/error.hpp"
#include "catena/models/cable.hpp"
#include "catena/solvers/solve_request.hpp"

namespace catena::python {
namespace {

Environment make_environment(double water_density_kg_per_m3, double gravity_m_per_s2) {
  Environment environment{water_density_kg_per_m3, gravity_m_per_s2};
  environment.validate();
  return environment;
}

void bind_environment(py::module_& module) {
  py::class_<Environment>(module, "Environment",
                          "The water the line hangs in (the scene's [environment]). Validated on "
                          "construction (catena.InvalidInput names the field).")
      .def(py::init(&make_environment), py::kw_only(), py::arg("water_density_kg_per_m3") = 1025.0,
           py::arg("gravity_m_per_s2") = 9.80665)
      .def_readonly("water_density_kg_per_m3", &Environment::water_density_kg_per_m3,
                    "water density rho of the Morison drag [kg/m^3]")
      .def_readonly("gravity_m_per_s2", &Environment::gravity_m_per_s2,
                    "gravitational acceleration g [m/s^2]")
      .def("__repr__", [](const Environment& e) {
        return fmt::format("Environment(water_density_kg_per_m3={}, gravity_m_per_s2={})",
                           e.water_density_kg_per_m3, e.gravity_m_per_s2);
      });
}

// A dict spelt like a TOML inline table: only `allowed` keys (an unknown key is most often a
// misspelt one), the `required` ones present. Messages name request.motion.<table>.<key>.
class Table {
 public:
  Table(const py::dict& dict,
        std::string name,
        const std::set<std::string>& allowed,
        const std::set<std::string>& required)
      : dict_(dict), name_(std::move(name)) {
    for (const auto& item : dict_) {
      const std::string key = py::str(item.first);
      if (!allowed.count(key)) {
        std::string accepted;
        for (const auto& a : allowed) accepted += (accepted.empty() ? "" : ", ") + a;
        throw InvalidInput(fmt::format("Invalid request.motion.{}.{}: unknown key (accepted: {})",
                                       name_, key, accepted));
      }
    }
    for (const auto& key : required) {
      if (!dict_.contains(key))
        throw InvalidInput(fmt::format("Invalid request.motion.{}: missing {}", name_, key));
    }
  }
  std::vector<double> values(const char* key) const {
    return cast<std::vector<double>>(key, "a sequence of numbers");
  }
  double number(const char* key, double otherwise) const {
    return dict_.contains(key) ? cast<double>(key, "a number") : otherwise;
  }
  bool flag(const char* key) const { return dict_.contains(key) && cast<bool>(key, "a bool"); }

 private:
  template <class T>
  T cast(const char* key, const char* what) const {
    try {
      return dict_[key].cast<T>();
    } catch (const py::cast_error&) {
      throw InvalidInput(fmt::format("Invalid request.motion.{}.{}: must be {}", name_, key, what));
    }
  }
  py::dict dict_;
  std::string name_;
};

void set_direction(MotionRequest& motion, const py::object& direction) {
  if (py::isinstance<py::str>(direction)) {
    const std::string text = direction.cast<std::string>();
    if (text != "out_of_plane") {
      throw InvalidInput(fmt::format(
          "Invalid request.motion.direction = \"{}\": must be (x, z) or \"out_of_plane\"", text));
    }
    motion.direction = ForcingDirection::OutOfPlane;
    return;
  }
  try {
    const auto vector = direction.cast<std::pair<double, double>>();
    motion.direction = ForcingDirection::GivenVector;
    motion.vector = Vec2(vector.first, vector.second);
  } catch (const py::cast_error&) {
    throw InvalidInput("Invalid request.motion.direction: must be (x, z) or \"out_of_plane\"");
  }
}

MotionRequest make_motion(const py::object& direction,
                          std::optional<double> amplitude_m,
                          std::optional<std::vector<double>> periods_s,
                          std::optional<py::dict> spectrum,
                          std::optional<py::dict> jonswap,
                          std::optional<py::dict> rao,
                          int frequencies,
                          double duration_s,
                          double tolerance,
                          int max_iterations) {
  MotionRequest motion;
  set_direction(motion, direction);
  motion.amplitude_m = amplitude_m.value_or(0.0);
  motion.periods_s = periods_s.value_or(std::vector<double>{});
  if (spectrum) {
    const Table t(*spectrum, "spectrum", {"omega", "density"}, {"omega", "density"});
    motion.spectrum = SpectrumTable{t.values("omega"), t.values("density")};
  }
  if (jonswap) {
    const Table t(*jonswap, "jonswap", {"hs", "tp", "gamma"}, {"hs", "tp"});
    motion.jonswap = JonswapSpectrum{t.number("hs", 0.0), t.number("tp", 0.0),
                                     t.number("gamma", JonswapSpectrum{}.gamma)};
  }
  if (rao) {
    const Table t(*rao, "rao", {"omega", "amplitude", "phase_deg", "per_wave_height"},
                  {"omega", "amplitude", "phase_deg"});
    motion.rao = RaoTable{t.values("omega"), t.values("amplitude"), t.values("phase_deg"),
                          t.flag("per_wave_height")};
  }
  motion.frequencies = frequencies;
  motion.duration_s = duration_s;
  motion.tolerance = tolerance;
  motion.max_iterations = max_iterations;
  motion.validate();
  return motion;
}

py::object spectrum_of(const MotionRequest& m) {
  if (!m.spectrum) return py::none();
  py::dict out;
  out["omega"] = owned_array(m.spectrum->omega_rad_s);
  out["density"] = owned_array(m.spectrum->density_m2_s_per_rad);
  return out;
}

py::object jonswap_of(const MotionRequest& m) {
  if (!m.jonswap) return py::none();
  py::dict out;
  out["hs"] = m.jonswap->hs_m;
  out["tp"] = m.jonswap->tp_s;
  out["gamma"] = m.jonswap->gamma;
  return out;
}

py::object rao_of(const MotionRequest& m) {
  if (!m.rao) return py::none();
  py::dict out;
  out["omega"] = owned_array(m.rao->omega_rad_s);
  out["amplitude"] = owned_array(m.rao->amplitude);
  out["phase_deg"] = owned_array(m.rao->phase_deg);
  out["per_wave_height"] = m.rao->per_wave_height;
  return out;
}

void bind_motion_request(py::module_& module) {
  using M = MotionRequest;
  py::class_<M>(module, "MotionRequest",
                "The motion of end b whose dynamic tension is asked, with Morison drag linearised "
                "about the response (the scene's [request.motion]). Regular: amplitude_m and "
                "periods_s. Irregular: spectrum={'omega': [...], 'density': [...]} (m^2 s/rad), or "
                "jonswap={'hs': ..., 'tp': ..., 'gamma': 3.3} with rao={'omega': [...], "
                "'amplitude': [...], 'phase_deg': [...], 'per_wave_height': False}. Validated on "
                "construction (catena.InvalidInput names the field).")
      .def(py::init(&make_motion), py::kw_only(),
           py::arg("direction") = std::pair<double, double>{1.0, 0.0},
           py::arg("amplitude_m") = py::none(), py::arg("periods_s") = py::none(),
           py::arg("spectrum") = py::none(), py::arg("jonswap") = py::none(),
           py::arg("rao") = py::none(), py::arg("frequencies") = 200,
           py::arg("duration_s") = 10800.0, py::arg("tolerance") = 1e-8,
           py::arg("max_iterations") = 200)
      .def_property_readonly(
          "direction",
          [](const M& m) -> py::object {
            if (m.direction == ForcingDirection::OutOfPlane) return py::str("out_of_plane");
            return py::make_tuple(m.vector.x(), m.vector.y());
          },
          "the in-plane direction (x, z), or 'out_of_plane'")
      .def_property_readonly("irregular", &M::is_irregular,
                             "True for a spectrum or a JONSWAP sea, False for regular motion")
      .def_property_readonly(
          "amplitude_m",
          [](const M& m) { return m.is_irregular() ? std::nullopt : std::optional(m.amplitude_m); },
          "regular motion: amplitude of end b [m]; None when irregular")
      .def_property_readonly(
          "periods_s", [](const M& m) { return owned_array(m.periods_s); },
          "regular motion: the periods [s], one fixed point each; empty when irregular")
      .def_property_readonly("spectrum", &spectrum_of,
                             "{'omega', 'density'} arrays [rad/s], [m^2 s/rad], or None")
      .def_property_readonly("jonswap", &jonswap_of, "{'hs', 'tp', 'gamma'} [m], [s], [-], or None")
      .def_property_readonly("rao", &rao_of,
                             "{'omega', 'amplitude', 'phase_deg', 'per_wave_height'} or None")
      .def_readonly("frequencies", &M::frequencies, "frequencies of the JONSWAP x |RAO|^2 grid")
      .def_readonly("duration_s", &M::duration_s,
                    "duration of the sea state for the most probable maximum [s]")
      .def_readonly("tolerance", &M::tolerance, "relative residual of the fixed point to reach")
      .def_readonly("max_iterations", &M::max_iterations, "most fixed-point iterations")
      .def("__repr__", [](const M& m) {
        if (!m.is_irregular()) {
          return fmt::format("MotionRequest(regular, amplitude_m={}, {} periods)", m.amplitude_m,
                             m.periods_s.size());
        }
        return std::string(m.spectrum ? "MotionRequest(irregular, motion spectrum)"
                                      : "MotionRequest(irregular, JONSWAP x RAO)");
      });
}

}  // namespace

void bind_motion(py::module_& module) {
  bind_environment(module);
  bind_motion_request(module);
}

}  // namespace catena::python
