// SPDX-License-Identifier: MIT
#pragma once
// The sections of the report, each built from the results JSON into the document model.

#include "io/report/document.hpp"
#include "io/report/report_data.hpp"

namespace catena::internal {

/// Title, provenance line and the count of each verdict.
void add_summary(Document& out, const json& document);
/// Per solver: scenes run, converged, failed, declined, times, largest error estimate.
void add_solvers(Document& out, const json& document);
/// Counts of each verdict by check kind and by solver pair.
void add_headline(Document& out, const json& document);
/// Published entries we believe wrong (a SOURCE verdict), one row per entry; returns the rows.
int add_discrepancies(Document& out, const json& document);
/// The mutation score by solver and scene family, and every uncaught mutation (nothing when the
/// run had no --mutation).
void add_mutation(Document& out, const json& document);
/// Actual error of the analytic models against the most accurate exact solver, by eps, with the
/// fitted order; also written to `data_dir`/model-error.csv.
void add_model_error(Document& out, const json& document, const std::filesystem::path& data_dir);
/// Scene errors and FAIL/WARN checks.
void add_failures(Document& out, const json& document);
/// Each solver's outcome on each stress scene (nothing when the run has none).
void add_stress_outcomes(Document& out, const json& document);
/// Fastest time to each accuracy target (nothing when there is no baseline).
void add_time_to_accuracy(Document& out, const TimeToAccuracy& timing);
/// Per scene: groups, every solver's frequencies beside the published ones, the damping of a
/// damped scene (add_damping_tables), forced maxima, the dynamic tension
/// (add_dynamic_tension_table).
void add_scenes(Document& out, const json& document);
/// True when the scene's problem has damping (a section's damping, a seabed dashpot) or a solver
/// returned a decaying mode.
bool is_damped_scene(const json& scene);
/// A damped scene's damping ratio zeta and decay rate delta per mode and solver, per plane, and its
/// overdamped roots; nothing for an undamped scene.
void add_damping_tables(Document& out, const json& scene);
/// A scene with a motion request: per excitation and solver, the dynamic tension at the fairlead
/// and the anchor, the fixed point's iterations and residual, and the dynamic-tension check's
/// agreement at the fairlead; nothing for a scene without one.
void add_dynamic_tension_table(Document& out, const json& scene);

}  // namespace catena::internal
