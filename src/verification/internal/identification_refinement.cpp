// SPDX-License-Identifier: MIT
#include "verification/internal/identification_refinement.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <unsupported/Eigen/NonLinearOptimization>

namespace catena::internal {

namespace {

// The variable-projection residual for Eigen's Levenberg-Marquardt: x = (delta_1, omega_1, ...),
// the basis Phi(x) = [1, exp(-delta_k t) cos(omega_k t), exp(-delta_k t) sin(omega_k t)], the
// amplitudes a_c = Phi^+ y_c eliminated, the residual w_c (I - P) y_c stacked over the channels.
struct Projection {
  const Vector& tau;
  const std::vector<Vector>& y;
  Vector weights;

  int values() const { return static_cast<int>(tau.size() * static_cast<Index>(y.size())); }

  Eigen::MatrixXd basis(const Vector& x) const {
    const Index poles = x.size() / 2;
    Eigen::MatrixXd phi(tau.size(), 1 + 2 * poles);
    phi.col(0).setOnes();
    for (Index k = 0; k < poles; ++k) {
      const Vector envelope = (-x[2 * k] * tau.array()).exp().matrix();
      phi.col(1 + 2 * k) = envelope.cwiseProduct((x[2 * k + 1] * tau.array()).cos().matrix());
      phi.col(2 + 2 * k) = envelope.cwiseProduct((x[2 * k + 1] * tau.array()).sin().matrix());
    }
    return phi;
  }

  int operator()(const Vector& x, Vector& residual) const {
    const Eigen::MatrixXd phi = basis(x);
    residual.resize(values());
    if (!phi.allFinite()) {  // a trial step that overflows: a residual LM will reject
      residual.setConstant(1e100);
      return 0;
    }
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(phi);
    const Index n = tau.size();
    for (std::size_t c = 0; c < y.size(); ++c) {
      residual.segment(static_cast<Index>(c) * n, n) =
          weights[static_cast<Index>(c)] * (y[c] - phi * qr.solve(y[c]));
    }
    return 0;
  }

