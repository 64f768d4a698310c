// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// One iterate of the drag linearisation (docs/explanation/dynamic-tension.md, "Linearised drag"):
/// the Morison drag of every section replaced by linear damping proportional to a velocity scale
/// V(s) of the response,
///
///     c_n(s) = a 1/2 rho Cd d V_n(s),   c_t(s) = a 1/2 rho CdAx (pi d) V_t(s),
///
/// with a = 8 / (3 pi) and V the velocity amplitude (harmonic linearisation, regular motion), or
/// a = sqrt(8 / pi) and V the velocity standard deviation (stochastic linearisation, irregular
/// motion). V_n, V_t are given at the request's stations and interpolated linearly between them;
/// the coefficients jump where the section does. The solvers add c_n, c_t to the sections' own
/// linear damping (SectionDamping); point attachments carry no drag.

#include <cstddef>
#include <vector>

#include "catena/core/types.hpp"
#include "catena/models/cable.hpp"

namespace catena::internal {

/// Which linearisation the profile's velocity scales belong to.
enum class DragLinearisation { Harmonic, Stochastic };

class DragProfile {
 public:
  /// Drag of `problem`'s sections at `stations` (ascending, from 0 to L) with zero velocity scales.
  DragProfile(const Problem& problem, Vector stations, DragLinearisation linearisation);

  /// Sets the velocity scales V_n, V_t [m/s] at the stations (same size as the stations, >= 0).
  void set_velocity_scales(const Vector& normal, const Vector& tangential);

  /// The segment (index into Problem::as_line().segments) that contains s; on a boundary, the one
  /// that begins there. Elements and pieces ask with an interior point (their midpoint).
  std::size_t segment_of(double s) const;
  /// c_n(s), c_t(s) on `segment` [N s/m per m].
  double normal_at(double s, std::size_t segment) const;
  double tangential_at(double s, std::size_t segment) const;
  /// The means of c_n and c_t over [s0, s1] within `segment`, exact for the piecewise linear V
  /// (an element's damping per unit length).
  double normal_mean(double s0, double s1, std::size_t segment) const;
  double tangential_mean(double s0, double s1, std::size_t segment) const;
  /// c_n and c_t at the stations (on a boundary station, the segment that begins there).
  Vector normal_at_stations() const;
  Vector tangential_at_stations() const;

  const Vector& stations() const { return stations_; }
  /// True when every section has zero drag (the profile adds nothing).
  bool has_drag() const;

  /// True for the driver's last call, at the final iterate, whose responses and error estimates
  /// are reported; false inside the iteration, where a solver may skip work that only the error
  /// estimate needs (relative_error_estimate -1 there: the driver never reports it).
  bool is_final() const { return final_; }
  void set_final(bool final) { final_ = final; }

 private:
  double mean_of(const Vector& values, double s0, double s1) const;
  double value_of(const Vector& values, double s) const;

  Vector stations_;
  std::vector<double> segment_start_;  // ascending, segment_start_[0] = 0
  std::vector<double> normal_factor_;  // a 1/2 rho Cd d per segment [kg/m^2]
  std::vector<double> tangential_factor_;
  Vector normal_scale_;
  Vector tangential_scale_;
  bool final_ = false;
};

}  // namespace catena::internal
