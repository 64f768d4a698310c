// SPDX-License-Identifier: MIT
// Another program's modes against Catena's certified reference (docs/how-to/check.md): grouping of
// the results by plane and mode, pairing with Catena's modes, per-resolution errors, the
// convergence study and the verdict.
#include "catena/verification/external_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "catena/core/error.hpp"
#include "catena/solvers/solve_request.hpp"
#include "verification/internal/shape_comparison.hpp"

namespace catena {
namespace {

// Pairing by MAC considers Catena's modes within this relative frequency distance: close modes
// (which MAC tells apart) are well inside it, distant modes with similar shapes are outside.
constexpr double kMacPairingWindow = 0.25;

// The results of one mode of the other program, coarsest first.
struct ModeGroup {
  Plane plane = Plane::InPlane;
  int mode = 0;
  std::vector<const ExternalMode*> rows;
  const ExternalMode& finest() const { return *rows.back(); }
};

std::string group_origin(const ModeGroup& group) {
  return fmt::format("{} mode {} ({})", to_string(group.plane), group.mode, group.finest().origin);
}

void sort_and_check_resolutions(ModeGroup& group) {
  const bool with = group.rows.front()->resolution.has_value();
  for (const ExternalMode* row : group.rows) {
    if (row->resolution.has_value() != with) {
      throw InvalidInput(fmt::format("{}: {} mode {} mixes results with and without a resolution",
                                     row->origin, to_string(group.plane), group.mode));
    }
  }
  std::stable_sort(group.rows.begin(), group.rows.end(),
                   [](const ExternalMode* a, const ExternalMode* b) {
                     return a->resolution.value_or(0.0) < b->resolution.value_or(0.0);
                   });
  for (std::size_t i = 1; i < group.rows.size(); ++i) {
    if (group.rows[i]->resolution == group.rows[i - 1]->resolution) {
      throw InvalidInput(fmt::format(
          "{}: duplicate {} mode {}{} (also {})", group.rows[i]->origin, to_string(group.plane),
          group.mode, with ? fmt::format(" at resolution {}", *group.rows[i]->resolution) : "",
          group.rows[i - 1]->origin));
    }
  }
}

std::vector<ModeGroup> group_results(const std::vector<ExternalMode>& results) {
  std::map<std::pair<int, int>, ModeGroup> groups;  // in-plane first, then by mode number
  for (const ExternalMode& row : results) {
    if (row.mode < 1)
      throw InvalidInput(fmt::format("{}: mode = {}: must be >= 1", row.origin, row.mode));
    // Catena solves at most kMaxRequestModes per plane: a higher mode has no reference, and a
    // reference near the limit is minutes of work, so it is refused before anything is solved.
    if (row.mode > kMaxRequestModes)
      throw InvalidInput(fmt::format("{}: mode = {}: Catena solves at most {} modes per plane",
                                     row.origin, row.mode, kMaxRequestModes));
    if (!std::isfinite(row.omega_rad_s) || row.omega_rad_s <= 0.0) {
      throw InvalidInput(fmt::format("{}: frequency = {} rad/s: must be finite and > 0", row.origin,
                                     row.omega_rad_s));
    }
    if (row.resolution && !(std::isfinite(*row.resolution) && *row.resolution > 0.0)) {
      throw InvalidInput(
          fmt::format("{}: resolution = {}: must be finite and > 0", row.origin, *row.resolution));
    }
    ModeGroup& group = groups[{row.plane == Plane::InPlane ? 0 : 1, row.mode}];
    group.plane = row.plane;
    group.mode = row.mode;
    group.rows.push_back(&row);
  }
  std::vector<ModeGroup> out;
  for (auto& [key, group] : groups) {
    sort_and_check_resolutions(group);
    out.push_back(std::move(group));
  }
  return out;
}

const CertifiedReference& reference_for(const std::vector<CertifiedReference>& references,
                                        const ModeGroup& group) {
  for (const auto& reference : references) {
    if (reference.plane == group.plane && !reference.modes.empty()) return reference;
  }
  throw InvalidInput(
      fmt::format("{}: Catena has no {} reference modes for it (the scene asks none?)",
                  group_origin(group), to_string(group.plane)));
}

double relative_distance(double a, double b) { return std::abs(a / b - 1.0); }

struct Candidate {
  std::size_t group;
  std::size_t reference;
  double score;  // lower is better
  double mac;    // -1 when by frequency
};

// Pairs the groups of one plane with Catena's modes, one to one, greedily by score: by MAC (of
// the finest result) when every group has a shape, else by relative frequency distance.
void pair_plane(const std::vector<ModeGroup>& groups,
                const std::vector<std::size_t>& members,
                const CertifiedReference& reference,
                std::vector<ModeComparison>& out) {
  bool by_mac = true;
  for (std::size_t g : members) by_mac = by_mac && groups[g].finest().shape.has_value();
  std::vector<Candidate> candidates;
  for (std::size_t g : members) {
    const ExternalMode& finest = groups[g].finest();
    for (std::size_t r = 0; r < reference.modes.size(); ++r) {
      const double distance = relative_distance(finest.omega_rad_s, reference.modes[r].omega_rad_s);
      if (!by_mac) {
        candidates.push_back({g, r, distance, -1.0});
      } else if (distance <= kMacPairingWindow) {
        const double mac =
            internal::compare_shape(*finest.shape, groups[g].plane, reference.modes[r]).mac;
        candidates.push_back({g, r, -mac, mac});
      }
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
  std::vector<bool> taken(reference.modes.size(), false);
  for (const Candidate& c : candidates) {
    ModeComparison& mode = out[c.group];
    if (mode.reference_index != 0 || taken[c.reference]) continue;
    taken[c.reference] = true;
    const ReferenceMode& ref = reference.modes[c.reference];
    mode.reference_index = ref.index;
    mode.reference_omega_rad_s = ref.omega_rad_s;
    mode.reference_relative_estimate = ref.relative_error_estimate;
    mode.pairing = c.mac >= 0.0 ? fmt::format("MAC {:.6f}", c.mac) : std::string("frequency");
    if (ref.index != mode.mode)
      mode.pairing +=
          fmt::format("; the other program's mode {} is Catena's mode {}", mode.mode, ref.index);
  }
}

ModeVerdict decide(const ModeComparison& mode, double rtol) {
  if (mode.reference_index == 0) return ModeVerdict::Unpaired;
  const bool within = std::abs(mode.resolutions.back().relative_error) <= rtol;
  const auto& study = mode.study;
  if (study && study->trustworthy && study->bias_relative) {
    const double uncertainty =
        study->limit_uncertainty_rad_s.value_or(0.0) / mode.reference_omega_rad_s;
    if (std::abs(*study->bias_relative) - uncertainty > rtol)
      return ModeVerdict::ConvergesToWrongLimit;
    return within ? ModeVerdict::Converged : ModeVerdict::NotYetWithinTolerance;
  }
  return within ? ModeVerdict::WithinTolerance : ModeVerdict::BeyondTolerance;
}

void compare_mode(const ModeGroup& group,
                  const CertifiedReference& reference,
                  const ExternalCheckOptions& options,
                  ModeComparison& mode) {
  if (mode.reference_index == 0) {
    mode.pairing = "no Catena mode left to pair with";
  } else {
    const ReferenceMode& ref = reference.modes[static_cast<std::size_t>(
        std::find_if(reference.modes.begin(), reference.modes.end(),
                     [&](const ReferenceMode& r) { return r.index == mode.reference_index; }) -
        reference.modes.begin())];
    std::vector<double> resolutions;
    std::vector<double> values;
    for (const ExternalMode* row : group.rows) {
      ResolutionComparison c;
      c.resolution = row->resolution;
      c.omega_rad_s = row->omega_rad_s;
      c.relative_error = (row->omega_rad_s - ref.omega_rad_s) / ref.omega_rad_s;
      if (row->shape) {
        const auto shape = internal::compare_shape(*row->shape, group.plane, ref);
        c.mac = shape.mac;
        c.tension_relative = shape.tension_relative;
      }
      mode.resolutions.push_back(c);
      resolutions.push_back(row->resolution.value_or(0.0));
      values.push_back(row->omega_rad_s);
    }
    if (group.rows.size() >= 3)
      mode.study = study_convergence(resolutions, values, ref.omega_rad_s, options);
  }
  mode.verdict = decide(mode, options.rtol);
}

void validate_shapes(const ModeGroup& group, const CertifiedReference& reference) {
  for (const ExternalMode* row : group.rows) {
    if (!row->shape) continue;
    const ReferenceMode& any = reference.modes.front();
    if (any.s_m.size() < 2) {
      throw InvalidInput(
          fmt::format("{}: a shape was given but the reference has no shapes", row->origin));
    }
    internal::validate_external_shape(*row->shape, group.plane, any.s_m[any.s_m.size() - 1],
                                      row->origin);
  }
}

}  // namespace

void ExternalCheckOptions::validate() const {
  if (!(std::isfinite(rtol) && rtol > 0.0)) {
    throw InvalidInput(
        fmt::format("Invalid ExternalCheckOptions::rtol = {}: must be finite and > 0", rtol));
  }
  if (!(std::isfinite(order_stability) && order_stability > 0.0)) {
    throw InvalidInput(
        fmt::format("Invalid ExternalCheckOptions::order_stability = {}: must be finite and > 0",
                    order_stability));
  }
}

std::string to_string(ModeVerdict verdict) {
  switch (verdict) {
    case ModeVerdict::WithinTolerance:
      return "within tolerance";
    case ModeVerdict::BeyondTolerance:
      return "beyond tolerance";
    case ModeVerdict::Converged:
      return "converged";
    case ModeVerdict::NotYetWithinTolerance:
      return "converges, not yet within tolerance";
    case ModeVerdict::ConvergesToWrongLimit:
      return "converges to a wrong limit";
    case ModeVerdict::Unpaired:
      return "unpaired";
  }
  return "unknown";
}

bool is_failure(ModeVerdict verdict) {
  return verdict != ModeVerdict::WithinTolerance && verdict != ModeVerdict::Converged;
}

bool ExternalCheck::any_failure() const {
  return std::any_of(modes.begin(), modes.end(),
                     [](const ModeComparison& m) { return is_failure(m.verdict); });
}

void validate_external_results(const std::vector<ExternalMode>& results) {
  if (results.empty()) throw InvalidInput("no results to check");
  group_results(results);
}

ExternalCheck check_external_results(const std::vector<ExternalMode>& results,
                                     const std::vector<CertifiedReference>& references,
                                     const ExternalCheckOptions& options) {
  options.validate();
  if (results.empty()) throw InvalidInput("no results to check");
  const std::vector<ModeGroup> groups = group_results(results);
  ExternalCheck check;
  check.options = options;
  check.modes.resize(groups.size());
  for (const Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    std::vector<std::size_t> members;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      if (groups[g].plane != plane) continue;
      members.push_back(g);
      check.modes[g].plane = plane;
      check.modes[g].mode = groups[g].mode;
    }
    if (members.empty()) continue;
    const CertifiedReference& reference = reference_for(references, groups[members.front()]);
    check.references.push_back(reference);
    for (std::size_t g : members) validate_shapes(groups[g], reference);
    pair_plane(groups, members, reference, check.modes);
    for (std::size_t g : members) compare_mode(groups[g], reference, options, check.modes[g]);
  }
  return check;
}

}  // namespace catena
