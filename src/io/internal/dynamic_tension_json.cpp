// SPDX-License-Identifier: MIT
#include "io/internal/dynamic_tension_json.hpp"

#include <cmath>

#include "io/internal/results_keys.hpp"

namespace catena::internal {
namespace {

using nlohmann::json;

json number(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json numbers(const Vector& values) {
  json out = json::array();
  for (Index i = 0; i < values.size(); ++i) out.push_back(number(values[i]));
  return out;
}

json numbers(const std::vector<double>& values) {
  json out = json::array();
  for (double x : values) out.push_back(number(x));
  return out;
}

// values[i], or null where a solver left the column short (never read past its end).
json at(const Vector& values, Index i) { return i < values.size() ? number(values[i]) : json(); }

// One record per station, the layout: {s_m, mean_n, amplitude_n, phase_deg, motion_m}
// (regular) or {s_m, mean_n, std_n, motion_m} (irregular).
json stations_json(const DynamicTension& t) {
  json out = json::array();
  for (Index i = 0; i < t.s_m.size(); ++i) {
    json station = {{key::s_m, number(t.s_m[i])}, {key::mean_n, at(t.mean_n, i)}};
    if (t.irregular) {
      station[key::std_n] = at(t.std_n, i);
    } else {
      station[key::amplitude_n] = at(t.amplitude_n, i);
      station[key::phase_deg] = at(t.phase_deg, i);
    }
    station[key::motion_m] = at(t.motion_m, i);
    out.push_back(station);
  }
  return out;
}

json end_json(const DynamicTensionEnd& end, bool irregular) {
  json out = {{key::s_m, number(end.s_m)}, {key::mean_n, number(end.mean_n)}};
  if (irregular) {
    out[key::std_n] = number(end.std_n);
    out[key::zero_upcrossing_period_s] = number(end.zero_upcrossing_period_s);
    out[key::most_probable_max_n] = number(end.most_probable_max_n);
  } else {
    out[key::amplitude_n] = number(end.amplitude_n);
    out[key::phase_deg] = number(end.phase_deg);
  }
  return out;
}

}  // namespace

json motion_request_json(const MotionRequest& m) {
  json out = {{key::direction, to_string(m.direction)}};
  if (m.direction == ForcingDirection::GivenVector) out[key::vector] = {m.vector.x(), m.vector.y()};
  if (!m.is_irregular()) {
    out[key::amplitude_m] = m.amplitude_m;
    out[key::periods_s] = numbers(m.periods_s);
  }
  if (m.spectrum) {
    out[key::spectrum] = {{key::omega_rad_s, numbers(m.spectrum->omega_rad_s)},
                          {key::density_m2_s_per_rad, numbers(m.spectrum->density_m2_s_per_rad)}};
  }
  if (m.jonswap) {
    out[key::jonswap] = {
        {key::hs_m, m.jonswap->hs_m}, {key::tp_s, m.jonswap->tp_s}, {key::gamma, m.jonswap->gamma}};
  }
  if (m.rao) {
    out[key::rao] = {{key::omega_rad_s, numbers(m.rao->omega_rad_s)},
                     {key::amplitude, numbers(m.rao->amplitude)},
                     {key::phase_deg, numbers(m.rao->phase_deg)},
                     {key::per, m.rao->per_wave_height ? "wave_height" : "wave_amplitude"}};
  }
  if (m.is_irregular()) {
    out[key::frequencies] = m.frequencies;
    out[key::duration_s] = m.duration_s;
  }
  out[key::tolerance] = m.tolerance;
  out[key::max_iterations] = m.max_iterations;
  return out;
}

json dynamic_tension_json(const DynamicTension& t) {
  json out = {{key::motion, t.irregular ? "irregular" : "regular"}};
  if (!t.irregular) {
    out[key::period_s] = number(t.period_s);
    out[key::omega_rad_s] = number(t.omega_rad_s);
  }
  out[key::stations] = stations_json(t);
  out[key::fairlead] = end_json(t.fairlead, t.irregular);
  out[key::anchor] = end_json(t.anchor, t.irregular);
  out[key::damping_n_s_per_m2] = numbers(t.normal_damping_n_s_per_m2);
  out[key::tangential_damping_n_s_per_m2] = numbers(t.tangential_damping_n_s_per_m2);
  if (t.irregular) {
    out[key::spectrum] = {{key::omega_rad_s, numbers(t.spectrum_omega_rad_s)},
                          {key::fairlead_n2_s_per_rad, numbers(t.fairlead_spectrum_n2_s_per_rad)},
                          {key::anchor_n2_s_per_rad, numbers(t.anchor_spectrum_n2_s_per_rad)}};
  }
  out[key::iterations] = t.iterations;
  out[key::residual] = number(t.residual);
  out[key::converged] = t.converged;
  out[key::relative_error_estimate] = number(t.relative_error_estimate);
  out[key::diagnostic] = t.diagnostic;
  return out;
}

json dynamic_tension_list_json(const std::vector<DynamicTension>& tensions) {
  json out = json::array();
  for (const DynamicTension& t : tensions) out.push_back(dynamic_tension_json(t));
  return out;
}

}  // namespace catena::internal
