// SPDX-License-Identifier: MIT
// KINSOL's Anderson-accelerated fixed point: see anderson_fixed_point.hpp.
#include "solvers/common/anderson_fixed_point.hpp"

#include <fmt/format.h>
#include <kinsol/kinsol.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <memory>

namespace catena::internal {
namespace {

struct Problem {
  const std::function<Vector(const Vector&)>* G = nullptr;
  long evaluations = 0;
  long max_evaluations = 0;
  std::exception_ptr error;
};

int evaluate(N_Vector u, N_Vector g, void* data) {
  auto* p = static_cast<Problem*>(data);
  const sunindextype n = N_VGetLength_Serial(u);
  try {
    if (p->evaluations >= p->max_evaluations) return 1;  // recoverable: KINSOL stops
    ++p->evaluations;
    const Vector value = (*p->G)(Eigen::Map<const Vector>(N_VGetArrayPointer(u), n));
    Eigen::Map<Vector>(N_VGetArrayPointer(g), n) = value;
    return value.allFinite() ? 0 : 1;
  } catch (...) {
    p->error = std::current_exception();
    return -1;
  }
}

void ignore_message(int, const char*, const char*, char*, void*) {}

struct ContextDeleter {
  void operator()(SUNContext c) const { SUNContext_Free(&c); }
};
struct VectorDeleter {
  void operator()(N_Vector v) const { N_VDestroy(v); }
};
struct KinsolDeleter {
  void operator()(void* mem) const { KINFree(&mem); }
};

}  // namespace

FixedPointOutcome anderson_fixed_point(const std::function<Vector(const Vector&)>& G,
                                       const Vector& u0,
                                       double tolerance,
                                       long max_evaluations) {
  FixedPointOutcome out;
  out.u = u0;
  SUNContext raw_context = nullptr;
  if (SUNContext_Create(nullptr, &raw_context) != 0) {
    out.reason = "could not create the SUNDIALS context";
    return out;
  }
  std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter> context(raw_context);
  const sunindextype n = u0.size();
  std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter> u(N_VNew_Serial(n, raw_context));
  std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter> scale(
      N_VNew_Serial(n, raw_context));
  std::unique_ptr<void, KinsolDeleter> kinsol(KINCreate(raw_context));
  if (!u || !scale || !kinsol) {
    out.reason = "could not allocate KINSOL";
    return out;
  }
  Eigen::Map<Vector>(N_VGetArrayPointer(u.get()), n) = u0;
  N_VConst(1.0, scale.get());
  Problem problem{&G, 0, max_evaluations, nullptr};
  void* mem = kinsol.get();
  const bool setup_ok = KINSetMAA(mem, std::min<long>(5, n)) == KIN_SUCCESS &&
                        KINInit(mem, evaluate, u.get()) == KIN_SUCCESS &&
                        KINSetUserData(mem, &problem) == KIN_SUCCESS &&
                        KINSetFuncNormTol(mem, tolerance) == KIN_SUCCESS &&
                        KINSetNumMaxIters(mem, max_evaluations) == KIN_SUCCESS &&
                        KINSetPrintLevel(mem, 0) == KIN_SUCCESS &&
                        // KINSOL's default handler prints to stderr (even under --quiet); the
                        // reason is made from the return flag below.
                        KINSetErrHandlerFn(mem, ignore_message, nullptr) == KIN_SUCCESS;
  if (!setup_ok) {
    out.reason = "could not set up KINSOL";
    return out;
  }
  const int flag = KINSol(mem, u.get(), KIN_FP, scale.get(), scale.get());
  if (problem.error) std::rethrow_exception(problem.error);
  out.u = Eigen::Map<const Vector>(N_VGetArrayPointer(u.get()), n);
  out.evaluations = problem.evaluations;
  out.reached = flag == KIN_SUCCESS || flag == KIN_INITIAL_GUESS_OK;
  if (!out.reached) {
    if (flag == KIN_MAXITER_REACHED || problem.evaluations >= max_evaluations) {
      out.reason = fmt::format("no fixed point within {} iterations", max_evaluations);
    } else {
      char* name = KINGetReturnFlagName(flag);  // malloc'ed by KINSOL
      out.reason = fmt::format("KINSOL stopped with flag {} ({})", flag, name ? name : "?");
      std::free(name);
    }
  }
  return out;
}

}  // namespace catena::internal
