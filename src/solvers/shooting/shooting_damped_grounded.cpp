// SPDX-License-Identifier: MIT
// The grounded run of a damped shot: see shooting_damped_grounded.hpp.
#include "solvers/shooting/shooting_damped_grounded.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "solvers/shooting/shooting_integrator.hpp"

namespace catena::internal {

using Complex = std::complex<double>;

void damped_grounded_coefficients(const RhsData& data, double s, Complex* b, Complex* c) {
  const ShootingCoefficients& k = data.coefficients;
  const ShootingPiece& p = k.pieces[data.piece];
  const Complex lambda = data.lambda;
  const PieceDamping damping = damping_at(data, p, s);
  const double scale = -k.length_m * k.length_m / k.t_ref;
  const double b_transverse = k.t_ref * (1.0 / p.tension(k.H, s) + p.compliance);
  const Complex normal_load = lambda * lambda * p.M + lambda * damping.normal;
  if (data.dimension == 1) {
    b[0] = b_transverse;
    c[0] = scale * (normal_load + p.foundation_tangential);
    return;
  }
  b[0] = k.t_ref * p.compliance / (1.0 + p.compliance * p.damping_axial * lambda);
  c[0] = scale * (lambda * lambda * p.m + lambda * damping.tangential + p.foundation_tangential);
  b[1] = b_transverse;
  c[1] = scale * (normal_load + p.foundation_normal + p.foundation_damping * lambda);
}

namespace {

// One normalised column (header): z = exp(g) y, |y| = 1.
struct Column {
  Complex y[2] = {0.0, 1.0};
  Complex g = 0.0;
};

// (1 - e^{-2 mu}) / (2 mu), by its series where the quotient cancels.
Complex sinh_factor(Complex mu) {
  if (std::abs(mu) > 1e-2) return (1.0 - std::exp(-2.0 * mu)) / (2.0 * mu);
  Complex term = 1.0, sum = 1.0;
  for (int k = 1; k <= 7; ++k) {
    term *= -2.0 * mu / static_cast<double>(k + 1);
    sum += term;
  }
  return sum;
}

// exp(Omega) applied to the column, Omega traceless 2 x 2 (Omega^2 = mu^2 I):
// exp(Omega) = e^mu [(1 + e^{-2mu})/2 I + (1 - e^{-2mu})/(2mu) Omega], Re mu >= 0, e^mu into g.
void apply_exponential(const Complex omega[2][2], Column& column) {
  Complex mu = std::sqrt(-(omega[0][0] * omega[1][1] - omega[0][1] * omega[1][0]));
  if (mu.real() < 0.0) mu = -mu;
  const Complex even = 0.5 * (1.0 + std::exp(-2.0 * mu)), odd = sinh_factor(mu);
  const Complex y0 = column.y[0], y1 = column.y[1];
  Complex w0 = even * y0 + odd * (omega[0][0] * y0 + omega[0][1] * y1);
  Complex w1 = even * y1 + odd * (omega[1][0] * y0 + omega[1][1] * y1);
  const double norm = std::sqrt(std::norm(w0) + std::norm(w1));
  column.y[0] = w0 / norm;
  column.y[1] = w1 / norm;
  column.g += mu + std::log(norm);
}

}  // namespace

// The run integrates by hand with Magnus' fourth-order exponential step (two Gauss points,
// Omega = h/2 (A1 + A2) - sqrt(3)/12 h^2 [A1, A2]) because no SUNDIALS integrator is exact for
// frozen coefficients: CVODE's BDF (the first version of this run) needs hundreds of steps per
// run at rtol 1e-10 whatever the coefficients do (its order is at most 5), 57 % of a
// dynamic-tension run; the exponential step is exact where A is constant and limited only by A's
// variation, however stiff the foundation (the growth goes into g). Steps stop at every piece end
// and every station of the drag profile (where c(s) has a kink); the step is controlled by step
// doubling.
struct DampedGroundedRun::Impl {
  Impl(RhsData& d, std::size_t pieces, long steps_allowed)
      : data(&d), run_pieces(pieces), max_steps(steps_allowed) {}

  double piece_end_x() const {
    const ShootingCoefficients& k = data->coefficients;
    return k.pieces[data->piece].s_end / k.length_m;
  }
  // The balanced A of every direction at x.
  void balanced(double x, Complex (*A)[2][2]) const {
    Complex b[2], c[2];
    damped_grounded_coefficients(*data, x * data->coefficients.length_m, b, c);
    for (int j = 0; j < data->dimension; ++j) {
      A[j][0][0] = 0.0;
      A[j][0][1] = beta2[j] * b[j];
      A[j][1][0] = -c[j] / beta2[j];
      A[j][1][1] = 0.0;
    }
  }
  // One Magnus step of length h from x for every column.
  void magnus(double x, double length, Column* out) {
    constexpr double kGauss = 0.28867513459481288225;  // sqrt(3) / 6
    Complex A1[2][2][2], A2[2][2][2];
    balanced(x + (0.5 - kGauss) * length, A1);
    balanced(x + (0.5 + kGauss) * length, A2);
    evaluations += 2;
    const double commutator_scale = -kGauss * 0.5 * length * length;  // -sqrt(3)/12 h^2
    for (int j = 0; j < data->dimension; ++j) {
      Complex omega[2][2];
      for (int r = 0; r < 2; ++r) {
        for (int c = 0; c < 2; ++c) {
          Complex commutator = 0.0;
          for (int m = 0; m < 2; ++m) {
            commutator += A1[j][r][m] * A2[j][m][c] - A2[j][r][m] * A1[j][m][c];
          }
          omega[r][c] = 0.5 * length * (A1[j][r][c] + A2[j][r][c]) + commutator_scale * commutator;
        }
      }
      apply_exponential(omega, out[j]);
    }
  }
  void integrate_interval(double end);
  void integrate_to(double x);
  double next_knot(double x) const;

