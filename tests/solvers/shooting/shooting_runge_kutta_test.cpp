// SPDX-License-Identifier: MIT
// The explicit Runge-Kutta stepper of the shooting solver
// (src/solvers/shooting/shooting_runge_kutta.hpp) on problems with closed-form solutions: its
// observed order, the stop point, the state inside a step, the components it does not control,
// a pure quadrature (where an embedded pair whose error weights cancel on quadratures, such as
// Fehlberg's 7(8), accepts any step) and the failures it must report.
#include "solvers/shooting/shooting_runge_kutta.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

namespace catena::internal {
namespace {

// y0' = y1, y1' = -y0 (a harmonic oscillator), with y2' = y0 uncontrolled (its exact value is
// 1 - cos x from y = (0, 1, 0)).
void oscillator(const void*, double, const double* y, double* dy) {
  dy[0] = y[1];
  dy[1] = -y[0];
  dy[2] = y[0];
}

// y' = cos(20 x): a quadrature, whose stages' derivatives do not depend on y.
void quadrature(const void*, double x, const double*, double* dy) { dy[0] = std::cos(20.0 * x); }

// y' = y^2 from y = 1: y = 1 / (1 - x), which blows up at x = 1.
void blow_up(const void*, double, const double* y, double* dy) { dy[0] = y[0] * y[0]; }

struct Outcome {
  double error = 0.0;  // of the controlled components at the end
  double uncontrolled_error = 0.0;
  long steps = 0;
};

Outcome oscillate(double tolerance, double end) {
  RungeKuttaStepper stepper(verner_6_5(), 3, oscillator, nullptr);
  stepper.state()[0] = 0.0;
  stepper.state()[1] = 1.0;
  stepper.state()[2] = 0.0;
  stepper.set_tolerances(tolerance, Eigen::VectorXd::Constant(2, tolerance));
  stepper.set_stop(end);
  stepper.begin(0.0);
  while (stepper.x() < end) stepper.step();
  Outcome run;
  run.error = std::hypot(stepper.state()[0] - std::sin(end), stepper.state()[1] - std::cos(end));
  run.uncontrolled_error = std::abs(stepper.state()[2] - (1.0 - std::cos(end)));
  run.steps = stepper.steps();
  return run;
}

TEST(ShootingRungeKutta, TableIsVernersSixFivePair) {
  const ButcherTableau& t = verner_6_5();
  EXPECT_EQ(t.stages, 8);
  EXPECT_EQ(t.order, 6);
  EXPECT_EQ(t.embedded_order, 5);
  EXPECT_NEAR(t.b.sum(), 1.0, 1e-15);
  EXPECT_NEAR(t.error.sum(), 0.0, 1e-15);  // both weight sets integrate a constant exactly
  for (int i = 0; i < t.stages; ++i) EXPECT_NEAR(t.a.row(i).sum(), t.c(i), 1e-15) << i;
}

// The global error falls as steps^-6 (the order of the propagated solution) and stays within a
// small multiple of the tolerance over ten periods.
TEST(ShootingRungeKutta, ObservedOrderIsSixAndTheErrorFollowsTheTolerance) {
  const double end = 20.0 * M_PI;
  std::vector<Outcome> runs;
  for (double tolerance : {1e-6, 1e-8, 1e-10}) {
    runs.push_back(oscillate(tolerance, end));
    EXPECT_LT(runs.back().error, 100.0 * tolerance) << tolerance;
    // Not controlled, but integrated with the same steps: as accurate as the rest.
    EXPECT_LT(runs.back().uncontrolled_error, 100.0 * tolerance) << tolerance;
  }
  for (std::size_t j = 1; j < runs.size(); ++j) {
    const double order = -std::log(runs[j].error / runs[j - 1].error) /
                         std::log(static_cast<double>(runs[j].steps) / runs[j - 1].steps);
    EXPECT_GT(order, 5.0) << j;
    EXPECT_LT(order, 7.5) << j;
  }
}

// Begins a stepper at x = 0 from `start` (its first components; the rest stay 0) at rtol 1e-10
// on `controlled` components, with the stop point `stop`.
void begin_at_zero(RungeKuttaStepper& stepper,
                   std::initializer_list<double> start,
                   int controlled,
                   double stop) {
  int i = 0;
  for (double value : start) stepper.state()[i++] = value;
  stepper.set_tolerances(1e-10, Eigen::VectorXd::Constant(controlled, 1e-12));
  stepper.set_stop(stop);
  stepper.begin(0.0);
}

TEST(ShootingRungeKutta, StepsEndExactlyAtTheStopPointAndContinueFromThere) {
  RungeKuttaStepper stepper(verner_6_5(), 3, oscillator, nullptr);
  begin_at_zero(stepper, {0.0, 1.0}, 2, 0.3);
  double x = 0.0;
  while (x < 0.3) x = stepper.step();
  EXPECT_EQ(x, 0.3);
  stepper.restart(0.3);
  stepper.set_stop(1.0);
  while (x < 1.0) x = stepper.step();
  EXPECT_EQ(x, 1.0);
  EXPECT_NEAR(stepper.state()[0], std::sin(1.0), 1e-9);
}

// A state inside the last step comes from one step of the method from its start, as accurate
// as the steps themselves.
TEST(ShootingRungeKutta, StateInsideTheLastStepIsAccurate) {
  RungeKuttaStepper stepper(verner_6_5(), 3, oscillator, nullptr);
  begin_at_zero(stepper, {0.0, 1.0}, 2, 5.0);
  double before = 0.0;
  double x = stepper.step();
  while (x < 2.0) {
    before = x;
    x = stepper.step();
  }
  ASSERT_LT(before, x);
  double inside[3];
  for (double f : {0.0, 0.25, 0.5, 1.0}) {
    const double xs = before + f * (x - before);
    stepper.state_at(xs, inside);
    EXPECT_NEAR(inside[0], std::sin(xs), 1e-9) << f;
    EXPECT_NEAR(inside[1], std::cos(xs), 1e-9) << f;
  }
}

TEST(ShootingRungeKutta, ControlsTheErrorOfAPureQuadrature) {
  RungeKuttaStepper stepper(verner_6_5(), 1, quadrature, nullptr);
  begin_at_zero(stepper, {0.0}, 1, 1.0);
  while (stepper.x() < 1.0) stepper.step();
  EXPECT_NEAR(stepper.state()[0], std::sin(20.0) / 20.0, 1e-9);
  EXPECT_GT(stepper.steps(), 5);
}

TEST(ShootingRungeKutta, ReportsAStepSizeThatUnderflows) {
  RungeKuttaStepper stepper(verner_6_5(), 1, blow_up, nullptr);
  begin_at_zero(stepper, {1.0}, 1, 2.0);
  try {
    for (int i = 0; i < 100000 && stepper.x() < 2.0; ++i) stepper.step();
    FAIL() << "passed the singularity at x = 1: x = " << stepper.x();
  } catch (const std::runtime_error& e) {
    EXPECT_LT(stepper.x(), 1.0);
    EXPECT_NE(std::string(e.what()).find("step size"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace catena::internal
