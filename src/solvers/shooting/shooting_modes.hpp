// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Mode construction of the `shooting` solver (docs/explanation/methods/shooting.md): the
/// frequencies found by the root finder become Modes, and on request their shapes and dynamic
/// tension, from the null vector of Phi(L) combined with the principal solutions recorded at the
/// request's stations. Roots closer than the integration resolves form one cluster: its null space
/// is spanned by the smallest singular vectors of Phi(L) together, and a double root gets a
/// mass-orthogonal pair.

#include <Eigen/Core>
#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "solvers/shooting/shooting_coefficients.hpp"
#include "solvers/shooting/shooting_integrator.hpp"
#include "solvers/shooting/shooting_profile.hpp"
#include "solvers/shooting/shooting_root_finder.hpp"

namespace catena::internal {

/// Groups ascending roots whose frequencies differ by at most `merge` relative to the larger
/// (consecutive neighbours).
std::vector<std::vector<Root>> cluster_roots(const std::vector<Root>& roots, double merge);

/// Builds the modes of one plane, cluster by cluster.
class ShootingModeBuilder {
 public:
  /// `plane`: the plane the modes belong to; `string_only`: an in-plane problem solved as the
  /// transverse string (straight inextensible cable), whose integrator is out of plane.
  /// `context`: the solve's problem (a general line's densities and points give its modal
  /// mass), statics, groups and request.
  ShootingModeBuilder(ShootingIntegrator& integrator,
                      const ShootingCoefficients& k,
                      const SolveContext& context,
                      Plane plane,
                      bool string_only);

  /// Appends the modes of one cluster to `modes`, numbered on from modes.size() + 1 and at most
  /// `num_modes` in all. Throws ShootingFailure when the shape shot fails.
  void add_cluster(const std::vector<Root>& cluster, int num_modes, std::vector<Mode>& modes);
  /// Marks the modes from `first` on that share one frequency as a proved multiple root.
  static void mark_equal_roots(std::vector<Mode>& modes, std::size_t first);

  /// Largest error estimate and residual over the modes added [-].
  double max_error() const { return max_error_; }
  double max_residual() const { return max_residual_; }

 private:
  std::vector<Eigen::VectorXd> null_vectors(const Shot& shot, int cluster_size) const;
  void mass_orthogonalise(const Shot& shot, std::vector<Eigen::VectorXd>& null_vectors) const;
  void set_shape(Mode& mode, const Shot& shot, const Eigen::VectorXd& null_vector) const;

  ShootingIntegrator& integrator_;
  const ShootingCoefficients& k_;
  const SolveContext& context_;
  const SolveRequest& request_;
  Plane plane_;
  Plane integration_plane_;
  bool string_only_;
  bool want_profile_;
  Vector stations_;
  std::vector<double> stations_x_;
  double max_error_ = 0.0;
  double max_residual_ = 0.0;
};

}  // namespace catena::internal