  // Kaufman's Jacobian -(I - P) dPhi/dx_j a_c: for a model linear in a, it is also the exact
  // Jacobian of the reduced problem's Gauss-Newton information (the amplitudes marginalised).
  int df(const Vector& x, Eigen::MatrixXd& jacobian) const {
    const Eigen::MatrixXd phi = basis(x);
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(phi);
    const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(phi.rows(), phi.cols());
    const Index n = tau.size();
    jacobian.resize(values(), x.size());
    for (std::size_t c = 0; c < y.size(); ++c) {
      const Vector a = qr.solve(y[c]);
      for (Index k = 0; k < x.size() / 2; ++k) {
        const Vector cos_part = phi.col(1 + 2 * k), sin_part = phi.col(2 + 2 * k);
        const double ac = a[1 + 2 * k], as = a[2 + 2 * k];
        // d/d delta and d/d omega of ac e^{-dt} cos(wt) + as e^{-dt} sin(wt)
        Vector d_delta = -tau.cwiseProduct(ac * cos_part + as * sin_part);
        Vector d_omega = tau.cwiseProduct(as * cos_part - ac * sin_part);
        d_delta -= q * (q.transpose() * d_delta);
        d_omega -= q * (q.transpose() * d_omega);
        const double w = weights[static_cast<Index>(c)];
        jacobian.block(static_cast<Index>(c) * n, 2 * k, n, 1) = -w * d_delta;
        jacobian.block(static_cast<Index>(c) * n, 2 * k + 1, n, 1) = -w * d_omega;
      }
    }
    return 0;
  }
};

bool minimise(const Projection& projection, Vector& x) {
  Eigen::LevenbergMarquardt<Projection> lm(const_cast<Projection&>(projection));
  // Tolerances near rounding: the fit must reach the noise's accuracy, which for a noise-free
  // record is rounding; MINPACK's "tolerance too small" statuses mean no further progress.
  lm.parameters.ftol = 1e-15;
  lm.parameters.xtol = 1e-14;
  lm.parameters.maxfev = 400 * static_cast<int>(x.size() + 1);
  const auto status = lm.minimize(x);
  using Eigen::LevenbergMarquardtSpace::Status;
  return x.allFinite() && status != Status::ImproperInputParameters &&
         status != Status::TooManyFunctionEvaluation && status != Status::UserAsked;
}

}  // namespace

PoleFit refine_poles(const Vector& tau_s,
                     const std::vector<Vector>& channels,
                     const std::vector<std::complex<double>>& initial) {
  const auto num_channels = static_cast<Index>(channels.size());
  const Index n = tau_s.size();
  const auto poles = static_cast<Index>(initial.size());
  Vector x(2 * poles);
  for (Index k = 0; k < poles; ++k) {
    x[2 * k] = -initial[static_cast<std::size_t>(k)].real();
    x[2 * k + 1] = initial[static_cast<std::size_t>(k)].imag();
  }
  Projection projection{tau_s, channels, Vector::Ones(num_channels)};
  PoleFit fit;
  fit.converged = minimise(projection, x);
  Vector residual;
  projection(x, residual);
  const Index per_channel_parameters = 1 + 2 * poles;
  const double dof_per_channel =
      static_cast<double>(n - per_channel_parameters) -
      2.0 * static_cast<double>(poles) / static_cast<double>(num_channels);
  for (Index c = 0; c < num_channels; ++c) {
    fit.residual_variance.push_back(residual.segment(c * n, n).squaredNorm() / dof_per_channel);
  }
  if (num_channels > 1) {  // weights 1 / sigma_c: each channel counts by its own noise
    const double largest =
        *std::max_element(fit.residual_variance.begin(), fit.residual_variance.end());
    for (Index c = 0; c < num_channels; ++c) {
      const double variance = std::max(fit.residual_variance[static_cast<std::size_t>(c)],
                                       1e-30 * largest + std::numeric_limits<double>::min());
      projection.weights[c] = 1.0 / std::sqrt(variance);
    }
    fit.converged = minimise(projection, x) && fit.converged;
    projection(x, residual);
    for (Index c = 0; c < num_channels; ++c) {
      fit.residual_variance[static_cast<std::size_t>(c)] =
          residual.segment(c * n, n).squaredNorm() / dof_per_channel /
          (projection.weights[c] * projection.weights[c]);
    }
  }
  // Covariance sigma^2 (J^T J)^-1, sigma^2 the (weighted) residual variance over its degrees of
  // freedom: all samples less all parameters (poles and every channel's amplitudes).
  Eigen::MatrixXd jacobian;
  projection.df(x, jacobian);
  const double sigma2 =
      residual.squaredNorm() / (dof_per_channel * static_cast<double>(num_channels));
  const Eigen::MatrixXd information = jacobian.transpose() * jacobian;
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(information);
  const bool invertible = ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() > 0.0 &&
                          ldlt.vectorD().minCoeff() > 1e-14 * ldlt.vectorD().maxCoeff();
  const Eigen::MatrixXd covariance =
      invertible
          ? Eigen::MatrixXd(sigma2 * ldlt.solve(Eigen::MatrixXd::Identity(2 * poles, 2 * poles)))
          : Eigen::MatrixXd::Constant(2 * poles, 2 * poles,
                                      std::numeric_limits<double>::infinity());
  const Eigen::MatrixXd phi = projection.basis(x);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(phi);
  fit.amplitudes.resize(channels.size());
  for (Index k = 0; k < poles; ++k) {
    fit.poles_1_s.emplace_back(-x[2 * k], x[2 * k + 1]);
    fit.covariance.push_back(covariance.block<2, 2>(2 * k, 2 * k));
  }
  for (std::size_t c = 0; c < channels.size(); ++c) {
    const Vector a = qr.solve(channels[c]);
    for (Index k = 0; k < poles; ++k) fit.amplitudes[c].emplace_back(a[1 + 2 * k], -a[2 + 2 * k]);
  }
  return fit;
}

}  // namespace catena::internal
