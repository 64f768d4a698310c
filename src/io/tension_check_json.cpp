// SPDX-License-Identifier: MIT
// The JSON of `catena check` on another program's dynamic tension
// (docs/how-to/check-dynamic-tension.md, "Output").
#include "catena/io/tension_check_json.hpp"

#include <nlohmann/json.hpp>

#include "catena/core/version.hpp"
#include "catena/io/file_access.hpp"
#include "io/internal/json_text.hpp"

namespace catena {
namespace {

using nlohmann::json;

template <class T>
json optional_value(const std::optional<T>& value) {
  return value ? json(*value) : json(nullptr);
}

json station_json(const TensionStationComparison& c) {
  return {{"s_m", c.s_m},
          {"other_n", c.other_n},
          {"catena_n", c.catena_n},
          {"catena_uncertainty_n", c.catena_uncertainty_n},
          {"other_uncertainty_n", c.other_uncertainty_n},
          {"difference_n", c.difference_n},
          {"relative_error", optional_value(c.relative_error)},
          {"allowed_n", c.allowed_n},
          {"within", c.within},
          {"origin", c.origin}};
}

// The shared convergence study holds tensions here in its fields named for frequencies.
json study_json(const TensionStationStudy& s) {
  return {{"s_m", s.s_m},
          {"station", s.label},
          {"resolutions", s.resolutions},
          {"values_n", s.values_n},
          {"catena_n", s.catena_n},
          {"trustworthy", s.study.trustworthy},
          {"note", s.study.note},
          {"observed_order", optional_value(s.study.observed_order)},
          {"coarser_order", optional_value(s.study.coarser_order)},
          {"limit_n", optional_value(s.study.limit_omega_rad_s)},
          {"limit_uncertainty_n", optional_value(s.study.limit_uncertainty_rad_s)},
          {"bias_relative", optional_value(s.study.bias_relative)},
          {"verdict", to_string(s.verdict)},
          {"failed", is_failure(s.verdict)}};
}

json end_json(const DynamicTensionEnd& end) {
  const auto present = [](double v) { return v < 0.0 ? json(nullptr) : json(v); };
  return {{"s_m", end.s_m},
          {"mean_n", end.mean_n},
          {"amplitude_n", present(end.amplitude_n)},
          {"phase_deg", end.amplitude_n < 0.0 ? json(nullptr) : json(end.phase_deg)},
          {"std_n", present(end.std_n)},
          {"most_probable_max_n", present(end.most_probable_max_n)}};
}

json reference_json(const TensionReference& reference) {
  const DynamicTension& t = reference.tension;
  return {
      {"solver", reference.solver},
      {"reason", reference.reason},
      {"shooting_vs_fe_relative",
       reference.cross_check_relative < 0.0 ? json(nullptr) : json(reference.cross_check_relative)},
      {"relative_error_estimate", t.relative_error_estimate},
      {"iterations", t.iterations},
      {"residual", t.residual},
      {"fairlead", end_json(t.fairlead)},
      {"anchor", end_json(t.anchor)}};
}

}  // namespace

std::string tension_check_to_json(const TensionCheck& check, const CheckSources& sources) {
  json stations = json::array();
  for (const auto& station : check.stations) stations.push_back(station_json(station));
  json studies = json::array();
  for (const auto& study : check.studies) studies.push_back(study_json(study));
  const json document = {
      {"catena", provenance()},
      {"created_utc", utc_timestamp()},
      {"scene", {{"name", sources.scene_name}, {"file", sources.scene_file}}},
      {"results_file", sources.results_file},
      {"quantity", to_string(check.quantity)},
      {"period_s", check.period_s > 0.0 ? json(check.period_s) : json(nullptr)},
      {"rtol", check.options.rtol},
      {"order_stability", check.options.order_stability},
      {"reference", reference_json(check.reference)},
      {"resolution", optional_value(check.resolution)},
      {"stations", stations},
      {"fairlead", check.fairlead ? station_json(*check.fairlead) : json(nullptr)},
      {"studies", studies},
      {"max_relative_difference", check.max_relative_difference},
      {"verdict", to_string(check.verdict)},
      {"failed", check.any_failure()}};
  return internal::json_text(document, 2);
}

void write_tension_check_json(const std::filesystem::path& path,
                              const TensionCheck& check,
                              const CheckSources& sources) {
  write_file_atomically(path, tension_check_to_json(check, sources) + "\n");
}

}  // namespace catena
