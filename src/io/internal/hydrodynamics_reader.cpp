// SPDX-License-Identifier: MIT
#include "io/internal/hydrodynamics_reader.hpp"

#include <fmt/format.h>

#include "catena/core/error.hpp"

namespace catena::internal {
namespace {

bool positive(double x) { return x > 0.0; }
bool non_negative(double x) { return x >= 0.0; }
bool any_value(double) { return true; }

// `direction`: an in-plane vector [x, z] (normalised by the solvers) or "out_of_plane"; default
// [1, 0], a horizontal (surge-like) motion of the fairlead in the line's plane.
void read_direction(TableReader& table, MotionRequest& motion) {
  const toml::value* direction = table.find("direction");
  if (!direction) return;
  if (direction->is_array()) {
    motion.direction = ForcingDirection::GivenVector;
    motion.vector = table.point("direction");
    if (motion.vector.norm() == 0.0) {
      throw InvalidInput(
          fmt::format("{}: the direction vector must be non-zero", table.where("direction")));
    }
    return;
  }
  const std::string text = table.string("direction");
  if (text != "out_of_plane") {
    throw InvalidInput(
        fmt::format("{} = \"{}\": must be [x, z] (in the line's plane) or "
                    "\"out_of_plane\"",
                    table.where("direction"), text));
  }
  motion.direction = ForcingDirection::OutOfPlane;
}

SpectrumTable read_spectrum(TableReader& table) {
  SpectrumTable spectrum;
  spectrum.omega_rad_s = table.numbers("omega");
  spectrum.density_m2_s_per_rad = table.numbers("density");
  table.finish();
  return spectrum;
}

JonswapSpectrum read_jonswap(TableReader& table) {
  JonswapSpectrum jonswap;
  jonswap.hs_m = table.checked("hs", positive, "finite and > 0", "m");
  jonswap.tp_s = table.checked("tp", positive, "finite and > 0", "s");
  jonswap.gamma = table.checked("gamma", any_value, "finite", "-", jonswap.gamma);
  table.finish();
  return jonswap;
}

// An RAO is conventionally given per unit wave AMPLITUDE (the default, `per = "wave_amplitude"`);
// issue 30 words it "per metre of wave height", which `per = "wave_height"` selects (the motion
// spectrum is then 4 times |RAO|^2 S_eta, as H = 2 a).
RaoTable read_rao(TableReader& table) {
  RaoTable rao;
  rao.omega_rad_s = table.numbers("omega");
  rao.amplitude = table.numbers("amplitude");
  if (table.has("phase_deg")) rao.phase_deg = table.numbers("phase_deg");
  const std::string per = table.string("per", "wave_amplitude");
  if (per != "wave_amplitude" && per != "wave_height") {
    throw InvalidInput(
        fmt::format("{} = \"{}\": must be \"wave_amplitude\" (the default) or "
                    "\"wave_height\"",
                    table.where("per"), per));
  }
  rao.per_wave_height = per == "wave_height";
  table.finish();
  return rao;
}

}  // namespace

MorisonDrag read_drag(TableReader& section) {
  MorisonDrag drag;
  // A diameter written in the scene must be a real one: 0 means "no drag" only by default.
  if (section.has("diameter"))
    drag.diameter_m = section.checked("diameter", positive, "finite and > 0", "m");
  drag.normal = section.checked("drag_normal", non_negative, "finite and >= 0", "-", 0.0);
  drag.tangential = section.checked("drag_tangential", non_negative, "finite and >= 0", "-", 0.0);
  return drag;
}

double read_added_mass_tangential(TableReader& section) {
  return section.checked("added_mass_tangential", non_negative, "finite and >= 0", "kg/m", 0.0);
}

Environment read_environment(TableReader& table) {
  Environment environment;
  environment.water_density_kg_per_m3 = table.checked(
      "water_density", positive, "finite and > 0", "kg/m^3", environment.water_density_kg_per_m3);
  environment.gravity_m_per_s2 =
      table.checked("gravity", positive, "finite and > 0", "m/s^2", environment.gravity_m_per_s2);
  table.finish();
  return environment;
}

MotionRequest read_motion(TableReader& table) {
  MotionRequest motion;
  read_direction(table, motion);
  if (table.has("amplitude"))
    motion.amplitude_m = table.checked("amplitude", positive, "finite and > 0", "m");
  if (table.has("periods")) {
    motion.periods_s = table.numbers("periods");
    for (std::size_t i = 0; i < motion.periods_s.size(); ++i) {
      if (!(motion.periods_s[i] > 0.0)) {
        throw InvalidInput(fmt::format("{}: period {} = {} must be > 0 [s]", table.where("periods"),
                                       i, motion.periods_s[i]));
      }
    }
  }
  if (table.has("spectrum")) {
    TableReader spectrum = table.subtable("spectrum");
    motion.spectrum = read_spectrum(spectrum);
  }
  if (table.has("jonswap")) {
    TableReader jonswap = table.subtable("jonswap");
    motion.jonswap = read_jonswap(jonswap);
  }
  if (table.has("rao")) {
    TableReader rao = table.subtable("rao");
    motion.rao = read_rao(rao);
  }
  motion.frequencies =
      static_cast<int>(table.read_integer("frequencies", 8, 100000, motion.frequencies));
  motion.duration_s = table.checked("duration", positive, "finite and > 0", "s", motion.duration_s);
  motion.tolerance = table.checked("tolerance", positive, "finite and > 0", "-", motion.tolerance);
  motion.max_iterations =
      static_cast<int>(table.read_integer("max_iterations", 1, 10000, motion.max_iterations));
  table.finish();
  return motion;
}

}  // namespace catena::internal
