// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Collects the checks of one scene: their common fields, tolerances from the reviewed table (never
/// from a solver's own estimate), the verdict rules, and the independence rule
/// (docs/reference/verdicts.md).

#include <optional>
#include <string>
#include <vector>

#include "catena/solvers/solver_registry.hpp"
#include "catena/verification/findings.hpp"
#include "catena/verification/scene_runner.hpp"
#include "catena/verification/tolerance_table.hpp"

namespace catena::internal {

const char* plane_name(Plane plane);
/// A relative difference above this is a gross disagreement: FAIL whatever the rule (unless the
/// rule is a `beyond = "warn"` model limit).
constexpr double kGrossRelativeDifference = 0.5;
/// The largest conditioned forced tolerance: beyond it a relative difference says nothing (the
/// response is at resonance for every solver) and the check is a WARN, never a silent PASS.
constexpr double kMostConditionedForcedTolerance = 0.1;
/// |a - b| / max(|a|, |b|) (0 when both are 0).
double relative_difference(double a, double b);
/// The modes of `plane`, or nullptr when there are none.
const ModalResult* modal_of(const SolverOutput& output, Plane plane);
/// eps and the static strain of the scene, for a rule's model term.
ModelParameters model_parameters(const SceneResult& result);

class CheckBuilder {
 public:
  /// `solvers`: the solvers' declarations of their computations (normally solver_registry()).
  CheckBuilder(const SceneResult& result,
               const ToleranceTable& tolerances,
               const FindingsTable& findings,
               const std::vector<SolverEntry>& solvers);

  const SceneResult& result() const { return result_; }
  const ToleranceTable& tolerances() const { return tolerances_; }
  const FindingsTable& findings() const { return findings_; }
  const std::vector<CheckResult>& checks() const { return checks_; }

  struct Tolerance {
    double value;
    std::string reason;
    bool warn_only = false;
  };
  /// The tolerance for `check` between a and b: the scene's [checks] override, else the first
  /// matching rule evaluated on the scene's model parameters; nullopt when neither exists.
  std::optional<Tolerance> tolerance(const std::string& check,
                                     const std::string& a,
                                     const std::string& b,
                                     std::optional<double> scene_override) const;

  /// The forced tolerance at forcing frequency `omega`: the rule's max (or the scene's override)
  /// times the response's condition number kappa(omega)
  /// (catena/verification/forced_conditioning.hpp, from the most accurate exact solver's natural
  /// frequencies, never from an estimate). `checkable` is false when that would exceed
  /// kMostConditionedForcedTolerance.
  struct ForcedTolerance {
    Tolerance tolerance;  // value = max x kappa
    double max = 0.0;
    double kappa = 1.0;
    bool checkable = true;
    std::string note;  // "tolerance <max> x kappa <kappa> (<source>) = <value>"
  };
  std::optional<ForcedTolerance> forced_tolerance(const std::string& a,
                                                  const std::string& b,
                                                  double omega) const;

  /// The computation id solvers a and b share for `quantity`, if any.
  std::optional<std::string> shared(const std::string& a,
                                    const std::string& b,
                                    const std::string& quantity) const;
  /// False, after recording one SKIP (kind `check`) naming the shared id, when a and b share the
  /// computation of `quantity`; true when they may be compared.
  bool independent(const std::string& a,
                   const std::string& b,
                   const std::string& quantity,
                   const std::string& check,
                   const std::string& plane);

  CheckResult base(const std::string& check,
                   const std::string& compare,
                   const std::string& plane,
                   int mode) const;
  void add(CheckResult check);
  /// measured <= tolerance, with the gross and non-finite rules.
  void add_measured(CheckResult check, double measured, const Tolerance& tol, bool relative);

 private:
  const SolverEntry* entry(const std::string& name) const;

  const SceneResult& result_;
  const ToleranceTable& tolerances_;
  const FindingsTable& findings_;
  const std::vector<SolverEntry>& solvers_;
  ModelParameters parameters_;
  std::vector<CheckResult> checks_;
};

/// `tol` tightened to the sum of the accuracy targets the scene asked of two exact solvers (their
/// planes' SolverSummary::accuracy_target, ma and mb) where that sum is below the rule; the rule
/// stays the ceiling (docs/reference/verdicts.md, "Tolerances"). Shared by the frequency and
/// decay-rate checks.
std::optional<CheckBuilder::Tolerance> tightened_by_targets(
    std::optional<CheckBuilder::Tolerance> tol,
    const CheckBuilder& builder,
    const SolverOutput& a,
    const SolverOutput& b,
    const ModalResult& ma,
    const ModalResult& mb);

}  // namespace catena::internal
