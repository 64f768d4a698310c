// SPDX-License-Identifier: MIT
// Conjugate-point counting from the end frame: see shooting_conjugate_count.hpp.
#include "solvers/shooting/shooting_conjugate_count.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <utility>

#include "catena/core/types.hpp"

namespace catena::internal {

namespace {

// Into [pi - delta, 3 pi - delta). An angle at pi to rounding is one that has not moved (the
// tangential angle of a nearly straight inextensible cable barely leaves pi, where every angle
// starts): it must count as not yet crossed. The shift delta moves the count threshold of a
// genuine crossing by 1e-12 rad, far inside the root brackets, which use the determinant.
double to_angle_range(double alpha) {
  constexpr double kDelta = 1e-12;
  while (alpha < kPi - kDelta) alpha += 2.0 * kPi;
  while (alpha >= 3.0 * kPi - kDelta) alpha -= 2.0 * kPi;
  return alpha;
}

// The beta in {0, pi/4, pi/2, 3 pi/4} that makes Q = sin(beta) Phi + cos(beta) F best conditioned.
double best_rotation(const FrameBlock<2>& Phi, const FrameBlock<2>& F) {
  double best_quality = -1.0, best_beta = 0.0;
  const double scale = Phi.squaredNorm() + F.squaredNorm();
  for (int k = 0; k < 4; ++k) {
    const double beta = 0.25 * kPi * k;
    const FrameBlock<2> Q = std::sin(beta) * Phi + std::cos(beta) * F;
    const double quality = std::abs(Q.determinant()) / scale;
    if (quality > best_quality) {
      best_quality = quality;
      best_beta = beta;
    }
  }
  return best_beta;
}

}  // namespace

double initial_phase(int dimension) { return dimension == 2 ? kPi : 0.5 * kPi; }

// The quadratic formula on U loses half the digits at a double eigenvalue (a double root of the
// cable), so the angles come from a real symmetric matrix instead: with e^{i beta} Z = P + i Q,
// U = e^{2 i beta} (V - i)(V + i)^{-1}, V = P Q^{-1} symmetric, and each eigenvalue nu of V gives
// alpha = 2 beta - 2 atan2(1, nu). beta is chosen to make Q best conditioned; the symmetric
// eigenproblem is then accurate to rounding.
template <int D>
Eigen::Matrix<double, D, 1> unitary_angles(const FrameBlock<D>& Phi, const FrameBlock<D>& F) {
  Eigen::Matrix<double, D, 1> angles;
  if constexpr (D == 1) {
    angles(0) = to_angle_range(-2.0 * std::atan2(F(0, 0), Phi(0, 0)));
  } else {
    const double beta = best_rotation(Phi, F);
    const FrameBlock<D> P = std::cos(beta) * Phi - std::sin(beta) * F;
    const FrameBlock<D> Q = std::sin(beta) * Phi + std::cos(beta) * F;
    FrameBlock<D> V = P * Q.inverse();
    V = 0.5 * (V + V.transpose()).eval();
    const Eigen::SelfAdjointEigenSolver<FrameBlock<D>> eig(V, Eigen::EigenvaluesOnly);
    for (int j = 0; j < D; ++j) {
      angles(j) = to_angle_range(2.0 * beta - 2.0 * std::atan2(1.0, eig.eigenvalues()(j)));
    }
    if (angles(0) > angles(1)) std::swap(angles(0), angles(1));
  }
  return angles;
}

template <int D>
double frame_phase(const FrameBlock<D>& Phi, const FrameBlock<D>& F) {
  using Complex = std::complex<double>;
  if constexpr (D == 1) {
    return std::arg(Complex(Phi(0, 0), F(0, 0)));
  } else {
    const Eigen::Matrix<Complex, 2, 2> Z =
        Phi.template cast<Complex>() + Complex(0.0, 1.0) * F.template cast<Complex>();
    return std::arg(Z.determinant());
  }
}

template <int D>
ConjugateCount count_conjugate_points(const FrameBlock<D>& Phi,
                                      const FrameBlock<D>& F,
                                      double theta_integrated) {
  ConjugateCount out;
  const FrameBlock<D> G = Phi.transpose() * Phi + F.transpose() * F;
  out.determinant = Phi.determinant() / std::sqrt(G.determinant());
  const double theta_mod = frame_phase<D>(Phi, F);
  const double winding = std::round((theta_integrated - theta_mod) / (2.0 * kPi));
  const double theta = theta_mod + 2.0 * kPi * winding;
  out.phase_defect = std::abs(theta_integrated - theta);
  const double total_alpha = 2.0 * kPi * D - 2.0 * theta;
  const Eigen::Matrix<double, D, 1> angles = unitary_angles<D>(Phi, F);
  const double count = (total_alpha - angles.sum()) / (2.0 * kPi);
  out.count = static_cast<int>(std::lround(count));
  out.angle_min = angles(0);
  out.angle_max = angles(D - 1);
  return out;
}

double count_function(int count, double angle_min, double angle_max, int n) {
  const double angle = count < n ? angle_max : angle_min;
  return (count - n) + (angle - kPi) / (2.0 * kPi);
}

template Eigen::Matrix<double, 1, 1> unitary_angles<1>(const FrameBlock<1>&, const FrameBlock<1>&);
template Eigen::Matrix<double, 2, 1> unitary_angles<2>(const FrameBlock<2>&, const FrameBlock<2>&);
template double frame_phase<1>(const FrameBlock<1>&, const FrameBlock<1>&);
template double frame_phase<2>(const FrameBlock<2>&, const FrameBlock<2>&);
template ConjugateCount count_conjugate_points<1>(const FrameBlock<1>&,
                                                  const FrameBlock<1>&,
                                                  double);
template ConjugateCount count_conjugate_points<2>(const FrameBlock<2>&,
                                                  const FrameBlock<2>&,
                                                  double);

}  // namespace catena::internal
