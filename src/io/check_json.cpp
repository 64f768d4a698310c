// SPDX-License-Identifier: MIT
// The JSON of `catena check` (docs/how-to/check.md, "JSON"): every number of the comparison.
#include <nlohmann/json.hpp>

#include "catena/core/version.hpp"
#include "catena/io/check_report.hpp"
#include "catena/io/file_access.hpp"
#include "io/internal/json_text.hpp"

namespace catena {
namespace {

using nlohmann::json;

constexpr double kRadPerSecondToHz = 1.0 / (2.0 * kPi);

template <class T>
json optional_value(const std::optional<T>& value) {
  return value ? json(*value) : json(nullptr);
}

json reference_json(const CertifiedReference& reference) {
  json modes = json::array();
  for (const auto& mode : reference.modes) {
    modes.push_back({{"index", mode.index},
                     {"omega_rad_s", mode.omega_rad_s},
                     {"frequency_hz", mode.omega_rad_s * kRadPerSecondToHz},
                     {"relative_error_estimate", mode.relative_error_estimate}});
  }
  return {
      {"plane", to_string(reference.plane)},
      {"solver", reference.solver},
      {"reason", reference.reason},
      {"shooting_vs_fe_relative",
       reference.cross_check_relative < 0 ? json(nullptr) : json(reference.cross_check_relative)},
      {"modes", modes}};
}

json study_json(const ConvergenceStudy& study) {
  const auto hz = [](const std::optional<double>& omega) {
    return omega ? json(*omega * kRadPerSecondToHz) : json(nullptr);
  };
  return {{"trustworthy", study.trustworthy},
          {"note", study.note},
          {"observed_order", optional_value(study.observed_order)},
          {"coarser_order", optional_value(study.coarser_order)},
          {"limit_omega_rad_s", optional_value(study.limit_omega_rad_s)},
          {"limit_frequency_hz", hz(study.limit_omega_rad_s)},
          {"limit_uncertainty_rad_s", optional_value(study.limit_uncertainty_rad_s)},
          {"bias_relative", optional_value(study.bias_relative)}};
}

json mode_json(const ModeComparison& mode) {
  json resolutions = json::array();
  for (const auto& r : mode.resolutions) {
    resolutions.push_back({{"resolution", optional_value(r.resolution)},
                           {"omega_rad_s", r.omega_rad_s},
                           {"frequency_hz", r.omega_rad_s * kRadPerSecondToHz},
                           {"relative_error", r.relative_error},
                           {"mac", optional_value(r.mac)},
                           {"tension_relative", optional_value(r.tension_relative)}});
  }
  return {{"plane", to_string(mode.plane)},
          {"mode", mode.mode},
          {"reference_index", mode.reference_index},
          {"reference_omega_rad_s", mode.reference_omega_rad_s},
          {"reference_frequency_hz", mode.reference_omega_rad_s * kRadPerSecondToHz},
          {"reference_relative_estimate", mode.reference_relative_estimate},
          {"pairing", mode.pairing},
          {"resolutions", resolutions},
          {"study", mode.study ? study_json(*mode.study) : json(nullptr)},
          {"verdict", to_string(mode.verdict)},
          {"failed", is_failure(mode.verdict)}};
}

}  // namespace

std::string check_to_json(const ExternalCheck& check, const CheckSources& sources) {
  json references = json::array();
  for (const auto& reference : check.references) references.push_back(reference_json(reference));
  json modes = json::array();
  int failed = 0;
  for (const auto& mode : check.modes) {
    modes.push_back(mode_json(mode));
    failed += is_failure(mode.verdict) ? 1 : 0;
  }
  const json document = {
      {"catena", provenance()},
      {"created_utc", utc_timestamp()},
      {"scene", {{"name", sources.scene_name}, {"file", sources.scene_file}}},
      {"results_file", sources.results_file},
      {"shapes_file", sources.shapes_file.empty() ? json(nullptr) : json(sources.shapes_file)},
      {"rtol", check.options.rtol},
      {"order_stability", check.options.order_stability},
      {"references", references},
      {"modes", modes},
      {"failed_modes", failed}};
  return internal::json_text(document, 2);
}

void write_check_json(const std::filesystem::path& path,
                      const ExternalCheck& check,
                      const CheckSources& sources) {
  write_file_atomically(path, check_to_json(check, sources) + "\n");
}

}  // namespace catena
