// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// An explicit embedded Runge-Kutta stepper for the shooting solver's small state (3 to 17
/// components): the `rk` method (docs/explanation/methods/shooting.md, "Integrators").
///
/// Why not CVODE alone. A shot's state is tiny, and CVODE's per-step work (vector operations
/// through function pointers, the Newton iteration's dense LU, its order ramp after every restart
/// at a break or a re-orthonormalisation) cost 20x more than the right-hand side itself. A
/// one-step method keeps its step size across those restarts, needs no linear algebra, and its
/// stages are plain loops over the state.
///
/// The tableau is Verner's 6(5) pair, read at run time from SUNDIALS ARKODE's table of built-in
/// methods (ARKodeButcherTable_LoadERK, ARKODE_VERNER_8_5_6): the 6th-order solution is propagated
/// (local extrapolation), the 5th-order embedding gives the local error estimate. The error norm
/// is CVODE's weighted root mean square, max over nothing: sqrt(mean((e_i / (rtol |y_i| +
/// atol_i))^2)) over the first `controlled` components (the rest, e.g. the frequency derivative,
/// ride along uncontrolled), with the weights of the step's start, as CVODE does.

#include <Eigen/Core>
#include <string>

namespace catena::internal {

/// A Butcher tableau with an embedded pair.
struct ButcherTableau {
  std::string name;
  int stages = 0;
  int order = 0;           ///< of the propagated solution
  int embedded_order = 0;  ///< of the embedding (the error estimate is of this order)
  Eigen::MatrixXd a;       ///< stages x stages, strictly lower triangular
  Eigen::VectorXd b;       ///< weights of the propagated solution
  Eigen::VectorXd c;       ///< nodes
  Eigen::VectorXd error;   ///< b - (embedding weights): the local error estimate's weights
};

/// Verner's 6(5) pair from ARKODE's built-in table (loaded once).
const ButcherTableau& verner_6_5();

/// Advances y' = f(x, y) one accepted step at a time with error control and a stop point.
class RungeKuttaStepper {
 public:
  /// f(data, x, y, dy) writes the derivative of the state y (size components) into dy.
  using Rhs = void (*)(const void* data, double x, const double* y, double* dy);

  RungeKuttaStepper(const ButcherTableau& tableau, int size, Rhs rhs, const void* data);

  /// The current state (size components); change it only through restart().
  double* state() { return y_.data(); }
  const double* state() const { return y_.data(); }
  double x() const { return x_; }

  /// Error control: rtol and the absolute tolerances of the first atol.size() components (the
  /// controlled ones).
  void set_tolerances(double relative_tolerance, const Eigen::VectorXd& absolute_tolerances);

  /// Starts at x with the state as it is now; forgets the step size (a new shot).
  void begin(double x);
  /// Continues at x after the state was changed in place (a re-orthonormalisation, a jump at a
  /// point): the step size is kept, since the solution's scales in x did not change.
  void restart(double x);
  /// The last point a step may reach (a break, or the end).
  void set_stop(double x_stop) { stop_ = x_stop; }

  /// Takes one accepted step toward the stop point and returns the new x; throws
  /// std::runtime_error with the reason when the step size underflows or the state is not finite.
  double step();

  /// The state at xs in [x_before_step, x] by one step of the method from the accepted step's
  /// start (no error control needed: it is shorter than the step that passed).
  void state_at(double xs, double* out);

  long steps() const { return steps_; }
  long rhs_evaluations() const { return evaluations_; }

 private:
  double initial_step();
  // One step of size h from (x0, y0) into out; the stage derivatives stay in k_ (k_.col(0) must
  // already hold f(x0, y0)). Returns the weighted error norm when asked.
  double attempt(
      double x0, const Eigen::VectorXd& y0, double h, Eigen::VectorXd& out, bool with_error);
  double weighted_norm(const Eigen::VectorXd& v, const Eigen::VectorXd& reference) const;
  void evaluate(double x, const Eigen::VectorXd& y, int stage);

  const ButcherTableau& tableau_;
  Rhs rhs_;
  const void* data_;
  Eigen::VectorXd y_, y_start_, y_next_, stage_state_;
  Eigen::MatrixXd k_;  // size x stages
  Eigen::VectorXd atol_;
  double rtol_ = 1e-10;
  double x_ = 0.0, x_start_ = 0.0, stop_ = 1.0;
  double h_ = 0.0;  // the next step to try (0: choose one)
  long steps_ = 0, evaluations_ = 0;
};

}  // namespace catena::internal
