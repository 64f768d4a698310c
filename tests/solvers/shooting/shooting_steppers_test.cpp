// SPDX-License-Identifier: MIT
// The Butcher table the shooting solver gives ARKODE's ERKStep
// (src/solvers/shooting/shooting_steppers.hpp, verner_table_with_fsal_stage), run by ERKStep on
// problems with closed-form solutions: it is Verner's 6(5) pair with a first-same-as-last stage,
// ERKStep integrates with it at order 6 (SUNDIALS 6.4.1 with the plain ARKODE_VERNER_8_5_6 table
// falls to order 3: llnl/sundials issue #311), its error follows the tolerance on an oscillator
// and on a pure quadrature (where an embedded pair whose error weights cancel on quadratures, such
// as Fehlberg's 7(8), accepts any step).
#include "solvers/shooting/shooting_steppers.hpp"

#include <arkode/arkode_erkstep.h>
#include <gtest/gtest.h>
#include <nvector/nvector_serial.h>

#include <algorithm>
#include <cmath>

namespace catena::internal {
namespace {

// y0' = y1, y1' = -100 y0 from y = (0, 1): y0 = sin(10 x) / 10, y1 = cos(10 x).
int oscillator(double, N_Vector y, N_Vector dy, void*) {
  NV_Ith_S(dy, 0) = NV_Ith_S(y, 1);
  NV_Ith_S(dy, 1) = -100.0 * NV_Ith_S(y, 0);
  return 0;
}

// y' = cos(20 x) from y = 0: a quadrature, whose stages' derivatives do not depend on y.
int quadrature(double x, N_Vector, N_Vector dy, void*) {
  NV_Ith_S(dy, 0) = std::cos(20.0 * x);
  return 0;
}

struct Outcome {
  double error = 0.0;  // at x = 1, max over the components
  long steps = 0;
};

// ERKStep with the shooting table from 0 to 1: fixed steps of `step` when step > 0, else
// adaptive at rtol `tolerance` (atol tolerance / 100).
Outcome integrate(ARKRhsFn rhs, int size, double step, double tolerance) {
  SUNContext context = nullptr;
  EXPECT_EQ(SUNContext_Create(nullptr, &context), 0);
  N_Vector y = N_VNew_Serial(size, context);
  N_VConst(0.0, y);
  if (size == 2) NV_Ith_S(y, 1) = 1.0;
  void* memory = ERKStepCreate(rhs, 0.0, y, context);
  ARKodeButcherTable table = verner_table_with_fsal_stage();
  EXPECT_EQ(ERKStepSetTable(memory, table), ARK_SUCCESS);
  ARKodeButcherTable_Free(table);
  EXPECT_EQ(ERKStepSStolerances(memory, tolerance, tolerance / 100.0), ARK_SUCCESS);
  if (step > 0.0) {
    EXPECT_EQ(ERKStepSetFixedStep(memory, step), ARK_SUCCESS);
  }
  EXPECT_EQ(ERKStepSetStopTime(memory, 1.0), ARK_SUCCESS);
  double x = 0.0;
  while (x < 1.0 - 1e-12) {
    const int flag = ERKStepEvolve(memory, 1.0, y, &x, ARK_ONE_STEP);
    EXPECT_GE(flag, 0);
    if (flag < 0) break;
  }
  Outcome run;
  if (size == 2) {
    run.error = std::max(std::abs(NV_Ith_S(y, 0) - std::sin(10.0) / 10.0),
                         std::abs(NV_Ith_S(y, 1) - std::cos(10.0)));
  } else {
    run.error = std::abs(NV_Ith_S(y, 0) - std::sin(20.0) / 20.0);
  }
  ERKStepGetNumSteps(memory, &run.steps);
  ERKStepFree(&memory);
  N_VDestroy(y);
  SUNContext_Free(&context);
  return run;
}

TEST(ShootingErkTable, IsVernersSixFivePairWithAFirstSameAsLastStage) {
  ARKodeButcherTable table = verner_table_with_fsal_stage();
  ARKodeButcherTable verner = ARKodeButcherTable_LoadERK(ARKODE_VERNER_8_5_6);
  ASSERT_NE(table, nullptr);
  ASSERT_NE(verner, nullptr);
  EXPECT_EQ(table->stages, verner->stages + 1);
  EXPECT_EQ(table->q, 6);
  EXPECT_EQ(table->p, 5);
  const int last = table->stages - 1;
  EXPECT_EQ(table->c[last], 1.0);
  EXPECT_EQ(table->b[last], 0.0);
  EXPECT_EQ(table->d[last], 0.0);
  for (int j = 0; j < last; ++j) {
    EXPECT_EQ(table->A[last][j], verner->b[j]) << j;  // the last stage is the step's solution
    EXPECT_EQ(table->b[j], verner->b[j]) << j;
    EXPECT_EQ(table->d[j], verner->d[j]) << j;
    for (int k = 0; k < last; ++k) EXPECT_EQ(table->A[j][k], verner->A[j][k]) << j << ", " << k;
  }
  int order = 0, embedded_order = 0;
  ARKodeButcherTable_CheckOrder(table, &order, &embedded_order, nullptr);
  EXPECT_EQ(order, 6);
  EXPECT_EQ(embedded_order, 5);
  ARKodeButcherTable_Free(verner);
  ARKodeButcherTable_Free(table);
}

TEST(ShootingErkTable, ErkStepIntegratesAtOrderSix) {
  // Fixed steps h and h/2 (10 h = 0.1 and 0.05 rad a step): the error falls by 2^6.
  const Outcome coarse = integrate(oscillator, 2, 0.01, 1e-10);
  const Outcome fine = integrate(oscillator, 2, 0.005, 1e-10);
  const double observed_order = std::log2(coarse.error / fine.error);
  EXPECT_GT(observed_order, 5.5) << coarse.error << " -> " << fine.error;
  EXPECT_LT(observed_order, 6.5) << coarse.error << " -> " << fine.error;
}

TEST(ShootingErkTable, AdaptiveErrorFollowsTheTolerance) {
  // 1.6 periods; a 6th-order method controlled per step lands within a few rtol at the end.
  for (double tolerance : {1e-6, 1e-8, 1e-10}) {
    const Outcome run = integrate(oscillator, 2, 0.0, tolerance);
    EXPECT_LT(run.error, 10.0 * tolerance) << "rtol " << tolerance << ", " << run.steps << " steps";
  }
}

TEST(ShootingErkTable, ControlsTheErrorOfAPureQuadrature) {
  // The embedding's estimate does not vanish when f does not depend on y (Fehlberg's 7(8) does:
  // docs/explanation/methods/shooting.md, "Integrators").
  const Outcome run = integrate(quadrature, 1, 0.0, 1e-10);
  EXPECT_LT(run.error, 1e-9) << run.steps << " steps";
  EXPECT_GT(run.steps, 5);
}

}  // namespace
}  // namespace catena::internal
