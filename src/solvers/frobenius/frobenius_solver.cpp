// SPDX-License-Identifier: MIT
// The `frobenius` solver: Gale's power series for the inextensible catenary
// (docs/explanation/methods/frobenius.md). This file holds the options, the applicability rule and
// the numerics class that ties the parts together; the parts live in src/solvers/frobenius/:
//   frobenius_series.hpp, frobenius_catenary.hpp  the series engine and the catenary's basis
//   frobenius_boundary.*                          the scaled boundary matrix and determinant
//   frobenius_root_scan.*                         the frequencies (scan, refinement, correction)
//   frobenius_conjugate_points.*                  the independent in-plane root count
//   frobenius_fields.*                            null vector, U, V, T along the cable, mode shapes
//   frobenius_forced.*                            the forced response
//   frobenius_damped_*                            the damped (viscous medium) modes and response
#include "catena/solvers/frobenius_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "catena/core/error.hpp"
#include "solvers/common/knob_table.hpp"
#include "solvers/common/line_applicability.hpp"
#include "solvers/common/mode_tools.hpp"
#include "solvers/common/solver_driver.hpp"
#include "solvers/common/solver_entries.hpp"
#include "solvers/common/work_meter.hpp"
#include "solvers/frobenius/frobenius_conjugate_points.hpp"
#include "solvers/frobenius/frobenius_damped_forced.hpp"
#include "solvers/frobenius/frobenius_damped_modes.hpp"
#include "solvers/frobenius/frobenius_fields.hpp"
#include "solvers/frobenius/frobenius_forced.hpp"
#include "solvers/frobenius/frobenius_root_scan.hpp"

namespace catena {

namespace internal {

const KnobTable<FrobeniusSolverOptions>& frobenius_knobs() {
  using O = FrobeniusSolverOptions;
  static const KnobTable<O> table(
      "frobenius",
      {real_knob("tolerance", &O::tolerance, Range::closed(1e-15, 1e-3),
                 "target relative accuracy of each frequency [-]"),
       integer_knob("max_terms", &O::max_terms, Range::closed(8, 5000),
                    "cap on the terms of one expansion"),
       real_knob("step_ratio", &O::step_ratio, Range::closed(0.1, 0.8),
                 "expansion-centre spacing as a fraction of the radius of convergence"),
       real_knob("scan_fraction", &O::scan_fraction, Range::closed(0.01, 0.5),
                 "root-scan grid as a fraction of the mode spacing"),
       flag_knob("extended_precision", &O::extended_precision,
                 "allow long double / quad when double loses digits")});
  return table;
}

}  // namespace internal

void FrobeniusSolverOptions::validate() const { internal::frobenius_knobs().validate(*this); }

std::optional<std::string> frobenius_not_applicable_reason(const Problem& problem,
                                                           const DimensionlessGroups& groups) {
  if (!problem.cable.is_inextensible())
    return fmt::format(
        "the frobenius solver models an inextensible cable (EA = inf, Gale 1976); this cable has "
        "EA = {:f} N",
        problem.cable.axial_stiffness_n);
  if (!groups.has_apex_parameterization || !(groups.catenary_parameter_m > 0.0))
    return std::string(
        "the frobenius solver needs a catenary with H > 0 (Gale's parameter a = H/W0 is "
        "undefined)");
  if (!(problem.cable.weight_n_per_m > 0.0))
    return std::string("the frobenius solver needs a positive weight W0 (Gale's catenary)");
  return std::nullopt;
}

namespace internal {
namespace {

// Stations s [m] with their sigma = V(s)/H.
FieldStations field_stations(const StaticSolution& statics, const Vector& s_m) {
  FieldStations stations;
  stations.s_m = s_m;
  const double H = statics.horizontal_force_n();
  for (Index i = 0; i < s_m.size(); ++i)
    stations.sigma.push_back(statics.vertical_force_n(s_m(i)) / H);
  return stations;
}

// The accuracy each frequency is asked for: ten times `tolerance` (the estimate is the last
// a-posteriori correction, itself conservative), and never below 1e-13 (double rounding).
double accuracy_target(const FrobeniusSolverOptions& options) {
  return std::max(options.tolerance, 1e-14) * 10.0;
}

// The numerics of the frobenius solver for one problem.
class FrobeniusNumerics final : public SolverNumerics {
 public:
  FrobeniusNumerics(const SolveContext& context, const FrobeniusSolverOptions& options)
      : context_(context), options_(options) {}

