// SPDX-License-Identifier: MIT
// The grounded run of a shot: see shooting_grounded.hpp.
#include "solvers/shooting/shooting_grounded.hpp"

#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>
#include <fmt/format.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>

#include "catena/core/types.hpp"
#include "solvers/shooting/shooting_integrator.hpp"
#include "solvers/shooting/shooting_sundials_handles.hpp"

namespace catena::internal {

void grounded_coefficients(const ShootingCoefficients& k,
                           const ShootingPiece& p,
                           int dimension,
                           double omega2,
                           double s,
                           double* b,
                           double* c) {
  const double foundation_scale = k.length_m * k.length_m / k.t_ref;
  const double b_transverse = k.t_ref * (1.0 / p.tension(k.H, s) + p.compliance);
  const double c_transverse = omega2 * p.M / k.M;
  if (dimension == 1) {
    b[0] = b_transverse;
    c[0] = c_transverse - foundation_scale * p.foundation_tangential;
    return;
  }
  b[0] = k.t_ref * p.compliance;
  c[0] = omega2 * p.m / k.M - foundation_scale * p.foundation_tangential;
  b[1] = b_transverse;
  c[1] = c_transverse - foundation_scale * p.foundation_normal;
}

std::size_t grounded_run_length(const ShootingCoefficients& k, int dimension) {
  std::size_t run = 0;
  while (run < k.pieces.size() && k.pieces[run].grounded) ++run;
  if (run == 0) return 0;
  const double s_end = k.pieces[run - 1].s_end;
  for (const ShootingPoint& point : k.points) {
    if (point.s <= s_end + 1e-10 * k.length_m) return 0;
  }
  for (std::size_t j = 0; j < run; ++j) {
    if (dimension == 2 && !(k.pieces[j].compliance > 0.0)) return 0;
  }
  return run;
}

namespace {

// What the C callbacks need: the coefficients, the piece being integrated and the balancing.
struct GroundedData {
  ShootingCoefficients coefficients;
  int dimension = 2;
  double omega2 = 0.0;
  std::size_t piece = 0;
  double beta2[2] = {1.0, 1.0};
};

// The balanced b~, c~ of every direction at x.
void balanced_coefficients(const GroundedData& d, double x, double* b, double* c) {
  const ShootingCoefficients& k = d.coefficients;
  grounded_coefficients(k, k.pieces[d.piece], d.dimension, d.omega2, x * k.length_m, b, c);
  for (int j = 0; j < d.dimension; ++j) {
    b[j] *= d.beta2[j];
    c[j] /= d.beta2[j];
  }
}

// State [psi_0, ln rho_0, psi_1, ln rho_1]: the balanced Pruefer pairs of the header.
int grounded_rhs(double x, N_Vector y, N_Vector ydot, void* user_data) {
  const auto& d = *static_cast<const GroundedData*>(user_data);
  double b[2], c[2];
  balanced_coefficients(d, x, b, c);
  const double* state = N_VGetArrayPointer(y);
  double* out = N_VGetArrayPointer(ydot);
  for (int j = 0; j < d.dimension; ++j) {
    const double cs = std::cos(state[2 * j]), sn = std::sin(state[2 * j]);
    out[2 * j] = -c[j] * cs * cs - b[j] * sn * sn;
    out[2 * j + 1] = (b[j] - c[j]) * sn * cs;
  }
  return 0;
}

int grounded_jacobian(
    double x, N_Vector y, N_Vector, SUNMatrix J, void* user_data, N_Vector, N_Vector, N_Vector) {
  const auto& d = *static_cast<const GroundedData*>(user_data);
  double b[2], c[2];
  balanced_coefficients(d, x, b, c);
  const double* state = N_VGetArrayPointer(y);
  SUNMatZero(J);
  for (int j = 0; j < d.dimension; ++j) {
    const double twice = 2.0 * state[2 * j];
    SM_ELEMENT_D(J, 2 * j, 2 * j) = (c[j] - b[j]) * std::sin(twice);
    SM_ELEMENT_D(J, 2 * j + 1, 2 * j) = (b[j] - c[j]) * std::cos(twice);
  }
  return 0;
}

// beta^2 = sqrt(|c| / b), which balances b~ = |c~| (1 where either vanishes).
double balance_of(double b, double c) {
  return (b > 0.0 && c != 0.0) ? std::sqrt(std::abs(c) / b) : 1.0;
}

}  // namespace

struct GroundedRun::Impl {
  Impl(const ShootingCoefficients& k, int dimension, std::size_t pieces, long max_steps)
      : run_pieces(pieces),
        y(2 * dimension, context.get()),
        matrix(SUNDenseMatrix(2 * dimension, 2 * dimension, context.get())),
        linear_solver(SUNLinSol_Dense(y.get(), matrix.get(), context.get())),
        cvode(CV_BDF, context.get()) {
    data.coefficients = k;
    data.dimension = dimension;
    if (!context.ok() || !y.ok() || !matrix.ok() || !linear_solver.ok() || !cvode.ok()) {
      throw ShootingFailure("could not allocate the SUNDIALS objects of the grounded run");
    }
    N_VConst(0.0, y.get());
    check(CVodeInit(cvode.get(), grounded_rhs, 0.0, y.get()), "CVodeInit");
    check(CVodeSetUserData(cvode.get(), &data), "CVodeSetUserData");
    check(CVodeSetLinearSolver(cvode.get(), linear_solver.get(), matrix.get()),
          "CVodeSetLinearSolver");
    check(CVodeSetJacFn(cvode.get(), grounded_jacobian), "CVodeSetJacFn");
    check(CVodeSetMaxNumSteps(cvode.get(), max_steps), "CVodeSetMaxNumSteps");
  }

