// SPDX-License-Identifier: MIT
#pragma once
// A free decay of Catena's own damped lumped-mass model, integrated in time and written as MoorDyn
// writes its main output file, for tests/verification/free_decay_end_to_end_test.cpp.
//
// The model is fe's in-plane chain (src/solvers/fe/fe_operators.hpp: lumped mass M, tangent
// stiffness K, damping C from c_n, c_t and the Kelvin-Voigt c_a) on the free nodes of a mesh of N
// elements; the ends are held. M x'' + C x' + K x = 0 is integrated by SUNDIALS ARKODE (ARKStep,
// an L-stable implicit Runge-Kutta method with a banded Newton matrix: the axial element modes
// with Kelvin-Voigt damping are stiff) from a released static offset: the displacement of the
// free nodes under a held offset of the fairlead, K x0 = -K_ib (0, 0, dx, dz), released at t = 0
// (the fairlead back at its place, x' = 0). Nothing here solves an eigenproblem: the test compares
// what the record shows with fe's damped eigenvalues of the same matrices.
//
// Channels as MoorDyn names and computes them (source/Line.hpp and MoorDyn2.cpp of
// FloatingArrayDesign/MoorDyn v2.7): FAIRTEN1 = |T + Td| of the top segment, linearised about the
// statics: T0 + (EA / l0) t . (u_N - u_{N-1}) + (c_a / l0) t . (v_N - v_{N-1}) (t the element's
// static direction, u_N = v_N = 0 at the held fairlead); L1N<i>PX and L1N<i>PZ = the static
// position of node i plus its displacement (x horizontal, z up; node 0 at end A, the anchor).

#include <arkode/arkode_arkstep.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunmatrix/sunmatrix_band.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "catena/core/types.hpp"
#include "catena/models/cable.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "solvers/fe/fe_chain_statics.hpp"
#include "solvers/fe/fe_operators.hpp"