  RhsData* data;
  std::size_t run_pieces;
  long max_steps;
  double beta2[2] = {1.0, 1.0};
  Column columns[2];
  double rtol = 1e-10;
  double x_now = 0.0;
  double h = 0.0;
  long steps = 0;
  long evaluations = 0;
};

// Step doubling: one step of h against two of h/2; the difference over 15 estimates the error of
// the halves (fourth order), which are kept.
void DampedGroundedRun::Impl::integrate_interval(double end) {
  const int D = data->dimension;
  while (x_now < end) {
    const double step = std::min(h > 0.0 ? h : end - x_now, end - x_now);
    Column coarse[2] = {columns[0], columns[1]}, fine[2] = {columns[0], columns[1]};
    magnus(x_now, step, coarse);
    magnus(x_now, 0.5 * step, fine);
    magnus(x_now + 0.5 * step, 0.5 * step, fine);
    double error = 0.0;
    for (int j = 0; j < D; ++j) {
      const Complex ratio = std::exp(coarse[j].g - fine[j].g);
      error = std::max(error, std::hypot(std::abs(ratio * coarse[j].y[0] - fine[j].y[0]),
                                         std::abs(ratio * coarse[j].y[1] - fine[j].y[1])));
    }
    error /= 15.0;
    if (!std::isfinite(error)) {
      throw ShootingFailure(fmt::format("the damped grounded run failed at s/L = {:.6g}", x_now));
    }
    const double factor = error > 0.0 ? 0.9 * std::pow(rtol / error, 0.2) : 4.0;
    if (++steps > max_steps) {
      throw ShootingFailure(
          fmt::format("more than {} steps (max_steps) in the damped grounded run at s/L = {:.6g}",
                      max_steps, x_now));
    }
    if (error <= rtol) {
      for (int j = 0; j < D; ++j) columns[j] = fine[j];
      x_now = step >= end - x_now ? end : x_now + step;
      h = step * std::min(factor, 4.0);
    } else {
      h = step * std::max(factor, 0.1);
    }
  }
}

// The next point where A may have a kink: the piece end or a station of the drag profile.
double DampedGroundedRun::Impl::next_knot(double x) const {
  double knot = piece_end_x();
  if (data->drag) {
    const double L = data->coefficients.length_m;
    for (double s : data->drag->stations()) {
      if (s / L > x) {
        knot = std::min(knot, s / L);
        break;
      }
    }
  }
  return knot;
}

void DampedGroundedRun::Impl::integrate_to(double x) {
  while (x > x_now) {
    const double piece_end = piece_end_x();
    const double target = std::min(x, next_knot(x_now));
    integrate_interval(target);
    if (target >= piece_end && data->piece + 1 < run_pieces) ++data->piece;
  }
}

DampedGroundedRun::DampedGroundedRun(RhsData& data, std::size_t pieces, long max_steps)
    : impl_(std::make_unique<Impl>(data, pieces, max_steps)) {}

DampedGroundedRun::~DampedGroundedRun() = default;

double DampedGroundedRun::end_x() const {
  const ShootingCoefficients& k = impl_->data->coefficients;
  return k.pieces[impl_->run_pieces - 1].s_end / k.length_m;
}

std::size_t DampedGroundedRun::pieces() const { return impl_->run_pieces; }

void DampedGroundedRun::begin(double relative_tolerance, double) {
  RhsData& data = *impl_->data;
  data.piece = 0;
  Complex b[2], c[2];
  damped_grounded_coefficients(data, 0.0, b, c);
  for (int j = 0; j < data.dimension; ++j) {
    const double modulus_b = std::abs(b[j]), modulus_c = std::abs(c[j]);
    impl_->beta2[j] = modulus_b > 0.0 && modulus_c > 0.0 ? std::sqrt(modulus_c / modulus_b) : 1.0;
    // phi = 0, F = 1: y = (0, 1) and g = ln(1 / beta) (z = (0, 1 / beta)).
    impl_->columns[j] = Column();
    impl_->columns[j].g = -0.5 * std::log(impl_->beta2[j]);
  }
  impl_->rtol = relative_tolerance;
  impl_->x_now = 0.0;
  impl_->h = 0.0;
  impl_->steps = 0;
  impl_->evaluations = 0;
}

DampedGroundedFrame DampedGroundedRun::advance_to(double x) {
  impl_->integrate_to(std::min(x, end_x()));
  const int D = impl_->data->dimension;
  DampedGroundedFrame f;
  f.phi.resize(D);
  f.force.resize(D);
  f.log_scale.resize(D);
  for (int j = 0; j < D; ++j) {
    const Column& column = impl_->columns[j];
    const double beta = std::sqrt(impl_->beta2[j]);
    const Complex phi = column.y[0] / beta, force = beta * column.y[1];
    const double norm = std::sqrt(std::norm(phi) + std::norm(force));
    f.phi(j) = phi / norm;
    f.force(j) = force / norm;
    f.log_scale(j) = column.g + std::log(norm);
  }
  return f;
}

long DampedGroundedRun::steps() const { return impl_->steps; }
long DampedGroundedRun::rhs_evaluations() const { return impl_->evaluations; }

}  // namespace catena::internal
