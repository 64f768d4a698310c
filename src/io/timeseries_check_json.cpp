// SPDX-License-Identifier: MIT
// The JSON of `catena check` on a free decay (docs/reference/json-layout.md, "Time-series check").
#include "catena/io/timeseries_check_json.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "catena/core/version.hpp"
#include "catena/io/file_access.hpp"
#include "io/internal/json_text.hpp"

namespace catena {
namespace {

using nlohmann::json;

// Non-finite numbers never reach the document: null instead.
json number(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

template <class T>
json optional_number(const std::optional<T>& value) {
  return value ? number(*value) : json(nullptr);
}

json numbers(const std::vector<double>& values) {
  json out = json::array();
  for (double v : values) out.push_back(number(v));
  return out;
}

json study_json(const TimeSeriesStudy& s) {
  const auto hz = [](const std::optional<double>& rad_s) {
    return rad_s ? number(*rad_s / (2.0 * kPi)) : json(nullptr);
  };
  return {{"resolutions", numbers(s.resolutions)},
          {"frequencies_hz", numbers(s.frequencies_hz)},
          {"frequency_uncertainties_hz", numbers(s.frequency_uncertainties_hz)},
          {"trustworthy", s.study.trustworthy},
          {"note", s.study.note},
          {"observed_order", optional_number(s.study.observed_order)},
          {"coarser_order", optional_number(s.study.coarser_order)},
          {"limit_frequency_hz", hz(s.study.limit_omega_rad_s)},
          {"limit_uncertainty_hz", hz(s.study.limit_uncertainty_rad_s)},
          {"bias_relative", optional_number(s.study.bias_relative)},
          {"verdict", s.verdict}};
}

json mode_json(const TimeSeriesModeCheck& m) {
  const bool matched = m.mode > 0;
  const auto catena = [&](double v) { return matched ? number(v) : json(nullptr); };
  return {{"plane", m.plane},
          {"mode", matched ? json(m.mode) : json(nullptr)},
          {"identified_frequency_hz", number(m.identified_frequency_hz)},
          {"frequency_uncertainty_hz", number(m.frequency_uncertainty_hz)},
          {"identified_damping_ratio", number(m.identified_damping_ratio)},
          {"damping_ratio_uncertainty", number(m.damping_ratio_uncertainty)},
          {"identified_decay_rate_1_s", number(m.identified_decay_rate_1_s)},
          {"signal_to_noise", number(m.signal_to_noise)},
          {"catena_frequency_hz", catena(m.catena_frequency_hz)},
          {"catena_damping_ratio", catena(m.catena_damping_ratio)},
          {"catena_frequency_error_hz", catena(m.catena_frequency_error_hz)},
          {"catena_damping_ratio_error", catena(m.catena_damping_ratio_error)},
          {"frequency_error_hz", catena(m.frequency_error_hz)},
          {"damping_ratio_error", catena(m.damping_ratio_error)},
          {"verdict", m.verdict},
          {"note", m.note},
          {"study", m.study ? study_json(*m.study) : json(nullptr)}};
}

json plane_json(const TimeSeriesPlane& p) {
  return {{"plane", p.plane},
          {"channels", p.channels},
          {"method", p.method},
          {"model_order", p.model_order},
          {"noise_rms", number(p.noise_rms)},
          {"sample_interval_s", number(p.sample_interval_s)},
          {"singular_values", numbers(p.singular_values)},
          {"reference_solver", p.reference_solver},
          {"reference_reason", p.reference_reason},
          {"shooting_vs_fe_relative",
           p.cross_check_relative < 0.0 ? json(nullptr) : number(p.cross_check_relative)},
          {"undamped", p.undamped}};
}

}  // namespace

std::string timeseries_check_to_json(const TimeSeriesCheck& check,
                                     const TimeSeriesSources& sources) {
  json modes = json::array();
  for (const auto& m : check.modes) modes.push_back(mode_json(m));
  json absent = json::array();
  for (const auto& m : check.not_present) {
    absent.push_back({{"plane", m.plane},
                      {"mode", m.mode},
                      {"catena_frequency_hz", number(m.catena_frequency_hz)},
                      {"catena_damping_ratio", number(m.catena_damping_ratio)}});
  }
  json planes = json::array();
  for (const auto& p : check.planes) planes.push_back(plane_json(p));
  const json document = {{"catena", provenance()},
                         {"created_utc", utc_timestamp()},
                         {"scene", {{"name", sources.scene_name}, {"file", sources.scene_file}}},
                         {"files", sources.files},
                         {"channels", sources.channels},
                         {"runs", check.runs},
                         {"resolutions", numbers(check.resolutions)},
                         {"window_s", {number(check.window_start_s), number(check.window_end_s)}},
                         {"planes", planes},
                         {"modes", modes},
                         {"not_present", absent},
                         {"notes", check.notes},
                         {"counts",
                          {{"agrees", check.agrees},
                           {"disagrees", check.disagrees},
                           {"not_identifiable", check.not_identifiable},
                           {"unmatched", check.unmatched}}},
                         {"error", check.error.empty() ? json(nullptr) : json(check.error)},
                         {"failed", check.any_failure()}};
  return internal::json_text(document, 2);
}

void write_timeseries_check_json(const std::filesystem::path& path,
                                 const TimeSeriesCheck& check,
                                 const TimeSeriesSources& sources) {
  write_file_atomically(path, timeseries_check_to_json(check, sources) + "\n");
}

}  // namespace catena
