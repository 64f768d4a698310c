// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Runs one scene: statics once (shared by every solver), then each applicable solver on the
/// resolved request, then the checks. Data flows one way: scene -> problem -> statics -> solvers
/// -> checks.

#include <optional>
#include <string>
#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/run_limits.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "catena/verification/check_result.hpp"
#include "catena/verification/findings.hpp"
#include "catena/verification/forced_conditioning.hpp"
#include "catena/verification/scene.hpp"
#include "catena/verification/tolerance_table.hpp"

namespace catena {

/// Why a scene could not be solved at all.
enum class SceneError {
  None,             ///< it was solved (its solvers may still have declined or failed: see outputs)
  BadInput,         ///< bad input found at run time (e.g. an unreachable chord): CLI exit 2
  NumericalFailure  ///< the shared statics did not converge: CLI exit 3, never "bad input"
};

struct SceneResult {
  Scene scene;
  /// Present when the statics solved.
  std::optional<StaticSolution> statics;
  std::optional<DimensionlessGroups> groups;
  /// The request in SI units.
  SolveRequest request;
  std::vector<SolverOutput> outputs;
  /// The natural frequencies behind the forced check's condition number (forced scenes, when
  /// checks are asked): from the most accurate exact solver that ran.
  ForcedConditioning forced_conditioning;
  std::vector<CheckResult> checks;
  /// Non-empty when the scene could not be solved at all; `error_kind` says whether the input was
  /// bad or the statics failed numerically.
  std::string error;
  SceneError error_kind = SceneError::None;
  double wall_time_s = 0.0;

  /// Number of checks with verdict Fail.
  int failed_checks() const;
};

/// A deliberate error injected into one solver's result after it ran: for testing that the
/// harness catches a wrong solver (`catena verify --perturb`). Never used in a real run.
struct Perturbation {
  std::string solver;
  Plane plane = Plane::InPlane;
  /// 1-based mode whose frequency is multiplied by (1 + relative).
  int mode = 1;
  double relative = 1e-3;
};

/// Options of a run.
struct SceneRunOptions {
  /// Test hook: perturb one frequency of one solver (see Perturbation).
  std::optional<Perturbation> perturbation;
  /// Run only these solvers (empty: the scene's choice).
  std::vector<std::string> only_solvers;
  /// Compute the checks (otherwise statics and solvers only).
  bool checks = true;
  /// Wall-clock budget of each scene [s], from the start of run_scene (none: no limit). When it
  /// runs out, the solvers stop cooperatively and keep what they have
  /// (catena/solvers/run_limits.hpp).
  std::optional<double> time_limit_s;
  /// Progress of the solvers (see ProgressCallback); empty: none.
  ProgressCallback progress;
  /// The expected agreement of each check. Required when `checks` is set (run_scene throws
  /// InvalidInput for an empty table, which would skip every check): pass
  /// builtin_tolerance_table() (catena/io/tolerance_reader.hpp, the compiled-in
  /// verification/tolerances.toml) or a table read by read_tolerance_file().
  ToleranceTable tolerances;
  /// Reviewed findings about published tables (may be empty: an unexplained disagreement with a
  /// published value then fails). Default of the CLI: builtin_findings_table().
  FindingsTable findings;

  /// Throws InvalidInput when checks are asked without a tolerance table, or for a time limit
  /// that is not finite and > 0.
  void validate() const;
};

/// Runs the scene. Never throws: numerical trouble of a solver is in its output's summary and in
/// the checks; bad input discovered at run time and a statics that does not converge are recorded
/// in SceneResult::error with their SceneError kind. Throws InvalidInput, before any work, only
/// when `options` asks for checks without a tolerance table.
SceneResult run_scene(const Scene& scene, const SceneRunOptions& options = {});

}  // namespace catena
