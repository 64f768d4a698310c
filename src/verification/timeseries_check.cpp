// SPDX-License-Identifier: MIT
// `catena check` on a free decay: channels grouped by plane, the window checked, the modes
// identified, Catena's damped modes computed and matched, and with several runs the convergence
// study per mode (docs/how-to/check-time-series.md).
#include "catena/verification/timeseries_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

#include "catena/core/error.hpp"
#include "catena/verification/modal_identification.hpp"
#include "verification/internal/timeseries_matching.hpp"
#include "verification/internal/timeseries_reference.hpp"
#include "verification/internal/timeseries_window.hpp"

namespace catena {
namespace {

using internal::DampedReference;
using internal::SampleWindow;

// Catena computes this many modes per plane before it knows what the record holds (the lowest
// sets the shortest window), then as many as the highest identified frequency needs.
constexpr int kFirstReferenceModes = 6;
// Catena's modes must reach this factor above the highest identified frequency, so that the
// nearest Catena mode of the top identified one is really the nearest.
constexpr double kReferenceMargin = 1.2;
// Without --max-frequency the band identified reaches this factor above Catena's
// kFirstReferenceModes-th mode of the plane: a real record (MoorDyn at 20 Hz) rings in dozens of
// modes up to Nyquist, and fitting them all costs minutes while the high ones are the least linear
// and least resolved.
constexpr double kDefaultBandFactor = 1.5;
// A window must span this many periods of Catena's lowest mode of the plane (issue 33).
constexpr double kMinimumPeriods = 2.0;
// At most this many singular values go into the result (the order choice needs the top ones).
constexpr std::size_t kSingularValuesKept = 20;

struct PlaneChannels {
  Plane plane = Plane::InPlane;
  std::vector<std::string> names;
};

// The channels by plane, in-plane first; checks that each exists in every run.
std::vector<PlaneChannels> group_channels(const TimeSeries& series,
                                          const TimeSeriesCheckOptions& options) {
  std::map<Plane, std::vector<std::string>> planes;
  for (const std::string& name : options.channels) {
    const std::string& spelled = series.names[series.channel_index(name)];
    const auto plane = options.plane ? options.plane : channel_plane(spelled);
    if (!plane) {
      throw InvalidInput(fmt::format(
          "{}: channel '{}': its name does not say which plane it sees; give --plane in-plane "
          "(tension, x and z motion of a line in the x-z plane) or out-of-plane (y motion)",
          series.source, spelled));
    }
    planes[*plane].push_back(spelled);
  }
  std::vector<PlaneChannels> groups;
  for (const auto& [plane, names] : planes) groups.push_back({plane, names});
  return groups;
}

std::vector<Vector> window_samples(const TimeSeries& series,
                                   const PlaneChannels& group,
                                   const SampleWindow& window) {
  std::vector<Vector> samples;
  for (const std::string& name : group.names)
    samples.push_back(series.channel(name).segment(window.first, window.count));
  return samples;
}

const DampedReference& reference_of(const std::vector<DampedReference>& references, Plane plane) {
  return *std::find_if(references.begin(), references.end(),
                       [&](const DampedReference& r) { return r.plane == plane; });
}

void check_window_length(const TimeSeries& series,
                         const SampleWindow& window,
                         const DampedReference& reference) {
  if (reference.modes.empty()) return;
  const double lowest_hz = reference.modes.front().frequency_hz;
  const double length_s = window.time_s[window.count - 1] - window.time_s[0];
  if (lowest_hz > 0.0 && length_s < kMinimumPeriods / lowest_hz) {
    throw InvalidInput(fmt::format(
        "{}: the window {}:{} s lasts {:.4g} s, shorter than two periods of Catena's lowest {} "
        "mode ({:.6g} Hz, period {:.4g} s): the decay cannot resolve it; give a longer record or "
        "window",
        series.source, window.time_s[0], window.time_s[window.count - 1], length_s,
        to_string(reference.plane), lowest_hz, 1.0 / lowest_hz));
  }
}

std::vector<double> run_resolutions(const std::vector<TimeSeries>& runs,
                                    const TimeSeriesCheckOptions& options) {
  if (runs.size() == 1) return {};
  std::vector<double> resolutions = options.resolutions;
  if (resolutions.empty()) {
    for (const TimeSeries& run : runs) {
      if (!run.num_segments) {
        throw InvalidInput(fmt::format(
            "{}: several runs need the resolution of each (--resolution N per file, e.g. MoorDyn's "
            "NumSegs); a MoorDyn line file (Line<k>.out) tells its own",
            run.source));
      }
      resolutions.push_back(*run.num_segments);
    }
  }
  if (resolutions.size() != runs.size()) {
    throw InvalidInput(fmt::format("{} runs and {} resolutions: give one resolution per run",
                                   runs.size(), resolutions.size()));
  }
  if (std::set<double>(resolutions.begin(), resolutions.end()).size() != resolutions.size())
    throw InvalidInput("two runs have the same resolution: each run must be a different mesh");
  return resolutions;
}

// The notes on what makes a decay of this scene non-linear, so that the comparison is not exact.
std::vector<std::string> scene_notes(const Scene& scene, const std::vector<DampedReference>& refs) {
  std::vector<std::string> notes;
  notes.push_back(
      "the comparison is linear: tension sees in-plane modes only in the linear theory; the record "
      "must be a small-amplitude decay (docs/how-to/moordyn-free-decay.md)");
  if (scene.problem.has_drag()) {
    notes.push_back(
        "the scene has Morison drag: Catena's damped modes include only its linear damping; a run "
        "with quadratic drag decays faster at large amplitude, and its damping ratios do not "
        "compare exactly");
  }
  if (scene.problem.seabed) {
    notes.push_back(
        "the scene has a seabed: a touchdown point that moves during the decay makes the run "
        "non-linear; Catena's modes are those of the static contact");
  }
  for (const auto& ref : refs) {
    const bool undamped = std::all_of(ref.modes.begin(), ref.modes.end(),
                                      [](const Mode& m) { return m.damping_ratio == 0.0; });
    if (undamped) {
      notes.push_back(fmt::format(
          "{}: the scene is undamped: Catena's zeta is 0 and each identified zeta is compared to 0 "
          "within its uncertainty",
          to_string(ref.plane)));
    }
  }
  return notes;
}

// The top of the band identified when the user gives none (kDefaultBandFactor); 0 (the
// identification's own default, 0.8 Nyquist) when that is lower anyway.
double default_band_top_hz(const DampedReference& reference, const SampleWindow& window) {
  if (reference.modes.empty() || window.count < 2) return 0.0;
  const double nyquist_hz = 0.5 / window.step_s;
  const double top_hz = kDefaultBandFactor * reference.modes.back().frequency_hz;
  return top_hz < 0.8 * nyquist_hz ? top_hz : 0.0;
}

int highest_needed(const std::vector<Identification>& found, const DampedReference& reference) {
  double top_hz = 0.0;
  for (const auto& id : found)
    for (const auto& m : id.modes) top_hz = std::max(top_hz, m.frequency_hz);
  const int have = static_cast<int>(reference.modes.size());
  if (reference.modes.empty()) return kFirstReferenceModes;
  const double catena_top = reference.modes.back().frequency_hz;
  if (catena_top >= kReferenceMargin * top_hz) return have;
  // Mode frequencies grow about linearly with the mode number: ask enough, with room.
  return std::min(kMaxRequestModes,
                  static_cast<int>(std::ceil(have * kReferenceMargin * top_hz / catena_top)) + 2);
}

// The convergence study of one Catena mode over the runs (resolutions ascending).
TimeSeriesStudy study_mode(const std::vector<std::vector<TimeSeriesModeCheck>>& per_run,
                           const std::vector<double>& resolutions,
                           const TimeSeriesModeCheck& finest) {
  TimeSeriesStudy s;
  std::vector<std::size_t> order(resolutions.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return resolutions[a] < resolutions[b]; });
  for (const std::size_t r : order) {
    for (const auto& c : per_run[r]) {
      if (c.plane == finest.plane && c.mode == finest.mode &&
          (c.verdict == "agrees" || c.verdict == "disagrees")) {
        s.resolutions.push_back(resolutions[r]);
        s.frequencies_hz.push_back(c.identified_frequency_hz);
        s.frequency_uncertainties_hz.push_back(c.frequency_uncertainty_hz);
      }
    }
  }
  const std::size_t n = s.resolutions.size();
  s.verdict = "inconclusive";
  if (n < 3) {
    s.study.note = fmt::format("identified in {} of the runs; the study needs three", n);
    return s;
  }
  // Differences within the identification's uncertainty are noise, not mesh convergence: fitting
  // an order to them would invent one.
  for (std::size_t i = n - 3; i + 1 < n; ++i) {
    const double step = std::abs(s.frequencies_hz[i + 1] - s.frequencies_hz[i]);
    if (step <= s.frequency_uncertainties_hz[i] + s.frequency_uncertainties_hz[i + 1]) {
      s.study.note = fmt::format(
          "the runs at resolutions {} and {} differ by {:.3e} Hz, within their identification "
          "uncertainty: the mesh error is below what the records resolve; the finest run's verdict "
          "stands",
          s.resolutions[i], s.resolutions[i + 1], step);
      return s;
    }
  }
  std::vector<double> omegas;
  for (double f : s.frequencies_hz) omegas.push_back(2.0 * kPi * f);
  s.study = study_convergence(s.resolutions, omegas, 2.0 * kPi * finest.catena_frequency_hz);
  if (!s.study.trustworthy || !s.study.limit_omega_rad_s) return s;
  const double limit_hz = *s.study.limit_omega_rad_s / (2.0 * kPi);
  const double allowed = s.study.limit_uncertainty_rad_s.value_or(0.0) / (2.0 * kPi) +
                         s.frequency_uncertainties_hz.back() + finest.catena_frequency_error_hz;
  s.verdict = std::abs(limit_hz - finest.catena_frequency_hz) <= allowed
                  ? "converges to Catena"
                  : "converges to a wrong limit";
  return s;
}

}  // namespace

