// SPDX-License-Identifier: MIT
// Validation of a motion request: see catena/solvers/solve_request.hpp.
#include <fmt/format.h>

#include <cmath>

#include "catena/core/error.hpp"
#include "catena/solvers/solve_request.hpp"

namespace catena {
namespace {

void require(bool ok, const std::string& field, double value, const char* rule) {
  if (!ok)
    throw InvalidInput(fmt::format("Invalid request.motion.{} = {}: {}", field, value, rule));
}

// A table column: finite values; `increasing`: strictly increasing and >= 0; else >= 0 unless
// `any_sign`.
void require_column(const std::vector<double>& values,
                    const std::string& field,
                    bool increasing,
                    bool any_sign,
                    const char* unit) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::string name = fmt::format("{}[{}]", field, i);
    const double v = values[i];
    if (!std::isfinite(v)) {
      throw InvalidInput(
          fmt::format("Invalid request.motion.{} = {}: must be finite [{}]", name, v, unit));
    }
    if (!any_sign && v < 0.0) {
      throw InvalidInput(
          fmt::format("Invalid request.motion.{} = {}: must be >= 0 [{}]", name, v, unit));
    }
    if (increasing && i > 0 && !(v > values[i - 1])) {
      throw InvalidInput(fmt::format(
          "Invalid request.motion.{} = {}: the frequencies must be strictly increasing (the "
          "previous one is {}) [{}]",
          name, v, values[i - 1], unit));
    }
  }
}

void require_table_size(std::size_t size, std::size_t expected, const std::string& field) {
  if (size != expected) {
    throw InvalidInput(
        fmt::format("Invalid request.motion.{}: {} values, but the frequency column has {}", field,
                    size, expected));
  }
}

void validate_spectrum(const SpectrumTable& table) {
  if (table.omega_rad_s.size() < 2 || table.omega_rad_s.size() > 100000) {
    throw InvalidInput(fmt::format(
        "Invalid request.motion.spectrum.omega: {} frequencies; need between 2 and 100000",
        table.omega_rad_s.size()));
  }
  require_column(table.omega_rad_s, "spectrum.omega", true, false, "rad/s");
  require_table_size(table.density_m2_s_per_rad.size(), table.omega_rad_s.size(),
                     "spectrum.density");
  require_column(table.density_m2_s_per_rad, "spectrum.density", false, false, "m^2 s/rad");
}

void validate_rao(const RaoTable& rao) {
  if (rao.omega_rad_s.size() < 2 || rao.omega_rad_s.size() > 100000) {
    throw InvalidInput(
        fmt::format("Invalid request.motion.rao.omega: {} frequencies; need between 2 and 100000",
                    rao.omega_rad_s.size()));
  }
  require_column(rao.omega_rad_s, "rao.omega", true, false, "rad/s");
  require_table_size(rao.amplitude.size(), rao.omega_rad_s.size(), "rao.amplitude");
  require_column(rao.amplitude, "rao.amplitude", false, false, "m/m");
  if (!rao.phase_deg.empty()) {
    require_table_size(rao.phase_deg.size(), rao.omega_rad_s.size(), "rao.phase_deg");
    require_column(rao.phase_deg, "rao.phase_deg", false, true, "deg");
  }
}

void validate_irregular(const MotionRequest& m) {
  if (m.spectrum && m.jonswap) {
    throw InvalidInput(
        "Invalid request.motion: give either spectrum or jonswap (with rao), not both");
  }
  if (m.spectrum) validate_spectrum(*m.spectrum);
  if (m.jonswap) {
    const JonswapSpectrum& j = *m.jonswap;
    require(std::isfinite(j.hs_m) && j.hs_m > 0.0 && j.hs_m <= 100.0, "jonswap.hs", j.hs_m,
            "must be finite and in (0, 100] [m]");
    require(std::isfinite(j.tp_s) && j.tp_s > 0.0 && j.tp_s <= 1000.0, "jonswap.tp", j.tp_s,
            "must be finite and in (0, 1000] [s]");
    require(std::isfinite(j.gamma) && j.gamma >= 1.0 && j.gamma <= 7.0, "jonswap.gamma", j.gamma,
            "must be in [1, 7] (DNV-RP-C205's range) [-]");
    if (!m.rao) {
      throw InvalidInput(
          "Invalid request.motion.jonswap: a wave spectrum needs the fairlead's motion RAO; give "
          "request.motion.rao = { omega = [...], amplitude = [...], phase_deg = [...] }");
    }
    validate_rao(*m.rao);
  } else if (m.rao) {
    throw InvalidInput(
        "Invalid request.motion.rao: an RAO needs a wave spectrum; give request.motion.jonswap");
  }
  require(m.frequencies >= 8 && m.frequencies <= 100000, "frequencies", m.frequencies,
          "must be in [8, 100000]");
  require(std::isfinite(m.duration_s) && m.duration_s > 0.0 && m.duration_s <= 1e9, "duration",
          m.duration_s, "must be finite and in (0, 1e9] [s]");
  if (m.amplitude_m != 0.0 || !m.periods_s.empty()) {
    throw InvalidInput(
        "Invalid request.motion: amplitude and periods are for regular motion; an irregular "
        "motion (spectrum or jonswap) takes neither");
  }
}

void validate_regular(const MotionRequest& m) {
  require(std::isfinite(m.amplitude_m) && m.amplitude_m > 0.0 && m.amplitude_m <= 1e4, "amplitude",
          m.amplitude_m, "must be finite and in (0, 1e4] [m]");
  if (m.periods_s.empty() || m.periods_s.size() > 10000) {
    throw InvalidInput(fmt::format(
        "Invalid request.motion.periods: {} periods; give between 1 and 10000 (regular motion), "
        "or a spectrum or jonswap (irregular)",
        m.periods_s.size()));
  }
  for (std::size_t i = 0; i < m.periods_s.size(); ++i) {
    const double T = m.periods_s[i];
    require(std::isfinite(T) && T > 0.0 && T <= 1e6, fmt::format("periods[{}]", i), T,
            "must be finite and in (0, 1e6] [s]");
  }
}

}  // namespace

Vec2 MotionRequest::unit_vector() const {
  ForcedRequest forced;
  forced.vector = vector;
  return forced.unit_vector();
}

void MotionRequest::validate() const {
  if (direction != ForcingDirection::GivenVector && direction != ForcingDirection::OutOfPlane) {
    throw InvalidInput(
        "Invalid request.motion.direction: must be an in-plane vector [x, z] or \"out_of_plane\"");
  }
  if (direction == ForcingDirection::GivenVector &&
      (!vector.allFinite() || unit_vector().isZero(0.0))) {
    throw InvalidInput("Invalid request.motion.direction: the vector must be finite and non-zero");
  }
  if (is_irregular()) {
    validate_irregular(*this);
  } else {
    if (rao) validate_irregular(*this);  // an RAO without a spectrum: says so
    validate_regular(*this);
  }
  require(std::isfinite(tolerance) && tolerance >= 1e-14 && tolerance <= 0.1, "tolerance",
          tolerance, "must be in [1e-14, 0.1] [-]");
  require(max_iterations >= 1 && max_iterations <= 10000, "max_iterations", max_iterations,
          "must be in [1, 10000]");
}

}  // namespace catena
