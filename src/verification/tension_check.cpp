// SPDX-License-Identifier: MIT
// Another program's dynamic tension along a line against Catena's for the same excitation
// (docs/how-to/check-dynamic-tension.md): stations grouped by resolution, Catena interpolated to
// the other program's arc lengths, per-station differences against the combined uncertainty, and
// the convergence study at the stations every resolution shares.
#include "catena/verification/tension_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>

#include "catena/core/error.hpp"

namespace catena {
namespace {

using Complex = std::complex<double>;

// Two arc lengths closer than this fraction of L are the same station: node-based files compute
// s = i L / (nodes - 1) in floating point, so the same physical node at two resolutions may differ
// by a few ulps; no mesh is anywhere near 1e9 segments.
constexpr double kSameStation = 1e-9;

// Catena's profile of the compared quantity at its own stations. The amplitude is interpolated as
// the complex amplitude and its modulus taken afterwards, so that a turning phase does not dent
// the interpolated modulus.
struct Profile {
  const Vector& s;
  std::vector<Complex> values;

  Profile(const DynamicTension& t, TensionQuantity quantity) : s(t.s_m) {
    const bool amplitude = quantity == TensionQuantity::Amplitude;
    const Vector& magnitude = amplitude ? t.amplitude_n : t.std_n;
    if (magnitude.size() != s.size() || s.size() < 2) {
      throw InvalidInput(
          fmt::format("Catena's dynamic tension has no {} along the line ({} motion)",
                      to_string(quantity), t.irregular ? "irregular" : "regular"));
    }
    for (Index j = 0; j < s.size(); ++j) {
      const double phase = amplitude && t.phase_deg.size() == s.size() ? t.phase_deg[j] : 0.0;
      values.push_back(std::polar(magnitude[j], phase * kPi / 180.0));
    }
  }

