// SPDX-License-Identifier: MIT
// The grounded run of a damped shot: see shooting_damped_grounded.hpp.
#include "solvers/shooting/shooting_damped_grounded.hpp"

#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>
#include <fmt/format.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>

#include "solvers/shooting/shooting_integrator.hpp"
#include "solvers/shooting/shooting_sundials_handles.hpp"

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

// What the C callback needs: the shot's data and the balancing of each direction.
struct RunData {
  RhsData* data = nullptr;
  double beta2[2] = {1.0, 1.0};
};

// State per direction j: [y0, y1, g] complex (header), interleaved real and imaginary parts.
constexpr int kPerDirection = 6;

int damped_grounded_rhs(double x, N_Vector y, N_Vector ydot, void* user_data) {
  const auto& run = *static_cast<const RunData*>(user_data);
  const RhsData& data = *run.data;
  Complex b[2], c[2];
  damped_grounded_coefficients(data, x * data.coefficients.length_m, b, c);
  const auto* state = reinterpret_cast<const Complex*>(N_VGetArrayPointer(y));
  auto* out = reinterpret_cast<Complex*>(N_VGetArrayPointer(ydot));
  for (int j = 0; j < data.dimension; ++j) {
    const Complex bt = run.beta2[j] * b[j], ct = c[j] / run.beta2[j];
    const Complex* z = state + 3 * j;
    const Complex a0 = bt * z[1], a1 = -ct * z[0];
    const Complex rayleigh = std::conj(z[0]) * a0 + std::conj(z[1]) * a1;
    out[3 * j] = a0 - rayleigh * z[0];
    out[3 * j + 1] = a1 - rayleigh * z[1];
    out[3 * j + 2] = rayleigh;
  }
  return 0;
}

// beta^2 = sqrt(|c| / |b|), which balances |b~| = |c~| (1 where either vanishes).
double balance_of(Complex b, Complex c) {
  return (std::abs(b) > 0.0 && std::abs(c) > 0.0) ? std::sqrt(std::abs(c) / std::abs(b)) : 1.0;
}

}  // namespace

struct DampedGroundedRun::Impl {
  Impl(RhsData& d, std::size_t pieces, long max_steps)
      : run_pieces(pieces),
        size(kPerDirection * d.dimension),
        y(size, context.get()),
        matrix(SUNDenseMatrix(size, size, context.get())),
        linear_solver(SUNLinSol_Dense(y.get(), matrix.get(), context.get())),
        cvode(CV_BDF, context.get()) {
    run.data = &d;
    if (!context.ok() || !y.ok() || !matrix.ok() || !linear_solver.ok() || !cvode.ok()) {
      throw ShootingFailure("could not allocate the SUNDIALS objects of the damped grounded run");
    }
    N_VConst(0.0, y.get());
    // The Jacobian by CVODE's difference quotients: y^H A y is not complex-analytic, and the
    // Jacobian is rebuilt rarely (a 12 x 12 costs 12 evaluations).
    check(CVodeInit(cvode.get(), damped_grounded_rhs, 0.0, y.get()), "CVodeInit");
    check(CVodeSetUserData(cvode.get(), &run), "CVodeSetUserData");
    check(CVodeSetLinearSolver(cvode.get(), linear_solver.get(), matrix.get()),
          "CVodeSetLinearSolver");
    check(CVodeSetMaxNumSteps(cvode.get(), max_steps), "CVodeSetMaxNumSteps");
  }

  void check(int flag, const char* call, double x = 0.0) const {
    if (flag < 0) {
      throw ShootingFailure(
          fmt::format("{} returned {} ({}) on the seabed (damped) at s/L = {:.6g}", call,
                      cvode_flag_name(flag), flag, x));
    }
  }
  const RhsData& data() const { return *run.data; }
  double piece_end_x() const {
    const ShootingCoefficients& k = data().coefficients;
    return k.pieces[data().piece].s_end / k.length_m;
  }
  void add_counts() {
    long n = 0, evaluations = 0;
    CVodeGetNumSteps(cvode.get(), &n);
    CVodeGetNumRhsEvals(cvode.get(), &evaluations);
    steps += n;
    rhs += evaluations;
  }
  void restart_at(double x) {
    check(CVodeReInit(cvode.get(), x, y.get()), "CVodeReInit", x);
    check(CVodeSetStopTime(cvode.get(), piece_end_x()), "CVodeSetStopTime", x);
  }
  void integrate_to(double x);
  DampedGroundedFrame frame() const;

