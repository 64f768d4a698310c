// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// A scene: one cable, one request, optionally which solvers (with knobs), check tolerances and
/// published values to compare with (docs/reference/scene-format.md). Scenes are read from TOML by
/// io/scene_reader.hpp; a sweep scene expands into one Scene per value.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "catena/models/cable.hpp"
#include "catena/solvers/solve_request.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "catena/statics/dimensionless_groups.hpp"

namespace catena {

/// What a published value is.
enum class PublishedQuantity { InPlaneFrequency, OutOfPlaneFrequency, ForcedMaxTension };
/// "inplane_frequency", "outofplane_frequency", "forced_max_tension".
std::string to_string(PublishedQuantity quantity);
std::optional<PublishedQuantity> parse_published_quantity(const std::string& text);

/// Values printed in a source table that this scene reproduces.
struct PublishedValues {
  /// e.g. "Gale (1976) Table B-3, h/b = 0.00, sag 0.9679".
  std::string source;
  PublishedQuantity quantity = PublishedQuantity::InPlaneFrequency;
  /// Unit of `values` for frequencies; for forced_max_tension the values are tension / H.
  FrequencyUnit unit = FrequencyUnit::RadPerSecond;
  /// Mode numbers (1-based) for frequencies; for forced_max_tension, the index (0-based) of the
  /// forcing frequency in the request.
  std::vector<int> modes;
  std::vector<double> values;
  /// The solvers that compute what the column tabulates (e.g. "asymptotic" for Grinfogel's
  /// 'approx' column); empty: every solver that runs.
  std::vector<std::string> compare_with;
  /// Decimal places printed: the rounding half-width is 0.5 * 10^-decimals. -1: unknown.
  int decimals = -1;
};

/// Cross-check tolerances a scene may override (defaults: verification/tolerances.toml).
struct CheckSettings {
  std::optional<double> frequency_rel;
  std::optional<double> mac_min;
  std::optional<double> shape_max_diff;
  std::optional<double> tension_rel;
  std::optional<double> orthogonality;
};

/// One scene, ready to run.
struct Scene {
  /// Unique name (a sweep appends "[parameter=value]").
  std::string name;
  std::string description;
  std::filesystem::path file;
  Problem problem;
  /// The request. Its forcing frequencies and amplitude are in the units below until
  /// resolve_request() converts them to SI (which needs the statics).
  SolveRequest request;
  /// Unit of request.forced->omegas_rad_s as written in the scene.
  FrequencyUnit forcing_frequency_unit = FrequencyUnit::RadPerSecond;
  /// True when the forcing amplitude is in units of Gale's a = H/W0 rather than metres.
  bool forcing_amplitude_in_a = false;
  /// Solvers named in [solvers] with their knobs; empty means every applicable solver with
  /// default knobs.
  std::map<std::string, SolverKnobs> solvers;
  CheckSettings checks;
  std::vector<PublishedValues> published;
  /// Tags for filtering and grouping in reports (e.g. "gale-B3", "stress").
  std::vector<std::string> tags;
  /// For a sweep member: the parameter and its value.
  std::optional<std::pair<std::string, double>> sweep_point;

  /// The solvers to run: the named ones, or all registered ones.
  std::vector<std::string> solver_names() const;
};

/// The scene's request in SI units (forcing frequencies in rad/s, amplitude in m).
SolveRequest resolve_request(const Scene& scene, const DimensionlessGroups& groups);

}  // namespace catena
