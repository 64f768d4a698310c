// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// RAII owners of the SUNDIALS objects the shooting solver uses (SUNContext, N_Vector,
/// SUNMatrix, SUNLinearSolver, CVODE and ARKODE memory). Each owner frees its object in the
/// destructor, in the order SUNDIALS requires when declared in the order context, vector, matrix,
/// solver, integrator (members are destroyed in reverse order). Private to the shooting solver;
/// never installed.

#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nonlinearsolver.h>

#include <cstdlib>
#include <string>
#include <utility>

namespace catena::internal {

/// Owns a SUNContext (SUNDIALS >= 6 needs one per thread of use).
class SundialsContext {
 public:
  SundialsContext() { ok_ = SUNContext_Create(nullptr, &context_) == 0; }
  ~SundialsContext() {
    if (context_) SUNContext_Free(&context_);
  }
  SundialsContext(const SundialsContext&) = delete;
  SundialsContext& operator=(const SundialsContext&) = delete;
  SUNContext get() const { return context_; }
  bool ok() const { return ok_ && context_ != nullptr; }

 private:
  SUNContext context_ = nullptr;
  bool ok_ = false;
};

/// Owns a serial N_Vector.
class SerialVector {
 public:
  SerialVector(sunindextype length, SUNContext context) : vector_(N_VNew_Serial(length, context)) {}
  ~SerialVector() {
    if (vector_) N_VDestroy(vector_);
  }
  SerialVector(const SerialVector&) = delete;
  SerialVector& operator=(const SerialVector&) = delete;
  N_Vector get() const { return vector_; }
  double* data() const { return N_VGetArrayPointer(vector_); }
  bool ok() const { return vector_ != nullptr; }

 private:
  N_Vector vector_ = nullptr;
};

/// Owns a SUNMatrix.
class SundialsMatrix {
 public:
  explicit SundialsMatrix(SUNMatrix matrix) : matrix_(matrix) {}
  ~SundialsMatrix() {
    if (matrix_) SUNMatDestroy(matrix_);
  }
  SundialsMatrix(const SundialsMatrix&) = delete;
  SundialsMatrix& operator=(const SundialsMatrix&) = delete;
  SUNMatrix get() const { return matrix_; }
  bool ok() const { return matrix_ != nullptr; }

 private:
  SUNMatrix matrix_ = nullptr;
};

/// Owns a SUNLinearSolver.
class SundialsLinearSolver {
 public:
  explicit SundialsLinearSolver(SUNLinearSolver solver) : solver_(solver) {}
  ~SundialsLinearSolver() {
    if (solver_) SUNLinSolFree(solver_);
  }
  SundialsLinearSolver(const SundialsLinearSolver&) = delete;
  SundialsLinearSolver& operator=(const SundialsLinearSolver&) = delete;
  SUNLinearSolver get() const { return solver_; }
  bool ok() const { return solver_ != nullptr; }

 private:
  SUNLinearSolver solver_ = nullptr;
};

/// Owns a SUNNonlinearSolver (may be empty: CVODE then uses its default Newton solver).
class SundialsNonlinearSolver {
 public:
  explicit SundialsNonlinearSolver(SUNNonlinearSolver solver) : solver_(solver) {}
  ~SundialsNonlinearSolver() {
    if (solver_) SUNNonlinSolFree(solver_);
  }
  SundialsNonlinearSolver(const SundialsNonlinearSolver&) = delete;
  SundialsNonlinearSolver& operator=(const SundialsNonlinearSolver&) = delete;
  SUNNonlinearSolver get() const { return solver_; }

 private:
  SUNNonlinearSolver solver_ = nullptr;
};

/// Owns CVODE's integrator memory. CVODE's default error handler prints to stderr, under
/// `catena --quiet` and inside Python alike; this one keeps the last message instead (the caller
/// reports the failure from the return flag).
class CvodeMemory {
 public:
  CvodeMemory(int method, SUNContext context) : memory_(CVodeCreate(method, context)) {
    if (memory_) CVodeSetErrHandlerFn(memory_, keep, &last_message_);
  }
  ~CvodeMemory() {
    if (memory_) CVodeFree(&memory_);
  }
  CvodeMemory(const CvodeMemory&) = delete;
  CvodeMemory& operator=(const CvodeMemory&) = delete;
  void* get() const { return memory_; }
  bool ok() const { return memory_ != nullptr; }
  /// CVODE's last error or warning message ("<function>: <message>"), empty when none.
  const std::string& last_message() const { return last_message_; }

 private:
  static void keep(int, const char*, const char* function, char* message, void* user_data) {
    *static_cast<std::string*>(user_data) = std::string(function) + ": " + message;
  }
  void* memory_ = nullptr;
  std::string last_message_;
};

/// Owns ARKODE's ERKStep memory (an explicit Runge-Kutta integrator).
class ErkStepMemory {
 public:
  ErkStepMemory(ARKRhsFn rhs, N_Vector y0, SUNContext context)
      : memory_(ERKStepCreate(rhs, 0.0, y0, context)) {}
  ~ErkStepMemory() {
    if (memory_) ERKStepFree(&memory_);
  }
  ErkStepMemory(const ErkStepMemory&) = delete;
  ErkStepMemory& operator=(const ErkStepMemory&) = delete;
  void* get() const { return memory_; }
  bool ok() const { return memory_ != nullptr; }

 private:
  void* memory_ = nullptr;
};

/// ERKStep's name of a return flag, e.g. "ARK_ERR_FAILURE" (ERKStepGetReturnFlagName allocates).
inline std::string erkstep_flag_name(int flag) {
  char* name = ERKStepGetReturnFlagName(flag);
  std::string result = name ? name : "ARK_UNKNOWN";
  std::free(name);
  return result;
}

/// CVODE's name of a return flag, e.g. "CV_CONV_FAILURE" (CVodeGetReturnFlagName allocates).
inline std::string cvode_flag_name(int flag) {
  char* name = CVodeGetReturnFlagName(flag);
  std::string result = name ? name : "CV_UNKNOWN";
  std::free(name);
  return result;
}

}  // namespace catena::internal