  std::optional<std::string> not_applicable() const override {
    if (auto reason = uniform_cable_only(context_.problem, "the Frobenius series of the catenary"))
      return reason;
    if (auto reason = no_seabed_contact(context_.statics, "the Frobenius series of the catenary"))
      return reason;
    return frobenius_not_applicable_reason(context_.problem, context_.groups);
  }
  // Gale's viscous medium (c_t, c_n; c_a = 0 for EA = inf, a seabed is declined above).
  bool handles_damping() const override { return true; }
  bool handles_damped_forced() const override { return true; }
  void describe(SolverSummary& summary) const override;
  std::optional<Outcome> prepare() override;
  ModalResult modes(Plane plane, int count) override;
  ForcedOutcome forced(const ForcedRequest& request) override;

 private:
  RootSettings root_settings() const {
    return {options_.tolerance, options_.scan_fraction, options_.extended_precision};
  }
  void summarise_plane(Plane plane, int count, const PlaneRoots& found, ModalResult& result) const;
  ModalResult damped_modes(Plane plane, int count);
  DampedSetup damped_setup(bool inplane) const;
  // Drag on the cable itself. A damped problem without it (a seabed dashpot under a cable that
  // does not touch the seabed: this solver declines contact) has the undamped modes.
  bool has_drag() const {
    const SectionDamping& d = context_.problem.cable.damping;
    return d.tangential_n_s_per_m2 > 0.0 || d.normal_n_s_per_m2 > 0.0;
  }

