// SPDX-License-Identifier: MIT
// Modes, shapes and tension from the shooting solver's roots: see shooting_modes.hpp.
#include "solvers/shooting/shooting_modes.hpp"

#include <Eigen/Dense>
#include <algorithm>

#include "solvers/common/line_modal_mass.hpp"
#include "solvers/common/mode_tools.hpp"

namespace catena::internal {

std::vector<std::vector<Root>> cluster_roots(const std::vector<Root>& roots, double merge) {
  std::vector<std::vector<Root>> clusters;
  for (const Root& root : roots) {
    if (!clusters.empty() && root.omega - clusters.back().back().omega <= merge * root.omega) {
      clusters.back().push_back(root);
    } else {
      clusters.push_back({root});
    }
  }
  return clusters;
}

ShootingModeBuilder::ShootingModeBuilder(ShootingIntegrator& integrator,
                                         const ShootingCoefficients& k,
                                         const SolveContext& context,
                                         Plane plane,
                                         bool string_only)
    : integrator_(integrator),
      k_(k),
      context_(context),
      request_(context.request),
      plane_(plane),
      integration_plane_(string_only ? Plane::OutOfPlane : plane),
      string_only_(string_only),
      want_profile_(request_.shapes || request_.tension),
      stations_(request_.stations_m(k.length_m)),
      stations_x_(scaled_stations(stations_, k.length_m, false)) {}

void ShootingModeBuilder::add_cluster(const std::vector<Root>& cluster,
                                      int num_modes,
                                      std::vector<Mode>& modes) {
  int cluster_size = 0;
  double cluster_omega = 0.0;
  for (const Root& r : cluster) {
    cluster_size += r.multiplicity;
    cluster_omega += r.omega * r.multiplicity;
  }
  cluster_omega /= cluster_size;
  std::vector<Eigen::VectorXd> vectors;
  Shot shot;
  if (want_profile_) {
    shot = integrator_.shoot(cluster_omega, 1.0, &stations_x_);
    vectors = null_vectors(shot, cluster_size);
    if (vectors.size() == 2) mass_orthogonalise(shot, vectors);
  }
  std::size_t member = 0;
  const std::size_t first = modes.size();
  for (const Root& root : cluster) {
    for (int j = 0; j < root.multiplicity && static_cast<int>(modes.size()) < num_modes; ++j) {
      Mode mode;
      mode.index = static_cast<int>(modes.size()) + 1;
      set_mode_frequency(mode, root.omega, context_.groups);
      mode.relative_error_estimate = root.relative_error;
      mode.multiplicity = root.multiplicity;
      if (want_profile_ && member < vectors.size()) set_shape(mode, shot, vectors[member++]);
      max_error_ = std::max(max_error_, root.relative_error);
      max_residual_ = std::max(max_residual_, root.residual);
      modes.push_back(std::move(mode));
    }
  }
  mark_equal_roots(modes, first);
}

// Roots of a cluster found one by one that came out equal in double precision (two eigenvalues
// closer than rounding, e.g. the two arcs of a symmetric U whose stiff grounded middle decouples
// them: the splitting falls like exp(-2 L_g sqrt(k / T))) are one multiple root: the count rose by
// one across each root's bracket, so it rose by their number across the union of these brackets,
// all around one double. Marked as proved multiple (Mode::multiplicity), like a bracket whose
// count rose by two.
void ShootingModeBuilder::mark_equal_roots(std::vector<Mode>& modes, std::size_t first) {
  for (std::size_t i = first; i < modes.size();) {
    std::size_t end = i + 1;
    while (end < modes.size() && modes[end].omega_rad_s == modes[i].omega_rad_s) ++end;
    const int equal = static_cast<int>(end - i);
    if (equal > 1)
      for (std::size_t j = i; j < end; ++j)
        modes[j].multiplicity = std::max(modes[j].multiplicity, equal);
    i = end;
  }
}

// The right singular vectors of Phi(L) for its `cluster_size` smallest singular values.
std::vector<Eigen::VectorXd> ShootingModeBuilder::null_vectors(const Shot& shot,
                                                               int cluster_size) const {
  const int D = integration_plane_ == Plane::InPlane ? 2 : 1;
  const Eigen::MatrixXd phi_end = shot.y_end.topRows(D);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(phi_end, Eigen::ComputeFullV);
  std::vector<Eigen::VectorXd> vectors;
  for (int j = 0; j < cluster_size && j < D; ++j) vectors.push_back(svd.matrixV().col(D - 1 - j));
  return vectors;
}

// A double root has a two-dimensional null space: return a mass-orthogonal pair (Gram-Schmidt in
// int (m u u' + M w w') ds on the stations).
void ShootingModeBuilder::mass_orthogonalise(const Shot& shot,
                                             std::vector<Eigen::VectorXd>& vectors) const {
  const Profile p1 = evaluate_profile(shot, vectors[0], k_, stations_, false, integration_plane_);
  const Profile p2 = evaluate_profile(shot, vectors[1], k_, stations_, false, integration_plane_);
  auto mass_product = [&](const Profile& a, const Profile& b) {
    const Vector density = k_.m * a.u.cwiseProduct(b.u) + k_.M * a.w.cwiseProduct(b.w);
    return integrate_on_stations(stations_, density);
  };
  const double m11 = mass_product(p1, p1);
  if (m11 > 0.0) vectors[1] -= (mass_product(p1, p2) / m11) * vectors[0];
}

// Shape, tension (on request), normalisation and modal mass of one mode; only the frequency
// part is kept when the shapes were not asked (the tension alone needs the shape to normalise).
void ShootingModeBuilder::set_shape(Mode& mode,
                                    const Shot& shot,
                                    const Eigen::VectorXd& null_vector) const {
  Profile p = evaluate_profile(shot, null_vector, k_, stations_, false, integration_plane_);
  if (string_only_) p = string_as_inplane(p);
  mode.s_m = stations_;
  if (plane_ == Plane::InPlane) {
    mode.u = p.u;
    mode.w = p.w;
    if (request_.tension) mode.tension_n = p.tension;
    normalise_inplane_mode(mode);
    mode.modal_mass_kg = inplane_modal_mass(mode, k_.m, k_.M);
  } else {
    mode.v = p.v;
    normalise_outofplane_mode(mode);
    mode.modal_mass_kg = outofplane_modal_mass(mode, k_.M);
    if (request_.tension) {
      // Out-of-plane motion carries no first-order dynamic tension.
      mode.tension_n = Vector::Zero(stations_.size());
      mode.max_abs_tension_n = 0.0;
    }
  }
  // A general line: each segment's densities and each point's mass at its own arc length.
  if (!context_.problem.is_uniform())
    mode.modal_mass_kg = line_modal_mass(plane_, mode, context_.problem.line, context_.statics);
  if (!request_.shapes) drop_shape_fields(mode);
}

}  // namespace catena::internal
