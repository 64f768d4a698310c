// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// One cross-check and its verdict (docs/reference/verdicts.md).

#include <string>

namespace catena {

enum class Verdict {
  Pass,
  Fail,
  /// A published value disagrees with two (or more) of our solvers that agree with each other:
  /// a finding about the source, not a failure of ours.
  SourceDiscrepancy,
  /// Outside tolerance but explained (e.g. a model's known validity limit); does not fail a run.
  Warn,
  /// Could not be evaluated (e.g. a solver did not run); says why.
  Skipped
};

/// "PASS", "FAIL", "SOURCE", "WARN", "SKIP".
std::string to_string(Verdict verdict);

struct CheckResult {
  std::string scene;
  /// Kind of check: "statics-closure", "solver-status", "frequency", "published", "mac",
  /// "shape", "tension", "orthogonality", ...
  std::string check;
  /// What is compared: "fe vs shooting", "shooting vs Gale (1976) Table B-3", ...
  std::string compare;
  /// "in-plane", "out-of-plane", "forced", "" (whole scene); for a dynamic tension where on the
  /// line ("fairlead", "anchor", "stations", "motion") or "dynamic" (a solver's own fixed point).
  std::string plane;
  /// 1-based mode (or forcing index, or excitation index) the check is about; 0 for none.
  int mode = 0;
  /// The two values compared, when the check compares values (NaN otherwise).
  double value_a = 0.0;
  double value_b = 0.0;
  /// The measured error (relative difference, 1 - MAC, ...).
  double measured = 0.0;
  /// The tolerance it is held to.
  double tolerance = 0.0;
  Verdict verdict = Verdict::Skipped;
  /// Free text: units, what was compared, what went wrong.
  std::string detail;
  /// Why this tolerance: the reason of the tolerance rule that set it (or the scene's override);
  /// empty when the check has no rule. Kept apart from `detail` because thousands of checks share
  /// a handful of reasons (report.json lists each once, docs/reference/json-layout.md).
  std::string tolerance_reason;
};

}  // namespace catena