  const SolveContext& context_;
  FrobeniusSolverOptions options_;
  PlaneSetup base_;
  CableUnits units_;
  FieldStations stations_;
  // Dense internal stations for max |T| when tension is asked without shapes.
  FieldStations dense_;
};

void FrobeniusNumerics::describe(SolverSummary& summary) const {
  summary.resolution = fmt::format(
      "tolerance {:g}, max_terms {}, step_ratio {:g}, scan_fraction {:g}, {}", options_.tolerance,
      options_.max_terms, options_.step_ratio, options_.scan_fraction,
      options_.extended_precision ? "long double / quad when double loses digits"
                                  : "double precision only");
}

std::optional<Outcome> FrobeniusNumerics::prepare() {
  const Problem& problem = context_.problem;
  const DimensionlessGroups& groups = context_.groups;
  units_.length_m = groups.catenary_parameter_m;
  units_.tension_n = context_.statics.horizontal_force_n();
  units_.frequency_rad_s = groups.gale_frequency_scale_rad_s;
  units_.mass_kg_per_m = problem.cable.mass_kg_per_m;
  units_.normal_mass_kg_per_m = problem.cable.normal_mass_kg_per_m();
  base_.sigma1 = groups.sigma1;
  base_.sigma2 = groups.sigma2;
  base_.mu = units_.normal_mass_kg_per_m / units_.mass_kg_per_m;
  base_.eta_max = std::max(std::abs(groups.xi1), std::abs(groups.xi2)) * (1.0 + 1e-12) + 1e-12;
  base_.settings.term_tolerance = std::max(options_.tolerance * 1e-3, 1e-34);
  base_.settings.max_terms = options_.max_terms;
  base_.settings.step_ratio = options_.step_ratio;
  stations_ = field_stations(context_.statics, context_.request.stations_m(problem.cable.length_m));
  Vector dense_s(401);
  for (int i = 0; i <= 400; ++i) dense_s(i) = problem.cable.length_m * i / 400.0;
  dense_ = field_stations(context_.statics, dense_s);
  return std::nullopt;
}

DampedSetup FrobeniusNumerics::damped_setup(bool inplane) const {
  DampedSetup setup;
  setup.plane = base_;
  setup.plane.inplane = inplane;
  const SectionDamping& damping = context_.problem.cable.damping;
  setup.eta1 = gale_drag(damping.tangential_n_s_per_m2, units_);
  setup.eta2 = gale_drag(damping.normal_n_s_per_m2, units_);
  return setup;
}

ModalResult FrobeniusNumerics::damped_modes(Plane plane, int count) {
  WorkMeter meter(context_, "frobenius", std::string(to_string(plane)) + " damped modes", count);
  const SolveRequest& request = context_.request;
  const ModeFieldRequest fields{request.shapes, request.tension, &stations_, &dense_};
  ModalResult result =
      damped_modal_result(damped_setup(plane == Plane::InPlane), count, root_settings(), fields,
                          units_, context_.groups, accuracy_target(options_));
  mark_time_limit(meter, result.summary);
  return result;
}

ModalResult FrobeniusNumerics::modes(Plane plane, int count) {
  if (context_.problem.is_damped() && has_drag()) return damped_modes(plane, count);
  const bool inplane = plane == Plane::InPlane;
  PlaneSetup setup = base_;
  setup.inplane = inplane;
  WorkMeter meter(context_, "frobenius", std::string(to_string(plane)) + " modes", count);
  PlaneRoots found = find_frequencies(setup, count, root_settings(), &meter);
  ModalResult result;
  if (inplane)
    result.proved_count_below_top = confirm_inplane_count(setup, count, root_settings(), found);
  const SolveRequest& request = context_.request;
  const ModeFieldRequest fields{request.shapes, request.tension, &stations_, &dense_};
  int sturm_ok = 0;
  for (std::size_t i = 0; i < found.roots.size(); ++i) {
    const FoundRoot& root = found.roots[i];
    Mode mode;
    mode.index = static_cast<int>(i) + 1;
    set_mode_frequency(mode, root.omega * units_.frequency_rad_s, context_.groups);
    mode.relative_error_estimate = root.relative_error;
    // Sturm: the n-th out-of-plane mode has n - 1 interior nodes (checked on the stations).
    if (add_mode_fields(mode, setup, root.omega, root.precision, fields, units_) == mode.index - 1)
      ++sturm_ok;
    result.modes.push_back(mode);
  }
  if (!inplane && sturm_ok == static_cast<int>(found.roots.size()) && !found.roots.empty()) {
    result.proved_count_below_top = static_cast<int>(found.roots.size());
    found.notes.push_back(fmt::format(
        "mode count checked by Sturm oscillation: mode n has n - 1 interior nodes for n = 1..{}",
        found.roots.size()));
  }
  summarise_plane(plane, count, found, result);
  mark_time_limit(meter, result.summary);
  return result;
}

// Converged when every root was found, no series hit max_terms and every root's error estimate
// is within ten times the tolerance (the estimate is the last a-posteriori correction, itself
// conservative).
void FrobeniusNumerics::summarise_plane(Plane plane,
                                        int count,
                                        const PlaneRoots& found,
                                        ModalResult& result) const {
  double worst = 0.0;
  Precision precision = Precision::Double;
  for (const FoundRoot& root : found.roots) {
    worst = std::max(worst, root.relative_error);
    precision = std::max(precision, root.precision);
  }
  const bool converged = static_cast<int>(found.roots.size()) == count && !found.work.truncated &&
                         worst <= accuracy_target(options_);
  SolverSummary& summary = result.summary;
  summary.accuracy_target = accuracy_target(options_);  // the skeleton names misses
  summary.termination = converged ? Termination::Converged
                                  : (found.roots.empty() ? Termination::NumericalFailure
                                                         : Termination::NoConvergence);
  summary.message = fmt::format(
      "{}: {} of {} {} modes, max relative error estimate {:g} {} {:g}{}",
      converged ? "Converged" : "Not converged", found.roots.size(), count, to_string(plane), worst,
      converged ? "<=" : "vs", accuracy_target(options_),
      found.work.truncated ? fmt::format("; some series hit max_terms = {}", options_.max_terms)
                           : std::string());
  summary.resolution = fmt::format(
      "tolerance {:g}, up to {} series terms over {} expansion centres, highest precision {}",
      options_.tolerance, found.work.terms, found.work.centres, precision_name(precision));
  summary.iterations = found.work.terms;
  summary.operations = found.work.determinant_evaluations;
  summary.max_error_estimate = worst;
  summary.notes = found.notes;
  summary.notes.push_back(
      fmt::format("root scan: {} local minima of |det| searched for hidden close pairs, {} found",
                  found.minima_checked, found.hidden_pairs_found));
  summary.warnings = found.warnings;
  if (precision != Precision::Double)
    summary.warnings.push_back(
        fmt::format("the double-precision roots needed corrections above tolerance/10 from the "
                    "finer-series re-evaluation in {} "
                    "(truncation carried through the matched expansions and/or rounding); the "
                    "returned roots include them",
                    precision_name(precision)));
}

// A forcing frequency at a natural frequency has no finite response: that response carries the
// diagnostic, and the part still converged (it is the physical answer, not a numerical failure).
// A frequency the series cannot resolve is declined: the part is then not converged.
ForcedOutcome FrobeniusNumerics::forced(const ForcedRequest& request) {
  ForcedOutcome outcome;
  ForcedWork work;
  WorkMeter meter(context_, "frobenius", "forced frequencies",
                  static_cast<long>(request.omegas_rad_s.size()));
  outcome.responses =
      context_.problem.is_damped() && has_drag()
          ? frobenius_damped_forced_responses(damped_setup(true), request, stations_, units_, work,
                                              &meter)
          : frobenius_forced_responses(base_, request, stations_, units_, work, &meter);
  std::size_t at_resonance = 0, declined = 0;
  double worst = 0.0;
  for (const ForcedResponse& r : outcome.responses) {
    if (r.at_resonance)
      ++at_resonance;
    else if (!r.diagnostic.empty())
      ++declined;
    worst = std::max(worst, r.relative_error_estimate);
    if (!r.diagnostic.empty()) outcome.summary.warnings.push_back(r.diagnostic);
  }
  SolverSummary& summary = outcome.summary;
  summary.termination = declined == 0                         ? Termination::Converged
                        : declined < outcome.responses.size() ? Termination::NoConvergence
                                                              : Termination::NumericalFailure;
  summary.message =
      fmt::format("{} of {} forced frequencies", outcome.responses.size() - at_resonance - declined,
                  request.omegas_rad_s.size());
  if (at_resonance > 0)
    summary.message +=
        fmt::format(" ({} at a natural frequency: no finite response)", at_resonance);
  if (declined > 0)
    summary.message += fmt::format(" ({} declined: beyond the series' resolution)", declined);
  summary.resolution = fmt::format(
      "up to {} series terms over {} expansion centres (at most {:g} rad of "
      "phase per expansion), long double",
      work.terms, work.centres, kForcedPhasePerExpansion);
  summary.notes.push_back(summary.resolution);
  summary.operations = work.evaluations;
  summary.max_error_estimate = worst > 0.0 ? worst : -1.0;
  mark_time_limit(meter, summary);
  return outcome;
}

}  // namespace

SolverEntry make_frobenius_entry() {
  SolverEntry entry = make_solver_entry(
      "Gale's power series for the inextensible catenary (Gale 1976), chained expansions to any "
      "sag, adaptive "
      "terms, extended precision when needed",
      frobenius_knobs(), [](const SolveContext& context, const FrobeniusSolverOptions& options) {
        return std::make_unique<FrobeniusNumerics>(context, options);
      });
  entry.kind = SolverKind::Exact;  // not a certifier: the inextensible catenary only
  set_accuracy_target(entry, frobenius_knobs(), accuracy_target);
  return entry;
}

}  // namespace internal

SolverOutput solve_frobenius(const Problem& problem,
                             const StaticSolution& statics,
                             const DimensionlessGroups& groups,
                             const SolveRequest& request,
                             const FrobeniusSolverOptions& options) {
  return internal::solve_with<internal::FrobeniusNumerics>(
      "frobenius", {problem, statics, groups, request}, options);
}

}  // namespace catena