namespace catena::test {

/// fe's in-plane operators of one mesh.
struct LumpedModel {
  internal::FeChain chain;
  internal::FeMatrices matrices;
  internal::FeDampingMatrix damping;
  /// Inverse of each free node's 2x2 lumped mass block (node i = 1..N-1 at index i - 1).
  std::vector<Eigen::Matrix2d> inverse_mass;
  int free_nodes() const { return chain.elements - 1; }
};

inline LumpedModel lumped_model(const Problem& problem,
                                const StaticSolution& statics,
                                int elements) {
  LumpedModel model;
  model.chain =
      internal::solve_chain_statics(problem, statics, elements, problem.cable.axial_stiffness_n);
  if (!model.chain.in_equilibrium()) throw std::runtime_error(model.chain.failure);
  model.matrices = internal::assemble_inplane(model.chain);
  model.damping = internal::assemble_damping(Plane::InPlane, model.chain);
  const Eigen::MatrixXd mass(model.matrices.mass);
  for (int i = 0; i < model.free_nodes(); ++i)
    model.inverse_mass.push_back(mass.block<2, 2>(2 * i, 2 * i).inverse());
  return model;
}

/// The free nodes' static displacement under a held fairlead offset (dx, dz) [m].
inline Vector released_offset(const LumpedModel& model, const Vec2& fairlead_offset_m) {
  Eigen::Vector4d ends(0.0, 0.0, fairlead_offset_m.x(), fairlead_offset_m.y());
  const Vector load = -(model.matrices.boundary_coupling * ends);
  Eigen::SparseLU<internal::SparseMatrix> lu(model.matrices.stiffness);
  return lu.solve(load);
}

/// The sampled decay: time and the channels, with MoorDyn's names and units.
struct DecayRecord {
  Vector time_s;
  std::vector<std::string> names;
  std::vector<std::string> units;
  std::vector<Vector> columns;
};

namespace detail {

// State y of 4 per free node i: (x_i, z_i, x'_i, z'_i), interleaved so that the Jacobian is banded
// (node i couples to i - 1 and i + 1 only: bandwidth 7 each side).
constexpr int kBand = 7;

inline int decay_rhs(realtype, N_Vector y, N_Vector ydot, void* data) {
  const auto& model = *static_cast<const LumpedModel*>(data);
  const int nodes = model.free_nodes();
  const realtype* s = N_VGetArrayPointer(y);
  realtype* d = N_VGetArrayPointer(ydot);
  Vector u(2 * nodes), v(2 * nodes);
  for (int i = 0; i < nodes; ++i) {
    u.segment<2>(2 * i) = Eigen::Vector2d(s[4 * i], s[4 * i + 1]);
    v.segment<2>(2 * i) = Eigen::Vector2d(s[4 * i + 2], s[4 * i + 3]);
  }
  const Vector force = -(model.matrices.stiffness * u) - model.damping.damping * v;
  for (int i = 0; i < nodes; ++i) {
    const Eigen::Vector2d a =
        model.inverse_mass[static_cast<std::size_t>(i)] * force.segment<2>(2 * i);
    d[4 * i] = v[2 * i];
    d[4 * i + 1] = v[2 * i + 1];
    d[4 * i + 2] = a.x();
    d[4 * i + 3] = a.y();
  }
  return 0;
}

// The constant Jacobian: d(x')/d(v) = I, d(v')/d(u_j) = -M_i^-1 K_ij, d(v')/d(v_j) = -M_i^-1 C_ij.
inline int decay_jacobian(
    realtype, N_Vector, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector, N_Vector) {
  const auto& model = *static_cast<const LumpedModel*>(data);
  const int nodes = model.free_nodes();
  SUNMatZero(J);
  const Eigen::MatrixXd K(model.matrices.stiffness), C(model.damping.damping);
  for (int i = 0; i < nodes; ++i) {
    SM_ELEMENT_B(J, 4 * i, 4 * i + 2) = 1.0;
    SM_ELEMENT_B(J, 4 * i + 1, 4 * i + 3) = 1.0;
    for (int j = std::max(0, i - 1); j <= std::min(nodes - 1, i + 1); ++j) {
      const Eigen::Matrix2d k =
          -model.inverse_mass[static_cast<std::size_t>(i)] * K.block<2, 2>(2 * i, 2 * j);
      const Eigen::Matrix2d c =
          -model.inverse_mass[static_cast<std::size_t>(i)] * C.block<2, 2>(2 * i, 2 * j);
      for (int r = 0; r < 2; ++r) {
        for (int q = 0; q < 2; ++q) {
          SM_ELEMENT_B(J, 4 * i + 2 + r, 4 * j + q) = k(r, q);
          SM_ELEMENT_B(J, 4 * i + 2 + r, 4 * j + 2 + q) = c(r, q);
        }
      }
    }
  }
  return 0;
}

// The channels at one sample from the state.
inline void record_sample(const LumpedModel& model,
                          const realtype* s,
                          const std::vector<int>& nodes,
                          std::vector<Vector>& columns,
                          Eigen::Index k) {
  const internal::FeChain& c = model.chain;
  const int top = c.elements - 1;  // the top element joins free node N-1 to the fairlead N
  const Vec2& t = c.direction[static_cast<std::size_t>(top)];
  const int last = 4 * (model.free_nodes() - 1);
  const double du = -(t.x() * s[last] + t.y() * s[last + 1]);  // t . (u_N - u_{N-1}), u_N = 0
  const double dv = -(t.x() * s[last + 2] + t.y() * s[last + 3]);
  columns[0][k] = c.tension_n[top] + c.axial_stiffness_n[top] / c.element_length_m[top] * du +
                  c.axial_damping_n_s[top] / c.element_length_m[top] * dv;
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const int i = nodes[n];
    const Vec2 static_position = c.node_offset_m[static_cast<std::size_t>(i)];
    columns[1 + 2 * n][k] = static_position.x() + s[4 * (i - 1)];
    columns[2 + 2 * n][k] = static_position.y() + s[4 * (i - 1) + 1];
  }
}

}  // namespace detail

