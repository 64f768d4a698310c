// SPDX-License-Identifier: MIT
// Mode matching and extrapolation of the fe solver: see fe_extrapolation.hpp and
// docs/explanation/methods/fe.md.
#include "solvers/fe/fe_extrapolation.hpp"

#include <algorithm>
#include <cmath>

#include "solvers/common/mode_tools.hpp"

namespace catena::internal {
namespace {

// The displacement of the free nodes of a chain of `elements` elements, restricted to the nodes
// of a chain of `coarse_elements` (a divisor): node i of the coarse chain is node i r of the fine.
Eigen::MatrixXd restrict_to_nodes(const Eigen::Ref<const Eigen::MatrixXd>& vectors,
                                  int elements,
                                  int coarse_elements,
                                  Plane plane) {
  const int per_node = plane == Plane::InPlane ? 2 : 1;
  const int ratio = elements / coarse_elements;
  Eigen::MatrixXd out(per_node * (coarse_elements - 1), vectors.cols());
  for (int i = 1; i < coarse_elements; ++i)
    out.middleRows(per_node * (i - 1), per_node) =
        vectors.middleRows(per_node * (i * ratio - 1), per_node);
  return out;
}

// The greedy assignment of match_modes on the MAC between the columns of a and b.
std::vector<int> assign_by_mac(const Eigen::Ref<const Eigen::MatrixXd>& a,
                               const Eigen::Ref<const Eigen::MatrixXd>& b) {
  const Eigen::MatrixXd cross = a.transpose() * b;
  const Vector na = a.colwise().squaredNorm().transpose(),
               nb = b.colwise().squaredNorm().transpose();
  const auto n = static_cast<int>(a.cols());
  std::vector<int> result(static_cast<std::size_t>(n), -1);
  std::vector<bool> used(static_cast<std::size_t>(b.cols()), false);
  for (int assigned = 0; assigned < n; ++assigned) {
    double best = -1.0;
    int bi = -1, bj = -1;
    for (int i = 0; i < n; ++i) {
      if (result[static_cast<std::size_t>(i)] >= 0) continue;
      for (int j = 0; j < b.cols(); ++j) {
        if (used[static_cast<std::size_t>(j)]) continue;
        const double norms = na[i] * nb[j];
        const double mac = norms > 0.0 ? cross(i, j) * cross(i, j) / norms : 0.0;
        if (mac > best) {
          best = mac;
          bi = i;
          bj = j;
        }
      }
    }
    result[static_cast<std::size_t>(bi)] = bj;
    used[static_cast<std::size_t>(bj)] = true;
  }
  return result;
}

}  // namespace

std::vector<int> match_modes(const Eigen::Ref<const Eigen::MatrixXd>& reference,
                             int reference_elements,
                             const Eigen::Ref<const Eigen::MatrixXd>& other,
                             int other_elements,
                             Plane plane) {
  const int common = std::min(reference_elements, other_elements);
  // A mesh whose nodes are all common is used as it is, not copied.
  if (reference_elements == common && other_elements == common)
    return assign_by_mac(reference, other);
  if (reference_elements == common)
    return assign_by_mac(reference, restrict_to_nodes(other, other_elements, common, plane));
  if (other_elements == common)
    return assign_by_mac(restrict_to_nodes(reference, reference_elements, common, plane), other);
  return assign_by_mac(restrict_to_nodes(reference, reference_elements, common, plane),
                       restrict_to_nodes(other, other_elements, common, plane));
}

// Pairing by shape, not by rank: near a cross-over the order of two close modes can differ
// between meshes (the discretisation error moves the crossing), and pairing by rank would then
// extrapolate one mode's frequency with the other's.
// The reference level matches itself mode for mode: it is not compared with itself (at N = 1e6
// that comparison copied and multiplied two n x k blocks for nothing). Column blocks are passed
// as references, not copied.
FeModeMatches match_level_modes(const FeLevels& levels,
                                const FePlan& plan,
                                Plane plane,
                                int available) {
  const FeLevel& reference = levels[static_cast<std::size_t>(plan.main_fine)][0];
  const auto reference_vectors = reference.eigen.at(plane).eigenvectors.leftCols(available);
  FeModeMatches matches(levels.size(), std::vector<std::vector<int>>(plan.penalties()));
  for (std::size_t m = 0; m < levels.size(); ++m) {
    for (std::size_t k = 0; k < plan.penalties(); ++k) {
      const FeLevel& level = levels[m][k];
      if (&level == &reference) {
        std::vector<int> identity(static_cast<std::size_t>(available));
        for (int i = 0; i < available; ++i) identity[static_cast<std::size_t>(i)] = i;
        matches[m][k] = identity;
        continue;
      }
      matches[m][k] = match_modes(reference_vectors, reference.chain.elements,
                                  level.eigen.at(plane).eigenvectors.leftCols(available),
                                  level.chain.elements, plane);
    }
  }
  return matches;
}

std::vector<std::vector<double>> level_omegas(const FeLevels& levels,
                                              const FeModeMatches& matches,
                                              Plane plane,
                                              int i) {
  std::vector<std::vector<double>> omega(levels.size());
  for (std::size_t m = 0; m < levels.size(); ++m) {
    for (std::size_t k = 0; k < levels[m].size(); ++k) {
      const int j = matches[m][k][static_cast<std::size_t>(i)];
      omega[m].push_back(std::sqrt(std::max(0.0, levels[m][k].eigen.at(plane).eigenvalues[j])));
    }
  }
  return omega;
}

double rounding_estimate(
    const FePlan& plan, const FeLevels& levels, const FeModeMatches& matches, Plane plane, int i) {
  double largest = 0.0;
  for (std::size_t m = 0; m < levels.size(); ++m) {
    for (std::size_t k = 0; k < levels[m].size(); ++k) {
      const Vector& rounding = levels[m][k].eigen.at(plane).rounding;
      const int j = matches[m][k][static_cast<std::size_t>(i)];
      if (j < rounding.size()) largest = std::max(largest, rounding[j]);
    }
  }
  const double mesh_gain = plan.richardson && plan.has_coarse() ? 5.0 / 3.0 : 1.0;
  const double kappa_gain = plan.inextensible ? 3.0 : 1.0;
  return 0.5 * largest * mesh_gain * kappa_gain;
}

namespace {

// Richardson value of a frequency on meshes N and 2N (order 2, mesh ratio 2).
double richardson(double coarse, double fine) { return fine + (fine - coarse) / 3.0; }

}  // namespace

// The error estimate of the Richardson value R(N, 2N) from the three meshes N/2, N, 2N, by the
// observed order p of the unextrapolated frequencies (docs/explanation/methods/fe.md, "Error
// behaviour and its estimate"), d = omega_2N - omega_N:
// - p within kOrderSlack of 2 (Richardson's regime): |R(N, 2N) - R(N/2, N)|, which bounds the
//   error of R(N, 2N) whenever the extrapolated values converge at least by a factor 2 per halving
//   (at order 4 by 16: the bound is then about 15x the error);
// - p above it: the Richardson correction |d| / 3, the fine mesh's own error, which R(N, 2N)
//   overshoots by less;
// - 0 < p below it (a term of lower order than Richardson assumes: a kink the mesh does not
//   follow, too few elements per wavelength): the fine mesh's error at the observed order,
//   |d| / (2^p - 1), plus the correction Richardson added, |d| / 3; this bounds R(N, 2N)'s error
//   when the frequencies converge at order p, and grows without bound as p -> 0;
// - differences that change sign (p not defined: a first-order term against the second, or
//   rounding): 4/3 (|omega_N/2 - omega_N| + |d|), which bounds R(N, 2N)'s error for any mix
//   a h + b h^2 (equality where omega_2N = omega_N).
FeMeshEstimate mesh_estimate(double half, double coarse, double fine) {
  constexpr double kOrderSlack = 0.25;
  const double order = observed_order(half, coarse, fine);
  const double d = std::abs(fine - coarse), d_half = std::abs(coarse - half);
  FeMeshEstimate out;
  out.observed_order = order;
  if (std::abs(order - 2.0) <= kOrderSlack) {
    out.error = std::abs(richardson(coarse, fine) - richardson(half, coarse));
  } else if (order > 2.0) {
    out.error = d / 3.0;
  } else if (order > 0.0) {
    out.error = d / std::expm1(order * std::log(2.0)) + d / 3.0;
    out.below_assumed_order = true;
  } else {
    out.error = 4.0 / 3.0 * (d_half + d);
    out.below_assumed_order = d_half + d > 0.0;
  }
  return out;
}

FeExtrapolatedFrequency extrapolate_frequency(const FePlan& plan,
                                              const std::vector<std::vector<double>>& omega) {
  const auto fine = static_cast<std::size_t>(plan.main_fine);
  const auto coarse = static_cast<std::size_t>(std::max(0, plan.main_coarse));
  std::vector<double> per_penalty, per_penalty_error;
  double observed = -1.0;
  bool below = false;
  for (std::size_t k = 0; k < plan.penalties(); ++k) {
    const double w_fine = omega[fine][k];
    double value = w_fine, estimate = -1.0;
    if (plan.has_coarse()) {
      const double correction = (w_fine - omega[coarse][k]) / 3.0;  // order 2, mesh ratio 2
      estimate = std::abs(correction);
      if (plan.richardson) value = w_fine + correction;
      if (plan.richardson && plan.has_estimate_mesh()) {
        const double w_half = omega[static_cast<std::size_t>(plan.estimate_coarse)][k];
        const FeMeshEstimate mesh = mesh_estimate(w_half, omega[coarse][k], w_fine);
        estimate = mesh.error;
        if (k == 0) {
          observed = mesh.observed_order;
          below = mesh.below_assumed_order;
        }
      }
    }
    per_penalty.push_back(value);
    per_penalty_error.push_back(estimate);
  }
  if (!plan.inextensible) return {per_penalty[0], per_penalty_error[0], observed, below};
  // Linear in kappa (Irvine's 1/lambda^2 is linear in the extensibility): 2 w(kappa) - w(2 kappa).
  const double linear = 2.0 * per_penalty[0] - per_penalty[1];
  const double kappa_error =
      per_penalty.size() > 2
          ? kappa_extrapolation_error(per_penalty[0], per_penalty[1], per_penalty[2])
          : std::abs(per_penalty[0] - per_penalty[1]);
  const double error = per_penalty_error[0] < 0.0 ? -1.0 : per_penalty_error[0] + kappa_error;
  return {linear, error, observed, below};
}

double kappa_extrapolation_error(double at_kappa, double at_2kappa, double at_4kappa) {
  return 2.0 * std::abs(2.0 * at_kappa - 3.0 * at_2kappa + at_4kappa) / 3.0;
}

double observed_order(double coarse, double middle, double fine) {
  const double d1 = coarse - middle;
  const double d2 = middle - fine;
  return d2 != 0.0 && d1 / d2 > 0.0 ? std::log2(d1 / d2) : 0.0;
}

void extrapolate_mode_in_kappa(Mode& a, const Mode& b) {
  auto stack = [](const Mode& mode) {
    Vector all(mode.u.size() + mode.w.size() + mode.v.size());
    all << mode.u, mode.w, mode.v;
    return all;
  };
  const Vector va = stack(a), vb = stack(b);
  const double denominator = vb.squaredNorm();
  if (denominator == 0.0) return;
  const double alpha = va.dot(vb) / denominator;
  auto combine = [alpha](Vector& x, const Vector& y) {
    if (x.size() && x.size() == y.size()) x = 2.0 * x - alpha * y;
  };
  combine(a.u, b.u);
  combine(a.w, b.w);
  combine(a.v, b.v);
  combine(a.tension_n, b.tension_n);
  if (a.v.size()) {
    normalise_outofplane_mode(a);
  } else {
    normalise_inplane_mode(a);
  }
}

}  // namespace catena::internal