  std::size_t run_pieces;
  sunindextype size;
  SundialsContext context;
  SerialVector y;
  SundialsMatrix matrix;
  SundialsLinearSolver linear_solver;
  CvodeMemory cvode;
  RunData run;
  double x_now = 0.0;
  long steps = 0;
  long rhs = 0;
};

// CVODE to x, stopping at every piece end (the friction profile, the section and the drag factor
// change there) and restarting on the next piece.
void DampedGroundedRun::Impl::integrate_to(double x) {
  while (x > x_now) {
    const double piece_end = piece_end_x();
    const double target = std::min(x, piece_end);
    double reached = x_now;
    check(CVode(cvode.get(), target, y.get(), &reached, CV_NORMAL), "CVode", x_now);
    x_now = target;
    if (target >= piece_end && run.data->piece + 1 < run_pieces) {
      add_counts();
      ++run.data->piece;
      restart_at(piece_end);
    }
  }
}

// The unit physical columns (the balancing undone) and their complex log scales.
DampedGroundedFrame DampedGroundedRun::Impl::frame() const {
  const int D = data().dimension;
  DampedGroundedFrame f;
  f.phi.resize(D);
  f.force.resize(D);
  f.log_scale.resize(D);
  const auto* state = reinterpret_cast<const Complex*>(y.data());
  for (int j = 0; j < D; ++j) {
    const double beta = std::sqrt(run.beta2[j]);
    const Complex phi = state[3 * j] / beta, force = beta * state[3 * j + 1];
    const double norm = std::sqrt(std::norm(phi) + std::norm(force));
    f.phi(j) = phi / norm;
    f.force(j) = force / norm;
    f.log_scale(j) = state[3 * j + 2] + std::log(norm);
  }
  return f;
}

DampedGroundedRun::DampedGroundedRun(RhsData& data, std::size_t pieces, long max_steps)
    : impl_(std::make_unique<Impl>(data, pieces, max_steps)) {}

DampedGroundedRun::~DampedGroundedRun() = default;

double DampedGroundedRun::end_x() const {
  const ShootingCoefficients& k = impl_->data().coefficients;
  return k.pieces[impl_->run_pieces - 1].s_end / k.length_m;
}

std::size_t DampedGroundedRun::pieces() const { return impl_->run_pieces; }

void DampedGroundedRun::begin(double relative_tolerance, double absolute_tolerance) {
  RhsData& data = *impl_->run.data;
  data.piece = 0;
  Complex b[2], c[2];
  damped_grounded_coefficients(data, 0.0, b, c);
  auto* state = reinterpret_cast<Complex*>(impl_->y.data());
  for (int j = 0; j < data.dimension; ++j) {
    impl_->run.beta2[j] = balance_of(b[j], c[j]);
    // phi = 0, F = 1: y = (0, 1) and g = ln(1 / beta) (z = (0, 1 / beta)).
    state[3 * j] = 0.0;
    state[3 * j + 1] = 1.0;
    state[3 * j + 2] = -0.5 * std::log(impl_->run.beta2[j]);
  }
  impl_->x_now = 0.0;
  impl_->steps = 0;
  impl_->rhs = 0;
  impl_->check(CVodeSStolerances(impl_->cvode.get(), relative_tolerance, absolute_tolerance),
               "CVodeSStolerances");
  impl_->restart_at(0.0);
}

DampedGroundedFrame DampedGroundedRun::advance_to(double x) {
  impl_->integrate_to(std::min(x, end_x()));
  return impl_->frame();
}

long DampedGroundedRun::steps() const {
  long n = 0;
  CVodeGetNumSteps(impl_->cvode.get(), &n);
  return impl_->steps + n;
}

long DampedGroundedRun::rhs_evaluations() const {
  long n = 0;
  CVodeGetNumRhsEvals(impl_->cvode.get(), &n);
  return impl_->rhs + n;
}

}  // namespace catena::internal