  void check(int flag, const char* call, double x = 0.0) const {
    if (flag < 0) {
      throw ShootingFailure(fmt::format("{} returned {} ({}) on the seabed at s/L = {:.6g}", call,
                                        cvode_flag_name(flag), flag, x));
    }
  }
  double piece_end_x() const {
    return data.coefficients.pieces[data.piece].s_end / data.coefficients.length_m;
  }
  void add_counts() {
    long n = 0, evaluations = 0;
    CVodeGetNumSteps(cvode.get(), &n);
    CVodeGetNumRhsEvals(cvode.get(), &evaluations);
    steps += n;
    rhs += evaluations;
  }
  void restart_at(double x);
  void integrate_to(double x);
  GroundedFrame frame() const;

  std::size_t run_pieces;
  SundialsContext context;
  SerialVector y;
  SundialsMatrix matrix;
  SundialsLinearSolver linear_solver;
  CvodeMemory cvode;
  GroundedData data;
  double x_now = 0.0;  // where y holds the state
  long steps = 0;
  long rhs = 0;
};

void GroundedRun::Impl::restart_at(double x) {
  check(CVodeReInit(cvode.get(), x, y.get()), "CVodeReInit", x);
  check(CVodeSetStopTime(cvode.get(), piece_end_x()), "CVodeSetStopTime", x);
}

// CVODE to x, stopping at every piece end on the way (the friction profile and the section
// change there) and restarting on the next piece.
void GroundedRun::Impl::integrate_to(double x) {
  while (x > x_now) {
    const double piece_end = piece_end_x();
    const double target = std::min(x, piece_end);
    double reached = x_now;
    check(CVode(cvode.get(), target, y.get(), &reached, CV_NORMAL), "CVode", x_now);
    x_now = target;
    if (target >= piece_end && data.piece + 1 < run_pieces) {
      add_counts();
      ++data.piece;
      restart_at(piece_end);
    }
  }
}

// The physical columns of the balanced pairs and the zeros of their phi on (0, x].
GroundedFrame GroundedRun::Impl::frame() const {
  const int D = data.dimension;
  GroundedFrame f;
  f.phi.resize(D);
  f.force.resize(D);
  f.log_scale.resize(D);
  const double* state = y.data();
  for (int j = 0; j < D; ++j) {
    const double beta = std::sqrt(data.beta2[j]);
    const double psi_balanced = state[2 * j];
    const double phi = std::cos(psi_balanced) / beta, force = beta * std::sin(psi_balanced);
    const double norm = std::hypot(phi, force);
    f.phi(j) = phi / norm;
    f.force(j) = force / norm;
    f.log_scale(j) = state[2 * j + 1] + std::log(norm);
    // The zeros of phi are where psi crosses pi/2 - k pi, always downwards (there psi' = -b~ < 0),
    // starting from pi/2 at A: their number is read off the continuous psi alone. (The count
    // formula of count_conjugate_points put the cut of its unitary angle where phi is zero to
    // rounding, so at a root the count could differ from psi's by one; a tightened estimate shot
    // of a line entirely on the seabed came out two zeros high.)
    f.count += static_cast<int>(std::floor((0.5 * kPi - psi_balanced) / kPi));
  }
  return f;
}

GroundedRun::GroundedRun(const ShootingCoefficients& k,
                         int dimension,
                         std::size_t pieces,
                         long max_steps)
    : impl_(std::make_unique<Impl>(k, dimension, pieces, max_steps)) {}

GroundedRun::~GroundedRun() = default;

double GroundedRun::end_x() const {
  const ShootingCoefficients& k = impl_->data.coefficients;
  return k.pieces[impl_->run_pieces - 1].s_end / k.length_m;
}

std::size_t GroundedRun::pieces() const { return impl_->run_pieces; }

void GroundedRun::begin(double omega2, double relative_tolerance, double absolute_tolerance) {
  GroundedData& d = impl_->data;
  d.omega2 = omega2;
  d.piece = 0;
  double b[2], c[2];
  grounded_coefficients(d.coefficients, d.coefficients.pieces[0], d.dimension, omega2, 0.0, b, c);
  double* state = impl_->y.data();
  for (int j = 0; j < d.dimension; ++j) {
    d.beta2[j] = balance_of(b[j], c[j]);
    // phi = 0, F = 1: psi = pi / 2 and rho = 1 / beta.
    state[2 * j] = 0.5 * kPi;
    state[2 * j + 1] = -0.5 * std::log(d.beta2[j]);
  }
  impl_->x_now = 0.0;
  impl_->steps = 0;
  impl_->rhs = 0;
  impl_->check(CVodeSStolerances(impl_->cvode.get(), relative_tolerance, absolute_tolerance),
               "CVodeSStolerances");
  impl_->restart_at(0.0);
}

GroundedFrame GroundedRun::advance_to(double x) {
  impl_->integrate_to(std::min(x, end_x()));
  return impl_->frame();
}

long GroundedRun::steps() const {
  long n = 0;
  CVodeGetNumSteps(impl_->cvode.get(), &n);
  return impl_->steps + n;
}

long GroundedRun::rhs_evaluations() const {
  long n = 0;
  CVodeGetNumRhsEvals(impl_->cvode.get(), &n);
  return impl_->rhs + n;
}

}  // namespace catena::internal