void TimeSeriesCheckOptions::validate() const {
  if (channels.empty()) throw InvalidInput("TimeSeriesCheckOptions::channels: give at least one");
  for (const auto& name : channels) {
    if (name.empty()) throw InvalidInput("TimeSeriesCheckOptions::channels: an empty name");
    if (std::count(channels.begin(), channels.end(), name) > 1)
      throw InvalidInput(fmt::format("TimeSeriesCheckOptions::channels: '{}' given twice", name));
  }
  for (const auto& [field, value] :
       {std::pair{"window_start_s", window_start_s}, std::pair{"window_end_s", window_end_s}}) {
    if (value && !std::isfinite(*value))
      throw InvalidInput(
          fmt::format("TimeSeriesCheckOptions::{} = {}: must be finite", field, *value));
  }
  if (window_start_s && window_end_s && !(*window_start_s < *window_end_s)) {
    throw InvalidInput(fmt::format("window {}:{} s: the start must be before the end",
                                   *window_start_s, *window_end_s));
  }
  for (const auto& [field, value] : {std::pair{"min_frequency_hz", min_frequency_hz},
                                     std::pair{"max_frequency_hz", max_frequency_hz}}) {
    if (!(std::isfinite(value) && value >= 0.0))
      throw InvalidInput(
          fmt::format("TimeSeriesCheckOptions::{} = {}: must be >= 0 [Hz]", field, value));
  }
  if (max_frequency_hz > 0.0 && !(max_frequency_hz > min_frequency_hz)) {
    throw InvalidInput(
        fmt::format("TimeSeriesCheckOptions::max_frequency_hz = {}: must be above "
                    "min_frequency_hz = {}",
                    max_frequency_hz, min_frequency_hz));
  }
  if (!(std::isfinite(confidence_sigmas) && confidence_sigmas > 0.0)) {
    throw InvalidInput(fmt::format("TimeSeriesCheckOptions::confidence_sigmas = {}: must be > 0",
                                   confidence_sigmas));
  }
  for (double r : resolutions) {
    if (!(std::isfinite(r) && r > 0.0))
      throw InvalidInput(fmt::format("TimeSeriesCheckOptions::resolutions: {} must be > 0", r));
  }
}

