// SPDX-License-Identifier: MIT
// The integrators of a shot: see shooting_steppers.hpp.
#include "solvers/shooting/shooting_steppers.hpp"

#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>
#include <fmt/format.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "solvers/shooting/shooting_block_solver.hpp"
#include "solvers/shooting/shooting_runge_kutta.hpp"
#include "solvers/shooting/shooting_sundials_handles.hpp"

namespace catena::internal {

namespace {

// CVODE's error weights for a shot with the slope: those of the plain shot for Y and the phase,
// none for S, and the weights scaled by sqrt(N / N_plain) so that the root-mean-square norm over
// all N components equals the plain shot's over its own. The steps are then chosen for Y and the
// phase exactly as without the slope: S, integrated with the same steps (the variational equation
// is linear, so the corrector solves it exactly), is as accurate as Y, and Y as accurate as in a
// plain shot. (Weighted in the norm, S added components of small error that let Y's error grow:
// on gale-b-5-sag0.90 the first out-of-plane root moved by 3.3e-10 against 2.5e-11 plain.)
int slope_error_weights(N_Vector y, N_Vector weights, void* user_data) {
  const auto& data = *static_cast<const RhsData*>(user_data);
  const double* state = N_VGetArrayPointer(y);
  double* w = N_VGetArrayPointer(weights);
  const int block = 2 * data.dimension * data.dimension;
  const double dilution = std::sqrt((2.0 * block + 1.0) / (block + 1.0));
  for (int i = 0; i < block; ++i) w[i] = dilution / (data.rtol * std::abs(state[i]) + data.atol);
  w[block] = dilution / (data.rtol * std::abs(state[block]) + data.atol_phase);
  for (int i = block + 1; i <= 2 * block; ++i) w[i] = 0.0;
  return 0;
}

// rhs_values as CVODE calls it.
template <int D, bool Slope>
int cvode_rhs(double x, N_Vector y, N_Vector ydot, void* user_data) {
  rhs_values<D, Slope>(*static_cast<const RhsData*>(user_data), x, N_VGetArrayPointer(y),
                       N_VGetArrayPointer(ydot));
  return 0;
}

// rhs_values as RungeKuttaStepper calls it.
template <int D, bool Slope>
void runge_kutta_rhs(const void* data, double x, const double* y, double* dy) {
  rhs_values<D, Slope>(*static_cast<const RhsData*>(data), x, y, dy);
}

// Analytic Jacobian of the linear part; the phase row is left zero (the phase feeds back into
// nothing, so the modified Newton iteration still converges for it).
template <int D, bool Slope>
int jacobian(
    double x, N_Vector, N_Vector, SUNMatrix J, void* user_data, N_Vector, N_Vector, N_Vector) {
  const auto& data = *static_cast<const RhsData*>(user_data);
  Square<D> B, C, inertia;
  coefficients_at<D>(data, x, B, C, &inertia);
  SUNMatZero(J);
  const int slope_base = 2 * D * D + 1;
  for (int column = 0; column < D; ++column) {
    const int base = 2 * D * column;
    for (int r = 0; r < D; ++r) {
      for (int k = 0; k < D; ++k) {
        SM_ELEMENT_D(J, base + r, base + D + k) = B(r, k);
        SM_ELEMENT_D(J, base + D + r, base + k) = -C(r, k);
        if constexpr (Slope) {
          const int sb = slope_base + base;
          SM_ELEMENT_D(J, sb + r, sb + D + k) = B(r, k);
          SM_ELEMENT_D(J, sb + D + r, sb + k) = -C(r, k);
          SM_ELEMENT_D(J, sb + D + r, base + k) = -2.0 * data.slope_scale * inertia(r, k);
        }
      }
    }
  }
  return 0;
}

// CVODE (Adams or BDF) with its vectors and linear algebra, for the plain state [Y, phase] or the
// state with the slope [Y, phase, S] (the latter solved by blocks: shooting_block_solver.hpp).
class CvodeStepper final : public ShotStepper {
 public:
  CvodeStepper(
      SUNContext context, int dimension, bool slope, const IntegratorSettings& s, RhsData& data)
      : block_(2 * dimension * dimension),
        slope_(slope),
        size_(slope ? 2 * block_ + 1 : block_ + 1),
        y_(size_, context),
        scratch_(size_, context),
        matrix_(SUNDenseMatrix(size_, size_, context)),
        linear_solver_(slope ? make_block_linear_solver(context, block_)
                             : SUNLinSol_Dense(y_.get(), matrix_.get(), context)),
        nonlinear_solver_(s.fixed_point ? SUNNonlinSol_FixedPoint(y_.get(), 0, context) : nullptr),
        cvode_(s.method == ShootingMethod::Bdf ? CV_BDF : CV_ADAMS, context) {
    if (!(y_.ok() && scratch_.ok() && matrix_.ok() && linear_solver_.ok() && cvode_.ok())) {
      throw ShootingFailure("could not allocate the SUNDIALS objects");
    }
    void* mem = cvode_.get();
    N_VConst(0.0, y_.get());
    CVRhsFn f = dimension == 2 ? (slope ? cvode_rhs<2, true> : cvode_rhs<2, false>)
                               : (slope ? cvode_rhs<1, true> : cvode_rhs<1, false>);
    CVLsJacFn jac = dimension == 2 ? (slope ? jacobian<2, true> : jacobian<2, false>)
                                   : (slope ? jacobian<1, true> : jacobian<1, false>);
    check(CVodeInit(mem, f, 0.0, y_.get()), "CVodeInit");
    check(CVodeSetUserData(mem, &data), "CVodeSetUserData");
    if (s.fixed_point) {
      // Functional iteration (no Jacobian, no linear solve): the system is not stiff.
      if (!nonlinear_solver_.get()) {
        throw ShootingFailure("could not allocate SUNNonlinSol_FixedPoint");
      }
      check(CVodeSetNonlinearSolver(mem, nonlinear_solver_.get()), "CVodeSetNonlinearSolver");
    } else {
      check(CVodeSetLinearSolver(mem, linear_solver_.get(), matrix_.get()), "CVodeSetLinearSolver");
      check(CVodeSetJacFn(mem, jac), "CVodeSetJacFn");
    }
    check(CVodeSetMaxNumSteps(mem, s.max_steps), "CVodeSetMaxNumSteps");
  }

