// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Expected agreement, held as reviewed data (verification/tolerances.toml, after Boost.Math's
/// expected_results()): each rule says which check and which pair of solvers (or a solver and the
/// published value) it governs, the tolerance, and why. A tolerance never depends on what a solver
/// says of its own accuracy (docs/reference/verdicts.md, "Tolerances"): it is a fixed number, plus,
/// for an asymptotic model, the model's published error term evaluated on the scene.
///
///     [[tolerance]]
///     check = "frequency"               # frequency, published, mac, shape, tension, forced,
///                                       # orthogonality, decay-rate, dynamic-tension,
///                                       # drag-anchor
///     compare = ["fe", "*"]             # solver names, "*" (any solver) or "published"
///     scene = "*"                       # optional glob on the scene name
///     tag = "gale"                      # optional: only scenes with this tag
///     max = 1e-8                        # the fixed part of the tolerance (required, > 0)
///     model_parameter = "eps"           # optional, with model_order and constant: adds
///     model_order = 2                   #   constant * parameter^model_order (the model's
///     constant = 1.0                    #   published order; the constant reviewed, with reason)
///     strain_constant = 0.5             # optional: adds strain_constant * T0 / EA (a model that
///                                       #   neglects the static strain)
///     beyond = "warn"                   # optional: a model's known limit, WARN (not FAIL) when
///                                       # exceeded; the measured value is still reported
///     reason = "..."                    # required
///
///     [[solver]]                        # one per solver whose error estimate is checked
///     name = "shooting"
///     family = "exact"                  # "exact" (may serve as the reference) or "model"
///     accuracy = 1e-10                  # the accuracy it is asked for by default
///     accuracy_knob = "rtol"            # optional: the knob that sets it in a scene
///     reason = "..."
///
/// The first rule that matches wins: put specific rules before general ones. `estimate_factor`
/// (a tolerance that grew with the solvers' own estimates) is rejected by the reader.

#include <string>
#include <vector>

namespace catena {

/// The scene quantities a model's error term is written in.
struct ModelParameters {
  /// Grinfogel's eps = W0 L / T0.
  double eps = 0.0;
  /// The static strain T0 / EA (0 for an inextensible cable).
  double strain = 0.0;
};

/// The model parameters a rule may name in `model_parameter`: "eps".
bool is_model_parameter(const std::string& name);

struct ToleranceRule {
  std::string check;
  /// Two entries: solver names, "*" or "published". Order does not matter.
  std::vector<std::string> compare;
  std::string scene_pattern = "*";
  std::string tag;
  /// The fixed part of the tolerance (for `published`: absolute, in the table's unit, added to
  /// the printed rounding; otherwise relative, or 1 - MAC for `mac`).
  double max = 0.0;
  /// Empty, or a name accepted by is_model_parameter(): the model's small parameter.
  std::string model_parameter;
  /// The model's published order in that parameter.
  int model_order = 0;
  /// The reviewed constant of the model term.
  double constant = 0.0;
  /// Coefficient of the static strain T0 / EA.
  double strain_constant = 0.0;
  /// True for `beyond = "warn"`: exceeding the tolerance is a documented model limit.
  bool warn_only = false;
  std::string reason;

  /// The model part: constant * parameter^model_order + strain_constant * strain (relative).
  double model_term(const ModelParameters& parameters) const;
  /// max + model_term(parameters): the tolerance of a relative check.
  double tolerance(const ModelParameters& parameters) const;
};

/// What the estimate check needs to know of a solver (docs/reference/verdicts.md, "The estimate as
/// a claim").
struct SolverAccuracy {
  std::string name;
  /// True for "exact": a method whose error can be driven to rounding (it may be the reference
  /// against which the others' estimates are checked); false for an asymptotic model.
  bool exact = false;
  /// The relative accuracy it is asked for by default; an estimate at or below it is never called
  /// uninformative.
  double accuracy = 0.0;
  /// The knob that sets that accuracy in a scene ([solvers.<name>].<knob>); empty: none.
  std::string accuracy_knob;
  std::string reason;
};

/// The rules in order, and the solvers' accuracy declarations. Plain data with lookups; reading it
/// from TOML is io's job (catena/io/tolerance_reader.hpp), and a run receives it in
/// SceneRunOptions.
class ToleranceTable {
 public:
  ToleranceTable() = default;
  explicit ToleranceTable(std::vector<ToleranceRule> rules,
                          std::vector<SolverAccuracy> solvers = {})
      : rules_(std::move(rules)), solvers_(std::move(solvers)) {}

  /// The first rule for `check` comparing `a` with `b` in `scene` (with `tags`), or nullptr.
  const ToleranceRule* find(const std::string& check,
                            const std::string& a,
                            const std::string& b,
                            const std::string& scene,
                            const std::vector<std::string>& tags) const;
  /// The accuracy declaration of `solver`, or nullptr.
  const SolverAccuracy* solver(const std::string& name) const;

  const std::vector<ToleranceRule>& rules() const { return rules_; }
  const std::vector<SolverAccuracy>& solvers() const { return solvers_; }

 private:
  std::vector<ToleranceRule> rules_;
  std::vector<SolverAccuracy> solvers_;
};

}  // namespace catena