  // The interpolated value at `x` and the estimated error of the linear interpolation: with f''
  // nearly constant over an interval, linear interpolation errs by at most h^2 |f''| / 8, and
  // h^2 f'' is the second difference at a neighbouring station (the larger of the two is taken).
  std::pair<double, double> at(double x) const {
    const Index n = s.size();
    const Index j = std::clamp<Index>(
        static_cast<Index>(std::upper_bound(s.data(), s.data() + n, x) - s.data()) - 1, 0, n - 2);
    const double h = s[j + 1] - s[j];
    const double t = h > 0.0 ? std::clamp((x - s[j]) / h, 0.0, 1.0) : 0.0;
    const Complex value = (1.0 - t) * values[std::size_t(j)] + t * values[std::size_t(j + 1)];
    double curvature = 0.0;
    for (Index k : {j, j + 1}) {
      if (k < 1 || k > n - 2 || t == 0.0 || t == 1.0) continue;
      curvature =
          std::max(curvature, std::abs(values[std::size_t(k - 1)] - 2.0 * values[std::size_t(k)] +
                                       values[std::size_t(k + 1)]));
    }
    return {std::abs(value), curvature / 8.0};
  }
};

std::string where(const ExternalTensionStation& station, const char* column) {
  return fmt::format("{}, column '{}'", station.origin, column);
}

void validate_station(const ExternalTensionStation& station, double length_m) {
  if (station.s_m.has_value() == station.node.has_value()) {
    throw InvalidInput(fmt::format("{}: give either s_m or node (with nodes), not {}",
                                   station.origin, station.s_m ? "both" : "neither"));
  }
  if (station.node) {
    if (!station.nodes)
      throw InvalidInput(fmt::format("{}: node without nodes", where(station, "nodes")));
    if (*station.nodes < 2)
      throw InvalidInput(
          fmt::format("{}: nodes = {}: must be >= 2", where(station, "nodes"), *station.nodes));
    if (*station.node < 0 || *station.node > *station.nodes - 1) {
      throw InvalidInput(fmt::format("{}: node = {}: must be in [0, nodes - 1 = {}]",
                                     where(station, "node"), *station.node, *station.nodes - 1));
    }
  } else if (!std::isfinite(*station.s_m) || *station.s_m < -kSameStation * length_m ||
             *station.s_m > (1.0 + kSameStation) * length_m) {
    throw InvalidInput(fmt::format("{}: s_m = {}: must be in [0, L = {:.10g}] m",
                                   where(station, "s_m"), *station.s_m, length_m));
  }
  if (!std::isfinite(station.tension_n) || station.tension_n < 0.0) {
    throw InvalidInput(fmt::format("{}: tension = {}: must be finite and >= 0 [N]", station.origin,
                                   station.tension_n));
  }
  if (station.uncertainty_n &&
      !(std::isfinite(*station.uncertainty_n) && *station.uncertainty_n >= 0.0)) {
    throw InvalidInput(fmt::format("{}: tension_uncertainty_n = {}: must be finite and >= 0 [N]",
                                   where(station, "tension_uncertainty_n"),
                                   *station.uncertainty_n));
  }
  if (station.resolution && !(std::isfinite(*station.resolution) && *station.resolution > 0.0)) {
    throw InvalidInput(fmt::format("{}: resolution = {}: must be finite and > 0",
                                   where(station, "resolution"), *station.resolution));
  }
}

// The stations of each resolution (ascending resolution), each sorted by s.
using Groups = std::map<double, std::vector<const ExternalTensionStation*>>;

Groups group_by_resolution(const ExternalTension& tension, double length_m) {
  Groups groups;
  const bool with = tension.stations.front().resolution.has_value();
  for (const auto& station : tension.stations) {
    if (station.resolution.has_value() != with) {
      throw InvalidInput(fmt::format("{}: resolution given on some rows but not on others",
                                     where(station, "resolution")));
    }
    groups[station.resolution.value_or(0.0)].push_back(&station);
  }
  for (auto& [resolution, rows] : groups) {
    std::stable_sort(rows.begin(), rows.end(), [&](const auto* a, const auto* b) {
      return station_s_m(*a, length_m) < station_s_m(*b, length_m);
    });
    for (std::size_t i = 1; i < rows.size(); ++i) {
      const double gap = station_s_m(*rows[i], length_m) - station_s_m(*rows[i - 1], length_m);
      if (gap <= kSameStation * length_m) {
        throw InvalidInput(fmt::format("{}: a second station at s = {:.10g} m (also {})",
                                       rows[i]->origin, station_s_m(*rows[i], length_m),
                                       rows[i - 1]->origin));
      }
    }
  }
  return groups;
}

TensionStationComparison compare_station(const ExternalTensionStation& station,
                                         const Profile& profile,
                                         double length_m,
                                         double catena_relative_estimate,
                                         double rtol) {
  TensionStationComparison c;
  c.s_m = station_s_m(station, length_m);
  c.other_n = station.tension_n;
  const auto [value, interpolation_error] = profile.at(c.s_m);
  c.catena_n = value;
  c.catena_uncertainty_n = std::max(catena_relative_estimate, 0.0) * value + interpolation_error;
  c.other_uncertainty_n = station.uncertainty_n.value_or(0.0);
  c.difference_n = c.other_n - c.catena_n;
  if (c.catena_n > 0.0) c.relative_error = c.difference_n / c.catena_n;
  c.allowed_n = rtol * c.catena_n + c.catena_uncertainty_n + c.other_uncertainty_n;
  c.within = std::abs(c.difference_n) <= c.allowed_n;
  c.origin = station.origin;
  return c;
}

// The verdict of a station with a study: as for frequencies (external_check.cpp), with Catena's
// own uncertainty beside the study's (Catena's tension estimate is not negligible as its
// frequencies' is).
ModeVerdict study_verdict(const TensionStationStudy& s,
                          const TensionStationComparison& finest,
                          double rtol) {
  if (s.study.trustworthy && s.study.bias_relative && s.catena_n > 0.0) {
    const double uncertainty = (s.study.limit_uncertainty_rad_s.value_or(0.0) +
                                finest.catena_uncertainty_n + finest.other_uncertainty_n) /
                               s.catena_n;
    if (std::abs(*s.study.bias_relative) - uncertainty > rtol)
      return ModeVerdict::ConvergesToWrongLimit;
    return finest.within ? ModeVerdict::Converged : ModeVerdict::NotYetWithinTolerance;
  }
  return finest.within ? ModeVerdict::WithinTolerance : ModeVerdict::BeyondTolerance;
}

std::string station_label(double s, double length_m) {
  if (s <= kSameStation * length_m) return "anchor";
  if (s >= (1.0 - kSameStation) * length_m) return "fairlead";
  return fmt::format("s = {:.6g} m", s);
}

// Studies at each station of the finest result that every coarser resolution also gives.
void study_shared_stations(const Groups& groups,
                           double length_m,
                           const ExternalCheckOptions& options,
                           TensionCheck& check) {
  for (std::size_t k = 0; k < check.stations.size(); ++k) {
    const TensionStationComparison& finest = check.stations[k];
    if (!(finest.catena_n > 0.0)) continue;  // no relative bias against a zero tension
    TensionStationStudy s;
    s.s_m = finest.s_m;
    s.label = station_label(s.s_m, length_m);
    s.catena_n = finest.catena_n;
    for (const auto& [resolution, rows] : groups) {
      const auto match = std::find_if(rows.begin(), rows.end(), [&](const auto* row) {
        return std::abs(station_s_m(*row, length_m) - s.s_m) <= kSameStation * length_m;
      });
      if (match == rows.end()) break;
      s.resolutions.push_back(resolution);
      s.values_n.push_back((*match)->tension_n);
    }
    if (s.resolutions.size() != groups.size()) continue;
    s.study = study_convergence(s.resolutions, s.values_n, s.catena_n, options);
    s.verdict = study_verdict(s, finest, options.rtol);
    check.studies.push_back(std::move(s));
  }
}

int severity(ModeVerdict verdict) {
  switch (verdict) {
    case ModeVerdict::ConvergesToWrongLimit:
      return 3;
    case ModeVerdict::BeyondTolerance:
      return 2;
    case ModeVerdict::NotYetWithinTolerance:
      return 1;
    default:
      return 0;
  }
}

ModeVerdict overall_verdict(const TensionCheck& check) {
  ModeVerdict worst = ModeVerdict::WithinTolerance;
  for (const auto& station : check.stations) {
    const auto study = std::find_if(check.studies.begin(), check.studies.end(),
                                    [&](const auto& s) { return s.s_m == station.s_m; });
    const ModeVerdict verdict =
        study != check.studies.end()
            ? study->verdict
            : (station.within ? ModeVerdict::WithinTolerance : ModeVerdict::BeyondTolerance);
    if (severity(verdict) > severity(worst)) worst = verdict;
  }
  // Every station within and converging to the right limit, with at least one study: converged.
  const bool all_converged =
      !check.studies.empty() && check.studies.size() == check.stations.size() &&
      std::all_of(check.studies.begin(), check.studies.end(),
                  [](const auto& s) { return s.verdict == ModeVerdict::Converged; });
  return severity(worst) == 0 && all_converged ? ModeVerdict::Converged : worst;
}

}  // namespace

std::string to_string(TensionQuantity quantity) {
  return quantity == TensionQuantity::Amplitude ? "tension_amplitude_n" : "tension_std_n";
}

double station_s_m(const ExternalTensionStation& station, double length_m) {
  if (station.s_m) return std::clamp(*station.s_m, 0.0, length_m);
  return length_m * double(*station.node) / double(*station.nodes - 1);
}

void validate_external_tension(const ExternalTension& tension, double length_m) {
  if (tension.stations.empty())
    throw InvalidInput(fmt::format("{}: no stations to check", tension.origin));
  if (tension.period_s && !(std::isfinite(*tension.period_s) && *tension.period_s > 0.0)) {
    throw InvalidInput(fmt::format("{}: period_s = {}: must be finite and > 0 [s]", tension.origin,
                                   *tension.period_s));
  }
  for (const auto& station : tension.stations) validate_station(station, length_m);
  group_by_resolution(tension, length_m);
}

TensionCheck check_external_tension(const ExternalTension& tension,
                                    const TensionReference& reference,
                                    const ExternalCheckOptions& options) {
  options.validate();
  const DynamicTension& t = reference.tension;
  const Profile profile(t, tension.quantity);
  const double length_m = t.s_m[t.s_m.size() - 1];
  validate_external_tension(tension, length_m);
  const Groups groups = group_by_resolution(tension, length_m);

  TensionCheck check;
  check.options = options;
  check.quantity = tension.quantity;
  check.period_s = t.irregular ? 0.0 : t.period_s;
  check.reference = reference;
  check.reference.tension.spectrum_omega_rad_s.resize(0);
  check.reference.tension.fairlead_spectrum_n2_s_per_rad.resize(0);
  check.reference.tension.anchor_spectrum_n2_s_per_rad.resize(0);
  const auto& [finest_resolution, finest_rows] = *groups.rbegin();
  if (finest_rows.front()->resolution) check.resolution = finest_resolution;
  double largest_difference = 0.0, largest_catena = 0.0;
  for (const ExternalTensionStation* row : finest_rows) {
    check.stations.push_back(
        compare_station(*row, profile, length_m, t.relative_error_estimate, options.rtol));
    const auto& c = check.stations.back();
    largest_difference = std::max(largest_difference, std::abs(c.difference_n));
    largest_catena = std::max(largest_catena, c.catena_n);
    if (c.s_m >= (1.0 - kSameStation) * length_m) check.fairlead = c;
  }
  check.max_relative_difference = largest_catena > 0.0 ? largest_difference / largest_catena : 0.0;
  if (groups.size() >= 3) study_shared_stations(groups, length_m, options, check);
  check.verdict = overall_verdict(check);
  return check;
}

}  // namespace catena
