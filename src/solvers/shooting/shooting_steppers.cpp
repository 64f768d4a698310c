// SPDX-License-Identifier: MIT
// The integrators of a shot: see shooting_steppers.hpp.
#include "solvers/shooting/shooting_steppers.hpp"

#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>
#include <fmt/format.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "solvers/shooting/shooting_block_solver.hpp"
#include "solvers/shooting/shooting_sundials_handles.hpp"
#include "solvers/shooting/shooting_vector_kernels.hpp"

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

// The error weights of a plain shot, 1 / (rtol |y_i| + atol_i) with the phase's atol, as
// ERKStepSVtolerances sets them (the same numbers), in one compiled loop instead of ARKODE's
// four unoptimised vector calls a step.
int plain_error_weights(N_Vector y, N_Vector weights, void* user_data) {
  const auto& data = *static_cast<const RhsData*>(user_data);
  const double* state = NV_DATA_S(y);
  double* w = NV_DATA_S(weights);
  const int block = 2 * data.dimension * data.dimension;
  for (int i = 0; i < block; ++i) w[i] = 1.0 / (data.rtol * std::abs(state[i]) + data.atol);
  w[block] = 1.0 / (data.rtol * std::abs(state[block]) + data.atol_phase);
  return 0;
}

// rhs_values as CVODE and ARKODE call it (NV_DATA_S: the serial vectors' data, without
// SUNDIALS' unoptimised accessor).
template <int D, bool Slope>
int sundials_rhs(double x, N_Vector y, N_Vector ydot, void* user_data) {
  rhs_values<D, Slope>(*static_cast<const RhsData*>(user_data), x, NV_DATA_S(y), NV_DATA_S(ydot));
  return 0;
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

// The error weights of a damped shot (complex Y, interleaved real and imaginary parts, no phase):
// 1 / (rtol |z| + atol) with the modulus |z| of each complex component, for both its parts (the
// split into real and imaginary parts is arbitrary: the rotation e^{i phi} of a column must not
// change the control).
int damped_error_weights(N_Vector y, N_Vector weights, void* user_data) {
  const auto& data = *static_cast<const RhsData*>(user_data);
  const double* state = NV_DATA_S(y);
  double* w = NV_DATA_S(weights);
  const int block = 2 * data.dimension * data.dimension;
  for (int i = 0; i < block; ++i) {
    const double weight =
        1.0 / (data.rtol * std::hypot(state[2 * i], state[2 * i + 1]) + data.atol);
    w[2 * i] = w[2 * i + 1] = weight;
  }
  return 0;
}

template <int D>
int damped_rhs(double x, N_Vector y, N_Vector ydot, void* user_data) {
  damped_rhs_values<D>(*static_cast<const RhsData*>(user_data), x, NV_DATA_S(y), NV_DATA_S(ydot));
  return 0;
}

// What a stepper integrates: the state's size, its right-hand side and error weights, and for
// CVODE the Jacobian (null: CVODE's difference quotients) and linear solver.
struct StateSystem {
  int block = 0;               // components of Y (the phase follows it in the undamped states)
  sunindextype size = 0;       // the whole state
  ARKRhsFn rhs = nullptr;      // also CVODE's (same signature)
  ARKEwtFn weights = nullptr;  // ERKStep's, and CVODE's unless vector_tolerances
  CVLsJacFn jacobian = nullptr;
  bool vector_tolerances = false;  // CVODE: CVodeSVtolerances (atol, the phase's atol_phase)
  bool block_solver = false;       // CVODE: shooting_block_solver.hpp instead of dense LU
};

// The plain state [Y, phase] or the state with the slope [Y, phase, S].
StateSystem undamped_system(int dimension, bool slope) {
  StateSystem system;
  system.block = 2 * dimension * dimension;
  system.size = slope ? 2 * system.block + 1 : system.block + 1;
  system.rhs = dimension == 2 ? (slope ? sundials_rhs<2, true> : sundials_rhs<2, false>)
                              : (slope ? sundials_rhs<1, true> : sundials_rhs<1, false>);
  system.weights = slope ? slope_error_weights : plain_error_weights;
  system.jacobian = dimension == 2 ? (slope ? jacobian<2, true> : jacobian<2, false>)
                                   : (slope ? jacobian<1, true> : jacobian<1, false>);
  system.vector_tolerances = !slope;
  system.block_solver = slope;
  return system;
}

// The damped state: the complex Y as 2 x 2 D^2 reals.
StateSystem damped_system(int dimension) {
  StateSystem system;
  system.block = 4 * dimension * dimension;
  system.size = system.block;
  system.rhs = dimension == 2 ? damped_rhs<2> : damped_rhs<1>;
  system.weights = damped_error_weights;
  return system;
}

// CVODE (Adams or BDF) with its vectors and linear algebra, for the plain state [Y, phase], the
// state with the slope [Y, phase, S] (the latter solved by blocks: shooting_block_solver.hpp) or
// the damped state.
class CvodeStepper final : public ShotStepper {
 public:
  CvodeStepper(SUNContext context,
               const StateSystem& system,
               const IntegratorSettings& s,
               RhsData& data)
      : system_(system),
        block_(system.block),
        size_(system.size),
        y_(size_, context),
        scratch_(size_, context),
        matrix_(SUNDenseMatrix(size_, size_, context)),
        linear_solver_(system.block_solver ? make_block_linear_solver(context, block_)
                                           : SUNLinSol_Dense(y_.get(), matrix_.get(), context)),
        nonlinear_solver_(s.fixed_point ? SUNNonlinSol_FixedPoint(y_.get(), 0, context) : nullptr),
        cvode_(s.method == ShootingMethod::Bdf ? CV_BDF : CV_ADAMS, context) {
    if (!(y_.ok() && scratch_.ok() && matrix_.ok() && linear_solver_.ok() && cvode_.ok())) {
      throw ShootingFailure("could not allocate the SUNDIALS objects");
    }
    void* mem = cvode_.get();
    N_VConst(0.0, y_.get());
    check(CVodeInit(mem, system.rhs, 0.0, y_.get()), "CVodeInit");
    check(CVodeSetUserData(mem, &data), "CVodeSetUserData");
    if (s.fixed_point) {
      // Functional iteration (no Jacobian, no linear solve): the system is not stiff.
      if (!nonlinear_solver_.get()) {
        throw ShootingFailure("could not allocate SUNNonlinSol_FixedPoint");
      }
      check(CVodeSetNonlinearSolver(mem, nonlinear_solver_.get()), "CVodeSetNonlinearSolver");
    } else {
      check(CVodeSetLinearSolver(mem, linear_solver_.get(), matrix_.get()), "CVodeSetLinearSolver");
      if (system.jacobian) check(CVodeSetJacFn(mem, system.jacobian), "CVodeSetJacFn");
    }
    check(CVodeSetMaxNumSteps(mem, s.max_steps), "CVodeSetMaxNumSteps");
  }

  double* state() override { return y_.data(); }

  void begin(double rtol, double atol, double atol_phase, double stop) override {
    finished_steps_ = finished_rhs_ = 0;
    void* mem = cvode_.get();
    check(CVodeReInit(mem, 0.0, y_.get()), "CVodeReInit");
    if (!system_.vector_tolerances) {
      check(CVodeWFtolerances(mem, system_.weights), "CVodeWFtolerances");
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

  StateSystem system_;
  int block_;
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

}  // namespace

ARKodeButcherTable verner_table_with_fsal_stage() {
  const ARKodeButcherTable verner = ARKodeButcherTable_LoadERK(ARKODE_VERNER_8_5_6);
  if (verner == nullptr) return nullptr;
  const int s = verner->stages;
  const ARKodeButcherTable table = ARKodeButcherTable_Alloc(s + 1, SUNTRUE);
  if (table != nullptr) {
    table->q = verner->q;
    table->p = verner->p;
    for (int i = 0; i <= s; ++i) {
      for (int j = 0; j <= s; ++j) {
        const bool original = i < s && j < s;
        table->A[i][j] = original ? verner->A[i][j] : (i == s && j < s ? verner->b[j] : 0.0);
      }
      table->c[i] = i < s ? verner->c[i] : 1.0;
      table->b[i] = i < s ? verner->b[i] : 0.0;
      table->d[i] = i < s ? verner->d[i] : 0.0;
    }
  }
  ARKodeButcherTable_Free(verner);
  return table;
}

namespace {

// ARKODE's error handler: keeps the last message for the ShootingFailure (the library never
// prints; ARKODE's default handler writes to stderr).
void keep_message(int, const char*, const char* function, char* message, void* user_data) {
  *static_cast<std::string*>(user_data) = fmt::format("{}: {}", function, message);
}

// ARKODE's ERKStep with Verner's 6(5) pair (ARKODE_VERNER_8_5_6: 8 stages, the 6th-order
// solution propagated, the 5th-order embedding for the error estimate; given to ERKStep as
// verner_table_with_fsal_stage), for the plain state
// [Y, phase] or the state with the slope [Y, phase, S] (S weighted zero: slope_error_weights).
// A new shot re-initialises ERKStep (counters and a new first step); a restart inside a shot
// (a re-orthonormalisation, a break) resets it at x with the changed state and keeps its step
// size, which the solution's scales in x justify. The vectors carry the compiled kernels
// (shooting_vector_kernels.hpp).
class ErkStepper final : public ShotStepper {
 public:
  ErkStepper(SUNContext context,
             const StateSystem& system,
             const IntegratorSettings& s,
             RhsData& data)
      : weights_(system.weights),
        size_(system.size),
        rhs_(system.rhs),
        y_(size_, context),
        scratch_(size_, context),
        start_(size_, context),
        erk_(rhs_, prepared(y_), context),
        context_(context),
        data_(&data) {
    if (!(y_.ok() && scratch_.ok() && start_.ok() && erk_.ok())) {
      throw ShootingFailure("could not allocate the SUNDIALS objects");
    }
    configure(erk_.get());
    set_step_control(erk_.get());
    check(ERKStepSetMaxNumSteps(erk_.get(), s.max_steps), "ERKStepSetMaxNumSteps");
  }

  double* state() override { return y_.data(); }

  // The tolerances are the shot's (RhsData::rtol, atol, atol_phase), read by the weights.
  void begin(double, double, double, double stop) override {
    void* mem = erk_.get();
    check(ERKStepReInit(mem, rhs_, 0.0, y_.get()), "ERKStepReInit");
    x_ = x_start_ = 0.0;
    std::copy_n(y_.data(), size_, start_.data());
    message_.clear();
    check(ERKStepWFtolerances(mem, weights_), "ERKStepWFtolerances");
    // The first step: the one the last shot chose after its first (the error-controlled step at
    // x = 0 of a shot at a nearby frequency); ARKODE's own estimate for the first shot, whose
    // step, of order sqrt(rtol) (a first-order guess), then took ~15 steps to grow.
    check(ERKStepSetInitStep(mem, first_step_), "ERKStepSetInitStep");
    steps_in_shot_ = 0;
    check(ERKStepSetStopTime(mem, stop), "ERKStepSetStopTime");
  }

  void restart(double x, double stop) override {
    check(ERKStepReset(erk_.get(), x, y_.get()), "ERKStepReset", x);
    check(ERKStepSetStopTime(erk_.get(), stop), "ERKStepSetStopTime", x);
    x_ = x;
  }

  double step(double stop) override {
    std::copy_n(y_.data(), size_, start_.data());
    x_start_ = x_;
    check(ERKStepEvolve(erk_.get(), stop, y_.get(), &x_, ARK_ONE_STEP), "ERKStepEvolve", x_);
    if (++steps_in_shot_ == 1) ERKStepGetCurrentStep(erk_.get(), &first_step_);
    return x_;
  }

  // One step of the method from the last step's start to xs, by a second ERKStep with that fixed
  // step: as accurate as the step that passed (shorter than it), where ERKStep's Hermite dense
  // output (ERKStepGetDky) moved the forced tensions of the Gale C-2 curves by up to 4.8e-9
  // (3.7e-9 from a rtol 1e-13 reference where this gives 9e-11).
  void state_at(double xs, double* out) override {
    if (!(xs > x_start_)) {
      std::copy_n(start_.data(), size_, out);
      return;
    }
    if (!station_erk_) {
      station_erk_ = std::make_unique<ErkStepMemory>(rhs_, start_.get(), context_);
      if (!station_erk_->ok()) throw ShootingFailure("could not allocate the SUNDIALS objects");
      configure(station_erk_->get());
    }
    void* mem = station_erk_->get();
    check(ERKStepReset(mem, x_start_, start_.get()), "ERKStepReset", x_start_);
    check(ERKStepSetFixedStep(mem, xs - x_start_), "ERKStepSetFixedStep", xs);
    check(ERKStepSetStopTime(mem, xs), "ERKStepSetStopTime", xs);
    double reached = 0.0;
    check(ERKStepEvolve(mem, xs, scratch_.get(), &reached, ARK_ONE_STEP), "ERKStepEvolve", xs);
    std::copy_n(scratch_.data(), size_, out);
  }

  long steps() const override {
    long n = 0;
    ERKStepGetNumSteps(erk_.get(), &n);
    return n;
  }
  long rhs_evaluations() const override {
    long n = 0;
    ERKStepGetNumRhsEvals(erk_.get(), &n);
    return n;
  }

 private:
  // The table, the user data, the error weights and the error handler of an ERKStep of this
  // stepper (the shot's and the one of the stations).
  void configure(void* mem) {
    check(ERKStepSetErrHandlerFn(mem, keep_message, &message_), "ERKStepSetErrHandlerFn");
    const ARKodeButcherTable table = verner_table_with_fsal_stage();
    if (table == nullptr) throw ShootingFailure("could not allocate the Butcher table");
    const int flag = ERKStepSetTable(mem, table);  // ERKStep keeps a copy
    ARKodeButcherTable_Free(table);
    check(flag, "ERKStepSetTable");
    check(ERKStepSetUserData(mem, data_), "ERKStepSetUserData");
    check(ERKStepWFtolerances(mem, weights_), "ERKStepWFtolerances");
  }

  // ERKStep's step-size controller set to the classical one: h_new = 0.9 h err^(-1/6) (the
  // exponent from the method's order 6, the error taken as estimated: bias 1), growth at most 5x
  // a step, any change of h taken. ARKODE's defaults (PID, safety 0.96, error bias 1.5, h held
  // for growth below 1.5x) took 1.56x the steps of this controller on the mooring line's six
  // in-plane modes (13,639 against 8,725) for no accuracy the solver uses.
  void set_step_control(void* mem) const {
    double exponents[3] = {1.0, 0.0, 0.0};
    check(ERKStepSetAdaptivityMethod(mem, 2, 0, 1, exponents), "ERKStepSetAdaptivityMethod");
    check(ERKStepSetSafetyFactor(mem, 0.9), "ERKStepSetSafetyFactor");
    check(ERKStepSetErrorBias(mem, 1.0), "ERKStepSetErrorBias");
    check(ERKStepSetMaxGrowth(mem, 5.0), "ERKStepSetMaxGrowth");
    check(ERKStepSetFixedStepBounds(mem, 1.0, 1.0), "ERKStepSetFixedStepBounds");
  }

  // The state, zero (ERKStepCreate copies it), with the compiled kernels that every vector
  // ERKStep clones from it inherits.
  static N_Vector prepared(const SerialVector& y) {
    if (!y.ok()) return nullptr;
    use_compiled_kernels(y.get());
    N_VConst(0.0, y.get());
    return y.get();
  }

  void check(int flag, const char* call, double x = 0.0) const {
    if (flag < 0) {
      throw ShootingFailure(fmt::format("{} returned {} ({}) at x = {:.6g}{}{}", call,
                                        erkstep_flag_name(flag), flag, x,
                                        message_.empty() ? "" : ": ", message_));
    }
  }

  ARKEwtFn weights_;
  sunindextype size_;
  ARKRhsFn rhs_;
  std::string message_;
  double first_step_ = 0.0;  // for the next shot (0: ARKODE's estimate)
  long steps_in_shot_ = 0;
  // Declaration order = construction order; destruction runs in reverse.
  SerialVector y_;
  SerialVector scratch_;
  SerialVector start_;  // the state at the start of the last step (x_start_)
  ErkStepMemory erk_;
  std::unique_ptr<ErkStepMemory> station_erk_;  // state_at's, made at its first use
  SUNContext context_;
  RhsData* data_;
  double x_ = 0.0;
  double x_start_ = 0.0;
};

}  // namespace

std::unique_ptr<ShotStepper> make_shot_stepper(const IntegratorSettings& settings,
                                               SUNContext context,
                                               int dimension,
                                               bool slope,
                                               RhsData& data) {
  const StateSystem system = undamped_system(dimension, slope);
  if (settings.method == ShootingMethod::RungeKutta) {
    return std::make_unique<ErkStepper>(context, system, settings, data);
  }
  return std::make_unique<CvodeStepper>(context, system, settings, data);
}

std::unique_ptr<ShotStepper> make_damped_stepper(const IntegratorSettings& settings,
                                                 SUNContext context,
                                                 int dimension,
                                                 RhsData& data) {
  const StateSystem system = damped_system(dimension);
  if (settings.method == ShootingMethod::RungeKutta) {
    return std::make_unique<ErkStepper>(context, system, settings, data);
  }
  return std::make_unique<CvodeStepper>(context, system, settings, data);
}

}  // namespace catena::internal
