// SPDX-License-Identifier: MIT
// The fe solver's damped forced response with a linearised drag profile: see fe_drag_forced.hpp
// and docs/explanation/methods/fe.md, "Dynamic tension (linearised drag)".
#include "solvers/fe/fe_drag_forced.hpp"

#include <algorithm>
#include <complex>
#include <optional>
#include <utility>

namespace catena::internal {

FeChain chain_with_drag(const FeChain& chain, const DragProfile& drag, bool drag_only) {
  FeChain out = chain;
  if (drag_only) {
    out.tangential_damping_n_s_per_m2.setZero();
    out.normal_damping_n_s_per_m2.setZero();
    out.axial_damping_n_s.setZero();
    out.foundation_damping_n_s_per_m2 = 0.0;
  }
  if (!drag.has_drag()) return out;
  for (int j = 0; j < chain.elements; ++j) {
    const double s0 = chain.node_s_m[j], s1 = chain.node_s_m[j + 1];
    const std::size_t segment = drag.segment_of(0.5 * (s0 + s1));
    out.normal_damping_n_s_per_m2[j] += drag.normal_mean(s0, s1, segment);
    out.tangential_damping_n_s_per_m2[j] += drag.tangential_mean(s0, s1, segment);
  }
  return out;
}

namespace {

// phi^H C phi / (2 phi^H M phi): the first-order decay rate of a mode of vector phi under C.
template <class Vec>
double rayleigh_decay(const Vec& phi, const SparseMatrix& C, const SparseMatrix& M) {
  using Scalar = typename Vec::Scalar;
  const double mass = std::real(phi.dot(M.cast<Scalar>() * phi));
  const double damping = std::real(phi.dot(C.cast<Scalar>() * phi));
  return mass > 0.0 ? 0.5 * damping / mass : 0.0;
}

}  // namespace

std::vector<FeNaturalFrequency> naturals_with_drag(
    Plane plane,
    const FeLevel& level,
    const DragProfile& drag,
    const std::vector<FeNaturalFrequency>& naturals) {
  std::vector<FeNaturalFrequency> out = naturals;
  if (!drag.has_drag() || !level.matrices.count(plane)) return out;
  const SparseMatrix C = assemble_damping(plane, chain_with_drag(level.chain, drag, true)).damping;
  const SparseMatrix& M = level.matrices.at(plane).mass;
  const auto eigen = level.eigen.find(plane);
  const auto damped = level.damped.find(plane);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto column = static_cast<Eigen::Index>(i);
    double share = 0.0;
    if (damped != level.damped.end() && column < damped->second.vectors.cols()) {
      share = rayleigh_decay(Eigen::VectorXcd(damped->second.vectors.col(column)), C, M);
    } else if (eigen != level.eigen.end() && column < eigen->second.eigenvectors.cols()) {
      share = rayleigh_decay(Vector(eigen->second.eigenvectors.col(column)), C, M);
    } else {
      continue;
    }
    FeNaturalFrequency& mode = out[i];
    // The damped frequency from the undamped modulus |lambda|^2 = omega_d^2 + delta^2.
    const double modulus2 =
        mode.omega_rad_s * mode.omega_rad_s + mode.decay_rate_1_s * mode.decay_rate_1_s;
    mode.decay_rate_1_s += share;
    mode.omega_rad_s =
        std::sqrt(std::max(modulus2 - mode.decay_rate_1_s * mode.decay_rate_1_s, 0.0));
    // The share comes from the level's vectors, whose discretisation error is that of the mode.
    mode.decay_rate_error_estimate =
        std::max(mode.decay_rate_error_estimate, mode.relative_error_estimate);
  }
  return out;
}

namespace {

// The levels' own damping matrices of one plane, put back when the drag solve ends (also when it
// throws), so that the section-damped modes and forced() keep theirs.
class DampingSwap {
 public:
  DampingSwap(Plane plane, std::vector<FeLevel*> levels)
      : plane_(plane), levels_(std::move(levels)) {
    for (FeLevel* level : levels_) {
      const auto own = level->damping.find(plane_);
      saved_.push_back(own == level->damping.end()
                           ? std::nullopt
                           : std::optional<FeDampingMatrix>(std::move(own->second)));
    }
  }
  ~DampingSwap() {
    for (std::size_t k = 0; k < levels_.size(); ++k) {
      if (saved_[k]) {
        levels_[k]->damping[plane_] = std::move(*saved_[k]);
      } else {
        levels_[k]->damping.erase(plane_);
      }
    }
  }
  DampingSwap(const DampingSwap&) = delete;
  DampingSwap& operator=(const DampingSwap&) = delete;

 private:
  Plane plane_;
  std::vector<FeLevel*> levels_;
  std::vector<std::optional<FeDampingMatrix>> saved_;
};

}  // namespace

ForcedOutcome fe_drag_forced_response(const ForcedRequest& request,
                                      const DragProfile& drag,
                                      const SolveContext& context,
                                      const FePlan& plan,
                                      FeLevels& levels,
                                      const std::vector<FeNaturalFrequency>& naturals,
                                      FeTimings& timings) {
  const Plane plane = forced_plane(request);
  std::vector<std::size_t> meshes = {static_cast<std::size_t>(plan.main_fine)};
  if (plan.has_coarse()) meshes.push_back(static_cast<std::size_t>(plan.main_coarse));
  assemble_missing(levels, plane, meshes);
  std::vector<FeLevel*> forced_levels;
  for (std::size_t m : meshes)
    for (FeLevel& level : levels[m]) forced_levels.push_back(&level);
  const DampingSwap swap(plane, forced_levels);
  for (FeLevel* level : forced_levels)
    level->damping[plane] = assemble_damping(plane, chain_with_drag(level->chain, drag, false));
  const std::vector<FeNaturalFrequency> damped_naturals =
      naturals_with_drag(plane, levels[meshes.front()].front(), drag, naturals);
  return fe_damped_forced_response(request, context, plan, levels, damped_naturals, timings);
}

}  // namespace catena::internal