bool TimeSeriesCheck::any_failure() const {
  const bool wrong_limit =
      std::any_of(modes.begin(), modes.end(), [](const TimeSeriesModeCheck& m) {
        return m.study && m.study->verdict == "converges to a wrong limit";
      });
  return !error.empty() || disagrees > 0 || unmatched > 0 || wrong_limit || agrees == 0;
}

TimeSeriesCheck check_time_series(const Scene& scene,
                                  const TimeSeries& series,
                                  const TimeSeriesCheckOptions& options) {
  return check_time_series_runs(scene, {series}, options);
}

TimeSeriesCheck check_time_series_runs(const Scene& scene,
                                       const std::vector<TimeSeries>& runs,
                                       const TimeSeriesCheckOptions& options) {
  options.validate();
  if (runs.empty()) throw InvalidInput("no time series to check");
  const std::vector<double> resolutions = run_resolutions(runs, options);
  const std::size_t finest =
      resolutions.empty()
          ? 0
          : static_cast<std::size_t>(std::max_element(resolutions.begin(), resolutions.end()) -
                                     resolutions.begin());
  // Bad input first, before any solve: channels, planes, samples, windows.
  std::vector<PlaneChannels> groups = group_channels(runs[finest], options);
  std::vector<SampleWindow> windows;
  for (const TimeSeries& run : runs) {
    for (const auto& group : groups)
      for (const auto& name : group.names) run.channel(name);
    windows.push_back(internal::select_window(run, options.window_start_s, options.window_end_s));
  }
  TimeSeriesCheck check;
  check.runs = static_cast<int>(runs.size());
  check.resolutions = resolutions;
  check.window_start_s = windows[finest].time_s[0];
  check.window_end_s = windows[finest].time_s[windows[finest].count - 1];
  std::map<Plane, int> counts;
  for (const auto& group : groups) counts[group.plane] = kFirstReferenceModes;
  std::vector<DampedReference> references = internal::damped_references(scene, counts, check.error);
  if (!check.error.empty()) return check;
  for (std::size_t r = 0; r < runs.size(); ++r)
    for (const auto& group : groups)
      check_window_length(runs[r], windows[r], reference_of(references, group.plane));
  // Identification of every run, plane by plane (the channels of a plane share the poles).
  IdentificationOptions identification;
  identification.min_frequency_hz = options.min_frequency_hz;
  identification.confidence_sigmas = options.confidence_sigmas;
  std::map<Plane, std::vector<Identification>> found;
  for (const auto& group : groups) {
    for (std::size_t r = 0; r < runs.size(); ++r) {
      identification.max_frequency_hz =
          options.max_frequency_hz > 0.0
              ? options.max_frequency_hz
              : default_band_top_hz(reference_of(references, group.plane), windows[r]);
      found[group.plane].push_back(identify_modes(
          windows[r].time_s, window_samples(runs[r], group, windows[r]), identification));
    }
  }
  // Enough Catena modes to reach the highest identified frequency.
  bool more = false;
  for (const auto& group : groups) {
    const int needed = highest_needed(found[group.plane], reference_of(references, group.plane));
    more = more || needed > static_cast<int>(reference_of(references, group.plane).modes.size());
    counts[group.plane] = needed;
  }
  if (more) {
    references = internal::damped_references(scene, counts, check.error);
    if (!check.error.empty()) return check;
  }
  for (const auto& group : groups) {
    const DampedReference& reference = reference_of(references, group.plane);
    const auto& ids = found[group.plane];
    std::vector<std::vector<TimeSeriesModeCheck>> per_run;
    std::vector<TimeSeriesModeNotPresent> ignored;
    for (std::size_t r = 0; r < runs.size(); ++r)
      per_run.push_back(
          internal::match_modes(ids[r], reference, r == finest ? check.not_present : ignored));
    for (TimeSeriesModeCheck& mode : per_run[finest]) {
      if (runs.size() > 1 && mode.mode > 0) {
        mode.study = study_mode(per_run, resolutions, mode);
        if (mode.verdict == "disagrees" && mode.study->verdict == "converges to Catena") {
          mode.note +=
              "; the runs converge to Catena's value: the finest run's difference is its "
              "discretisation error (refine further for agreement)";
        }
      }
      check.modes.push_back(mode);
    }
    TimeSeriesPlane plane;
    plane.plane = to_string(group.plane);
    plane.channels = group.names;
    const Identification& id = ids[finest];
    plane.method = id.method;
    plane.model_order = id.model_order;
    plane.noise_rms = id.noise_rms;
    plane.sample_interval_s = id.sample_interval_s;
    plane.singular_values.assign(
        id.singular_values.begin(),
        id.singular_values.begin() +
            static_cast<long>(std::min(kSingularValuesKept, id.singular_values.size())));
    plane.reference_solver = reference.solver;
    plane.reference_reason = reference.reason;
    plane.cross_check_relative = reference.cross_check_relative;
    plane.undamped = std::all_of(reference.modes.begin(), reference.modes.end(),
                                 [](const Mode& m) { return m.damping_ratio == 0.0; });
    check.planes.push_back(plane);
  }
  check.notes = scene_notes(scene, references);
  for (const auto& mode : check.modes) {
    check.agrees += mode.verdict == "agrees";
    check.disagrees += mode.verdict == "disagrees";
    check.not_identifiable += mode.verdict == "not identifiable";
    check.unmatched += mode.verdict == "unmatched";
  }
  if (check.agrees == 0 && check.disagrees == 0) {
    check.notes.push_back(
        "no mode could be compared: nothing was verified (a longer window, a larger initial "
        "offset, or less noise)");
  }
  return check;
}

}  // namespace catena
