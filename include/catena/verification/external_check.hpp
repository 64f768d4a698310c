// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Checking another program's natural frequencies, and optionally its mode shapes and dynamic
/// tensions, against Catena's certified reference (docs/how-to/check.md). Pure data in, comparison
/// out: reading the other program's files is include/catena/io/external_results_reader.hpp,
/// choosing the reference is include/catena/verification/certified_reference.hpp, the report is
/// include/catena/io/check_report.hpp.
///
/// What is compared, per mode of the other program:
/// - its frequency at each resolution it gives, against the paired Catena mode: the relative
///   error (other - Catena) / Catena;
/// - with shapes: the modal assurance criterion (MAC) against Catena's shape interpolated at the
///   other program's stations; with tensions: the largest tension difference after scaling the
///   other mode to Catena's normalisation;
/// - with three or more resolutions: a convergence study (observed order, Richardson-extrapolated
///   limit, the bias of that limit against Catena) and a verdict that tells a code converging to
///   the right answer from one converging, cleanly, to a wrong one.

#include <optional>
#include <string>
#include <vector>

#include "catena/core/types.hpp"

namespace catena {

/// A mode shape of the other program at its own stations. Components not given are empty.
struct ExternalShape {
  /// Unstretched arc length from end A [m], ascending, within [0, L].
  Vector s_m;
  /// In-plane tangential and normal displacement; out-of-plane displacement (any scale).
  Vector u;
  Vector w;
  Vector v;
  /// Dynamic tension amplitude [N] for the same scale as the displacements.
  Vector tension_n;
};

/// One mode of the other program at one resolution.
struct ExternalMode {
  Plane plane = Plane::InPlane;
  /// The other program's mode number within its plane (1-based).
  int mode = 1;
  /// The other program's mesh count (e.g. number of segments; larger = finer). The element size
  /// is taken proportional to 1 / resolution. Absent: a single result without a mesh.
  std::optional<double> resolution;
  double omega_rad_s = 0.0;
  std::optional<ExternalShape> shape;
  /// Where it came from, for messages (e.g. "results.csv row 4").
  std::string origin;
};

/// One mode of Catena's reference, with its shape on Catena's stations when shapes were asked.
struct ReferenceMode {
  int index = 1;
  double omega_rad_s = 0.0;
  /// The solver's own estimate of the relative error of omega.
  double relative_error_estimate = -1.0;
  Vector s_m;
  Vector u;
  Vector w;
  Vector v;
  Vector tension_n;
};

/// Catena's reference for one plane: which solver, why, and its modes.
struct CertifiedReference {
  Plane plane = Plane::InPlane;
  /// "shooting" or "fe".
  std::string solver;
  /// Why this solver (e.g. "shooting converged with the smaller estimate 1e-10; fe 3e-9").
  std::string reason;
  /// Largest relative difference between shooting and fe over the reference modes (-1 when only
  /// one of them converged): an independent confirmation of the reference.
  double cross_check_relative = -1.0;
  std::vector<ReferenceMode> modes;
};

/// Settings of the comparison (docs/how-to/check.md, "Verdicts").
struct ExternalCheckOptions {
  /// Relative tolerance on frequencies. > 0.
  double rtol = 1e-3;
  /// With four or more resolutions the order from the finest three and from the three before
  /// them must agree to this relative difference for the extrapolation to be trusted.
  double order_stability = 0.1;
  /// Throws InvalidInput naming the field.
  void validate() const;
};

/// The convergence study of one mode (three or more resolutions).
struct ConvergenceStudy {
  /// True when the extrapolation is trustworthy (docs/how-to/check.md): monotone convergence, an
  /// observed order in [0.5, 10], stable across triples when four or more resolutions are given;
  /// or differences already at rounding level.
  bool trustworthy = false;
  /// Why the study is not trustworthy, or what it rests on.
  std::string note;
  /// Observed order from the finest three resolutions (absent when the differences are at rounding
  /// level or the sequence is not monotone).
  std::optional<double> observed_order;
  /// The order from the three resolutions before the finest (four or more resolutions).
  std::optional<double> coarser_order;
  /// Richardson-extrapolated limit [rad/s] (the finest value when the differences are at rounding
  /// level).
  std::optional<double> limit_omega_rad_s;
  /// Uncertainty of the limit [rad/s]: the difference of the limits of the two finest triples
  /// (four or more resolutions), else |limit - finest value|.
  std::optional<double> limit_uncertainty_rad_s;
  /// (limit - Catena) / Catena.
  std::optional<double> bias_relative;
};

/// The verdict on one mode (docs/how-to/check.md, "Verdicts").
enum class ModeVerdict {
  WithinTolerance,        ///< one resolution (or an inconclusive study): |error| <= rtol
  BeyondTolerance,        ///< one resolution (or an inconclusive study): |error| > rtol
  Converged,              ///< trustworthy study, right limit, finest |error| <= rtol
  NotYetWithinTolerance,  ///< trustworthy study, right limit, finest |error| > rtol
  ConvergesToWrongLimit,  ///< trustworthy study, |bias| - uncertainty > rtol
  Unpaired                ///< no Catena mode left to pair with
};
/// "within tolerance", "beyond tolerance", "converged", "converges, not yet within tolerance",
/// "converges to a wrong limit", "unpaired".
std::string to_string(ModeVerdict verdict);
/// True for the verdicts that fail the check (exit 1).
bool is_failure(ModeVerdict verdict);

/// One resolution of one mode.
struct ResolutionComparison {
  std::optional<double> resolution;
  double omega_rad_s = 0.0;
  /// (other - Catena) / Catena.
  double relative_error = 0.0;
  /// MAC against Catena's shape, when a shape was given.
  std::optional<double> mac;
  /// max |alpha tau_other - tau_Catena| / max |tau_Catena|, alpha scaling the other mode to
  /// Catena's (least squares on the displacements), when tensions were given.
  std::optional<double> tension_relative;
};

/// One mode of the other program, compared.
struct ModeComparison {
  Plane plane = Plane::InPlane;
  /// The other program's number.
  int mode = 1;
  /// Catena's mode it was paired with (0 when unpaired).
  int reference_index = 0;
  double reference_omega_rad_s = 0.0;
  double reference_relative_estimate = -1.0;
  /// How it was paired ("frequency" or "MAC 0.998"), and a note when the numbers differ.
  std::string pairing;
  /// Coarsest first; the last is the finest (or the only one).
  std::vector<ResolutionComparison> resolutions;
  std::optional<ConvergenceStudy> study;
  ModeVerdict verdict = ModeVerdict::Unpaired;
};

/// The whole comparison.
struct ExternalCheck {
  ExternalCheckOptions options;
  std::vector<CertifiedReference> references;
  /// In-plane first, then by the other program's mode number.
  std::vector<ModeComparison> modes;
  /// True when any mode's verdict is a failure.
  bool any_failure() const;
};

/// Checks `results` on their own, before any reference is computed: modes >= 1, frequencies and
/// resolutions finite and > 0, no two results with the same plane, mode and resolution, no mode
/// mixing results with and without a resolution. Throws InvalidInput naming the result's origin.
void validate_external_results(const std::vector<ExternalMode>& results);

/// Compares `results` with the references (one per plane that `results` uses). Throws
/// InvalidInput when a plane has no reference, two results share plane, mode and resolution,
/// a mode mixes results with and without a resolution, or a shape is malformed (stations outside
/// [0, L], lengths that differ, components the plane does not have), naming the result's origin.
ExternalCheck check_external_results(const std::vector<ExternalMode>& results,
                                     const std::vector<CertifiedReference>& references,
                                     const ExternalCheckOptions& options = {});

/// The convergence study of values at resolutions (ascending resolution), as used by
/// check_external_results; exposed for tests and other callers. `reference` is Catena's value.
ConvergenceStudy study_convergence(const std::vector<double>& resolutions,
                                   const std::vector<double>& values,
                                   double reference,
                                   const ExternalCheckOptions& options = {});

}  // namespace catena