  double* state() override { return y_.data(); }

  void begin(double rtol, double atol, double atol_phase, double stop) override {
    finished_steps_ = finished_rhs_ = 0;
    void* mem = cvode_.get();
    check(CVodeReInit(mem, 0.0, y_.get()), "CVodeReInit");
    if (slope_) {
      check(CVodeWFtolerances(mem, slope_error_weights), "CVodeWFtolerances");
    } else {
      N_VConst(atol, scratch_.get());
      scratch_.data()[block_] = atol_phase;
      check(CVodeSVtolerances(mem, rtol, scratch_.get()), "CVodeSVtolerances");
    }
    check(CVodeSetStopTime(mem, stop), "CVodeSetStopTime");
  }

  // ReInit resets CVODE's counters: the finished segment's are kept.
  void restart(double x, double stop) override {
    finished_steps_ = steps();
    finished_rhs_ = rhs_evaluations();
    check(CVodeReInit(cvode_.get(), x, y_.get()), "CVodeReInit", x);
    check(CVodeSetStopTime(cvode_.get(), stop), "CVodeSetStopTime", x);
  }

  double step(double stop) override {
    double x = 0.0;
    check(CVode(cvode_.get(), stop, y_.get(), &x, CV_ONE_STEP), "CVode", x);
    return x;
  }

  void state_at(double xs, double* out) override {
    check(CVodeGetDky(cvode_.get(), xs, 0, scratch_.get()), "CVodeGetDky", xs);
    std::copy_n(scratch_.data(), size_, out);
  }

  long steps() const override {
    long n = 0;
    CVodeGetNumSteps(cvode_.get(), &n);
    return finished_steps_ + n;
  }
  long rhs_evaluations() const override {
    long n = 0;
    CVodeGetNumRhsEvals(cvode_.get(), &n);
    return finished_rhs_ + n;
  }

 private:
  static void check(int flag, const char* call, double x = 0.0) {
    if (flag < 0) {
      throw ShootingFailure(
          fmt::format("{} returned {} ({}) at x = {:.6g}", call, cvode_flag_name(flag), flag, x));
    }
  }

  int block_;
  bool slope_;
  sunindextype size_;
  // Declaration order = construction order; destruction runs in reverse.
  SerialVector y_;
  SerialVector scratch_;
  SundialsMatrix matrix_;
  SundialsLinearSolver linear_solver_;
  SundialsNonlinearSolver nonlinear_solver_;
  CvodeMemory cvode_;
  long finished_steps_ = 0;
  long finished_rhs_ = 0;
};

// The explicit Runge-Kutta method (shooting_runge_kutta.hpp). Error control covers Y and the
// phase; S rides along with the same steps (as with CVODE's weights: slope_error_weights).
class RungeKuttaShotStepper final : public ShotStepper {
 public:
  RungeKuttaShotStepper(int dimension, bool slope, const RhsData& data)
      : block_(2 * dimension * dimension),
        stepper_(verner_6_5(),
                 slope ? 2 * block_ + 1 : block_ + 1,
                 dimension == 2 ? (slope ? runge_kutta_rhs<2, true> : runge_kutta_rhs<2, false>)
                                : (slope ? runge_kutta_rhs<1, true> : runge_kutta_rhs<1, false>),
                 &data) {}

  double* state() override { return stepper_.state(); }

  void begin(double rtol, double atol, double atol_phase, double stop) override {
    Eigen::VectorXd tolerances = Eigen::VectorXd::Constant(block_ + 1, atol);
    tolerances(block_) = atol_phase;
    stepper_.set_tolerances(rtol, tolerances);
    stepper_.set_stop(stop);
    stepper_.begin(0.0);
  }

  void restart(double x, double stop) override {
    stepper_.restart(x);
    stepper_.set_stop(stop);
  }

  double step(double stop) override {
    stepper_.set_stop(stop);
    try {
      return stepper_.step();
    } catch (const std::runtime_error& e) {
      throw ShootingFailure(
          fmt::format("Runge-Kutta step at x = {:.6g}: {}", stepper_.x(), e.what()));
    }
  }

  void state_at(double xs, double* out) override { stepper_.state_at(xs, out); }
  long steps() const override { return stepper_.steps(); }
  long rhs_evaluations() const override { return stepper_.rhs_evaluations(); }

 private:
  int block_;
  RungeKuttaStepper stepper_;
};

}  // namespace

std::unique_ptr<ShotStepper> make_shot_stepper(const IntegratorSettings& settings,
                                               SUNContext context,
                                               int dimension,
                                               bool slope,
                                               RhsData& data) {
  if (settings.method == ShootingMethod::RungeKutta) {
    return std::make_unique<RungeKuttaShotStepper>(dimension, slope, data);
  }
  return std::make_unique<CvodeStepper>(context, dimension, slope, settings, data);
}

}  // namespace catena::internal