/// Integrates the decay from displacement `x0` (free unknowns, fe's order) at rest, sampled every
/// `sample_interval_s` for `duration_s`, with ARKODE's relative tolerance `rtol` (absolute: rtol
/// times the largest initial displacement). `nodes` are the nodes (1..N-1) whose positions are
/// recorded; `anchor_m` is end A's position, added to the chain's offsets. Throws on an
/// integrator failure (with ARKODE's flag).
inline DecayRecord integrate_decay(const LumpedModel& model,
                                   const Vector& x0,
                                   const Vec2& anchor_m,
                                   const std::vector<int>& nodes,
                                   double duration_s,
                                   double sample_interval_s,
                                   double rtol) {
  const int free = model.free_nodes();
  SUNContext context = nullptr;
  if (SUNContext_Create(nullptr, &context) != 0) throw std::runtime_error("SUNContext_Create");
  N_Vector y = N_VNew_Serial(4 * free, context);
  realtype* s = N_VGetArrayPointer(y);
  for (int i = 0; i < free; ++i) {
    s[4 * i] = x0[2 * i];
    s[4 * i + 1] = x0[2 * i + 1];
    s[4 * i + 2] = 0.0;
    s[4 * i + 3] = 0.0;
  }
  void* arkode = ARKStepCreate(nullptr, detail::decay_rhs, 0.0, y, context);
  SUNMatrix J = SUNBandMatrix(4 * free, detail::kBand, detail::kBand, context);
  SUNLinearSolver solver = SUNLinSol_Band(y, J, context);
  int flag = ARKStepSStolerances(arkode, rtol, rtol * x0.cwiseAbs().maxCoeff());
  flag = flag ? flag : ARKStepSetUserData(arkode, const_cast<LumpedModel*>(&model));
  flag = flag ? flag : ARKStepSetLinearSolver(arkode, solver, J);
  flag = flag ? flag : ARKStepSetJacFn(arkode, detail::decay_jacobian);
  // The right-hand side is linear with a constant Jacobian: one Newton iteration per stage.
  flag = flag ? flag : ARKStepSetLinear(arkode, 0);
  flag = flag ? flag : ARKStepSetOrder(arkode, 5);
  flag = flag ? flag : ARKStepSetMaxNumSteps(arkode, 10000000);
  const auto samples = static_cast<Eigen::Index>(std::llround(duration_s / sample_interval_s)) + 1;
  DecayRecord record;
  record.time_s =
      Vector::LinSpaced(samples, 0.0, sample_interval_s * static_cast<double>(samples - 1));
  record.names = {"FAIRTEN1"};
  record.units = {"N"};
  for (int i : nodes) {
    record.names.push_back("L1N" + std::to_string(i) + "PX");
    record.names.push_back("L1N" + std::to_string(i) + "PZ");
    record.units.insert(record.units.end(), {"m", "m"});
  }
  record.columns.assign(record.names.size(), Vector(samples));
  detail::record_sample(model, s, nodes, record.columns, 0);
  for (Eigen::Index k = 1; k < samples && flag >= 0; ++k) {
    realtype reached = 0.0;
    flag = ARKStepSetStopTime(arkode, record.time_s[k]);
    flag = flag ? flag : ARKStepEvolve(arkode, record.time_s[k], y, &reached, ARK_NORMAL);
    detail::record_sample(model, s, nodes, record.columns, k);
  }
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    record.columns[1 + 2 * n].array() += anchor_m.x();
    record.columns[2 + 2 * n].array() += anchor_m.y();
  }
  SUNLinSolFree(solver);
  SUNMatDestroy(J);
  N_VDestroy(y);
  ARKStepFree(&arkode);
  SUNContext_Free(&context);
  if (flag < 0) throw std::runtime_error("ARKStepEvolve failed, flag " + std::to_string(flag));
  return record;
}

/// Adds white Gaussian noise of standard deviation `fraction` times each channel's dynamic range
/// (max - min over the record) to every channel, with a fixed seed: a sensor's noise.
inline void add_noise(DecayRecord& record, double fraction, unsigned seed) {
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (Vector& column : record.columns) {
    const double range = column.maxCoeff() - column.minCoeff();
    for (Eigen::Index k = 0; k < column.size(); ++k)
      column[k] += fraction * range * normal(generator);
  }
}

/// Writes `record` as MoorDyn v2 writes its main output file (source/MoorDyn2.cpp, v2.7):
/// right-aligned columns, "Time" in 10 characters and each channel in 20, a units row ("(s)",
/// then MoorDyn's unit names), then one row per output time: the time in fixed notation with 4
/// decimals, each channel in scientific notation with 7 decimals.
inline void write_moordyn_output(const std::filesystem::path& file, const DecayRecord& record) {
  std::ofstream out(file);
  out << std::setw(10) << std::right << "Time";
  for (const auto& name : record.names) out << std::setw(20) << std::right << name;
  out << "\n" << std::setw(10) << std::right << "(s)";
  for (const auto& unit : record.units) out << std::setw(20) << std::right << unit;
  out << "\n";
  for (Eigen::Index k = 0; k < record.time_s.size(); ++k) {
    out << std::setw(10) << std::right << std::fixed << std::setprecision(4) << record.time_s[k];
    for (const Vector& column : record.columns)
      out << std::setw(20) << std::right << std::scientific << std::setprecision(7) << column[k];
    out << "\n";
  }
}

}  // namespace catena::test
