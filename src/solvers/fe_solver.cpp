// The `fe` solver: orchestration of the lumped-mass chain (meshes, penalty values, Richardson and
// kappa extrapolation, shapes, tension, forced response) and its registry entry. The building
// blocks are in internal/fe_model.cpp; the method is documented in fe_solver.hpp.
#include "catena/solvers/fe_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "catena/core/error.hpp"
#include "solvers/internal/fe_banded_ldlt.hpp"
#include "solvers/internal/fe_model.hpp"
#include "solvers/internal/knob_reader.hpp"
#include "solvers/internal/mode_tools.hpp"
#include "solvers/internal/solver_entries.hpp"

namespace catena {

void FeSolverOptions::validate() const {
  if (elements < 2)
    throw InvalidInput(fmt::format(
        "Invalid FeSolverOptions::elements = {}. Violated constraint: elements >= 2.", elements));
  if (elements > 50'000'000)
    throw InvalidInput(fmt::format(
        "Invalid FeSolverOptions::elements = {}. Violated constraint: elements <= 5e7.", elements));
  if (!(kappa > 0.0) || !(kappa <= 1e-2))
    throw InvalidInput(fmt::format(
        "Invalid FeSolverOptions::kappa = {}. Violated constraint: 0 < kappa <= 1e-2 (kappa = H/EA "
        "is the inextensibility penalty).",
        kappa));
  if (!(eigen_tolerance > 0.0) || !(eigen_tolerance <= 1e-4))
    throw InvalidInput(fmt::format(
        "Invalid FeSolverOptions::eigen_tolerance = {}. Violated constraint: 0 < eigen_tolerance "
        "<= 1e-4.",
        eigen_tolerance));
  if (max_restarts < 1)
    throw InvalidInput(fmt::format(
        "Invalid FeSolverOptions::max_restarts = {}. Violated constraint: max_restarts >= 1.",
        max_restarts));
}

namespace internal {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

int unknowns(Plane plane, int elements) {
  return (plane == Plane::InPlane ? 2 : 1) * (elements - 1);
}
const char* plane_name(Plane plane) { return plane == Plane::InPlane ? "in-plane" : "out-of-plane"; }

// Nodal displacements of the whole chain (fixed ends included) from the free unknowns.
// In plane: (x, z) per node; out of plane: (v, 0).
std::vector<Vec2> node_displacements(Plane plane,
                                     int elements,
                                     const Eigen::Ref<const Vector>& free,
                                     const Vec2& end_a = Vec2::Zero(),
                                     const Vec2& end_b = Vec2::Zero()) {
  std::vector<Vec2> D(static_cast<std::size_t>(elements) + 1, Vec2::Zero());
  D.front() = end_a;
  D.back() = end_b;
  for (int i = 1; i < elements; ++i) {
    D[static_cast<std::size_t>(i)] = plane == Plane::InPlane
                                         ? Vec2(free[2 * (i - 1)], free[2 * (i - 1) + 1])
                                         : Vec2(free[i - 1], 0.0);
  }
  return D;
}

// Dynamic tension of each element, tau_j = EA t_j . (D_{j+1} - D_j) / l0 [N].
Vector element_tension(const FeChain& chain, const std::vector<Vec2>& D) {
  Vector tau(chain.elements);
  for (int j = 0; j < chain.elements; ++j) {
    const auto k = static_cast<std::size_t>(j);
    tau[j] = chain.axial_stiffness_n * chain.direction[k].dot(D[k + 1] - D[k]) /
             chain.element_length_m;
  }
  return tau;
}

// Samples the chain's displacement on the stations: linear between nodes, projected on the
// continuous static tangent and normal (in plane); tension linear between element midpoints
// (extrapolated linearly over the half elements at the ends).
struct Sampled {
  Vector u, w, v, tension;
};
Sampled sample(Plane plane,
               const FeChain& chain,
               const std::vector<Vec2>& D,
               const Vector* tau,
               const Vector& stations,
               const StaticSolution& statics) {
  const int N = chain.elements;
  const double l0 = chain.element_length_m;
  Sampled out;
  const Index points = stations.size();
  if (plane == Plane::InPlane) {
    out.u.resize(points);
    out.w.resize(points);
  } else {
    out.v.resize(points);
  }
  if (tau) out.tension.resize(points);
  for (Index p = 0; p < points; ++p) {
    const double s = stations[p];
    const double x = s / l0;
    const int i = std::clamp(static_cast<int>(std::floor(x)), 0, N - 1);
    const double f = x - i;
    const Vec2 d = (1.0 - f) * D[static_cast<std::size_t>(i)] + f * D[static_cast<std::size_t>(i) + 1];
    if (plane == Plane::InPlane) {
      out.u[p] = d.dot(statics.tangent(s));
      out.w[p] = d.dot(statics.normal(s));
    } else {
      out.v[p] = d.x();
    }
    if (tau) {
      const double y = x - 0.5;
      const int j = std::clamp(static_cast<int>(std::floor(y)), 0, N - 2);
      const double g = y - j;
      out.tension[p] = (1.0 - g) * (*tau)[j] + g * (*tau)[j + 1];
    }
  }
  return out;
}

// One mode on the stations, normalised (modal_result.hpp convention).
Mode make_mode(Plane plane,
               const FeChain& chain,
               const Eigen::Ref<const Vector>& eigenvector,
               const Vector& stations,
               const StaticSolution& statics,
               bool with_tension) {
  const std::vector<Vec2> D = node_displacements(plane, chain.elements, eigenvector);
  Vector tau;
  if (with_tension && plane == Plane::InPlane) tau = element_tension(chain, D);
  const Sampled sampled =
      sample(plane, chain, D, (with_tension && plane == Plane::InPlane) ? &tau : nullptr, stations,
             statics);
  Mode mode;
  mode.s_m = stations;
  if (plane == Plane::InPlane) {
    mode.u = sampled.u;
    mode.w = sampled.w;
    if (with_tension) mode.tension_n = sampled.tension;
    normalise_inplane_mode(mode);
  } else {
    mode.v = sampled.v;
    // Out-of-plane motion causes no first-order dynamic tension.
    if (with_tension) mode.tension_n = Vector::Zero(stations.size());
    normalise_outofplane_mode(mode);
  }
  return mode;
}

// Linear extrapolation to kappa = 0 of two normalised modes (kappa and 2 kappa): 2 a - b, after
// aligning b to a by least squares (normalisation may pick a different peak of equal height).
void extrapolate_mode_in_kappa(Mode& a, const Mode& b_in) {
  Mode b = b_in;
  auto stack = [](const Mode& mode) {
    Vector all(mode.u.size() + mode.w.size() + mode.v.size());
    all << mode.u, mode.w, mode.v;
    return all;
  };
  const Vector va = stack(a), vb = stack(b);
  const double denominator = vb.squaredNorm();
  if (denominator == 0.0) return;
  const double alpha = va.dot(vb) / denominator;
  auto combine = [alpha](Vector& x, const Vector& y) {
    if (x.size() && x.size() == y.size()) x = 2.0 * x - alpha * y;
  };
  combine(a.u, b.u);
  combine(a.w, b.w);
  combine(a.v, b.v);
  combine(a.tension_n, b.tension_n);
  if (a.v.size()) {
    normalise_outofplane_mode(a);
  } else {
    normalise_inplane_mode(a);
  }
}

// The displacement of the free nodes of a chain of `elements` elements, restricted to the nodes
// of a chain of `coarse_elements` (a divisor): node i of the coarse chain is node i r of the fine.
Eigen::MatrixXd restrict_to_nodes(const Eigen::MatrixXd& vectors, int elements, int coarse_elements, Plane plane) {
  const int per_node = plane == Plane::InPlane ? 2 : 1;
  const int ratio = elements / coarse_elements;
  Eigen::MatrixXd out(per_node * (coarse_elements - 1), vectors.cols());
  for (int i = 1; i < coarse_elements; ++i)
    out.middleRows(per_node * (i - 1), per_node) = vectors.middleRows(per_node * (i * ratio - 1), per_node);
  return out;
}

// For each reference mode, the index of the mode of `other` with the largest modal assurance
// criterion MAC = (a.b)^2 / (a.a b.b) on the common nodes, assigned greedily from the best pair
// down (each mode used once). Meshes differ by powers of two, so the coarser nodes are common.
std::vector<int> match_modes(const Eigen::MatrixXd& reference,
                             int reference_elements,
                             const Eigen::MatrixXd& other,
                             int other_elements,
                             Plane plane) {
  const int common = std::min(reference_elements, other_elements);
  const Eigen::MatrixXd a = restrict_to_nodes(reference, reference_elements, common, plane);
  const Eigen::MatrixXd b = restrict_to_nodes(other, other_elements, common, plane);
  const Eigen::MatrixXd cross = a.transpose() * b;
  const Vector na = a.colwise().squaredNorm().transpose(), nb = b.colwise().squaredNorm().transpose();
  const auto n = static_cast<int>(reference.cols());
  std::vector<int> result(static_cast<std::size_t>(n), -1);
  std::vector<bool> used(static_cast<std::size_t>(other.cols()), false);
  for (int assigned = 0; assigned < n; ++assigned) {
    double best = -1.0;
    int bi = -1, bj = -1;
    for (int i = 0; i < n; ++i) {
      if (result[static_cast<std::size_t>(i)] >= 0) continue;
      for (int j = 0; j < other.cols(); ++j) {
        if (used[static_cast<std::size_t>(j)]) continue;
        const double norms = na[i] * nb[j];
        const double mac = norms > 0.0 ? cross(i, j) * cross(i, j) / norms : 0.0;
        if (mac > best) {
          best = mac;
          bi = i;
          bj = j;
        }
      }
    }
    result[static_cast<std::size_t>(bi)] = bj;
    used[static_cast<std::size_t>(bj)] = true;
  }
  return result;
}

Termination worse(Termination a, Termination b) {
  auto rank = [](Termination t) {
    switch (t) {
      case Termination::Converged: return 0;
      case Termination::NoConvergence: return 1;
      case Termination::NotApplicable: return 2;
      case Termination::NumericalFailure: return 3;
    }
    return 3;
  };
  return rank(a) >= rank(b) ? a : b;
}

// The meshes and penalties of one solve.
struct Plan {
  std::vector<int> meshes;  // ascending
  int main_coarse = -1;     // index in meshes of the pair used for the result
  int main_fine = -1;
  bool richardson = false;
  bool inextensible = false;
  std::vector<double> axial_stiffness_n;  // one per penalty (1 value when extensible)
  std::vector<double> kappas;
};

Plan make_plan(const Problem& problem,
               const StaticSolution& statics,
               const FeSolverOptions& options,
               int max_modes_in_plane,
               int max_modes_out_of_plane) {
  Plan plan;
  const int N = options.elements;
  auto fits = [&](int elements) {
    return elements >= 2 && unknowns(Plane::InPlane, elements) >= max_modes_in_plane &&
           unknowns(Plane::OutOfPlane, elements) >= max_modes_out_of_plane;
  };
  if (options.richardson) {
    plan.meshes = {N, 2 * N};
    plan.main_coarse = 0;
    plan.main_fine = 1;
    plan.richardson = true;
    if (options.observed_order) plan.meshes.push_back(4 * N);
  } else {
    if (fits(N / 2)) {
      plan.meshes = {N / 2, N};
      plan.main_coarse = 0;
      plan.main_fine = 1;
    } else {
      plan.meshes = {N};
      plan.main_fine = 0;
    }
    if (options.observed_order) plan.meshes.push_back(2 * N);
  }
  plan.inextensible = problem.cable.is_inextensible();
  if (plan.inextensible) {
    double reference = statics.horizontal_force_n();
    if (!(reference > 0.0))
      reference = std::max(statics.tension_n(0.0), statics.tension_n(problem.cable.length_m));
    plan.kappas = {options.kappa, 2.0 * options.kappa};
    for (double kappa : plan.kappas) plan.axial_stiffness_n.push_back(reference / kappa);
  } else {
    plan.axial_stiffness_n = {problem.cable.axial_stiffness_n};
  }
  return plan;
}

// Everything computed for one (mesh, penalty) pair.
struct Level {
  FeChain chain;
  std::map<Plane, FeMatrices> matrices;
  std::map<Plane, FeEigenSolution> eigen;
};

std::string format_seconds(double seconds) {
  return seconds < 1e-3 ? fmt::format("{:.1f} us", seconds * 1e6)
                        : fmt::format("{:.3f} ms", seconds * 1e3);
}

// Forced response of one plane on one level at frequency omega; `end_a`, `end_b` the imposed
// end displacements.
struct RawForced {
  bool ok = false;
  std::string diagnostic;
  Sampled sampled;
};
RawForced forced_on_level(Plane plane,
                          const FeChain& chain,
                          const FeMatrices& matrices,
                          double omega,
                          const Vec2& end_a,
                          const Vec2& end_b,
                          const Vector& stations,
                          const StaticSolution& statics) {
  RawForced out;
  Vector boundary(plane == Plane::InPlane ? 4 : 2);
  if (plane == Plane::InPlane) {
    boundary << end_a, end_b;
  } else {
    boundary << end_a.x(), end_b.x();
  }
  const Vector rhs = -(matrices.boundary_coupling * boundary);
  const SparseMatrix dynamic = matrices.stiffness - (omega * omega) * matrices.mass;
  // A pivot 1e-13 below the largest means omega^2 sits on an eigenvalue of the discrete model to
  // rounding: no finite answer.
  BandedLdlt ldlt;
  bool singular = !ldlt.factorize(dynamic) || ldlt.pivot_ratio() <= 1e-13;
  Vector x = rhs;
  if (!singular) {
    ldlt.solve_in_place(x.data());
    singular = !x.allFinite();
  }
  if (singular) {
    out.diagnostic = fmt::format(
        "K - omega^2 M is singular at omega = {:.9g} rad/s (N = {}): forcing at a natural "
        "frequency of the discrete model (resonance)",
        omega, chain.elements);
    return out;
  }
  const std::vector<Vec2> D = node_displacements(plane, chain.elements, x, end_a, end_b);
  Vector tau;
  if (plane == Plane::InPlane) tau = element_tension(chain, D);
  out.sampled = sample(plane, chain, D, plane == Plane::InPlane ? &tau : nullptr, stations, statics);
  if (plane == Plane::OutOfPlane) out.sampled.tension = Vector::Zero(stations.size());
  out.ok = true;
  return out;
}

}  // namespace

SolverOutput solve_fe_timed(const Problem& problem,
                            const StaticSolution& statics,
                            const DimensionlessGroups& groups,
                            const SolveRequest& request,
                            const FeSolverOptions& options,
                            FeTimings& timings) {
  const auto start_all = Clock::now();
  options.validate();
  request.validate();
  problem.validate();

  SolverOutput output;
  output.solver = "fe";
  output.summary.solver = "fe";

  std::vector<std::pair<Plane, int>> planes;
  if (request.inplane_modes > 0) planes.emplace_back(Plane::InPlane, request.inplane_modes);
  if (request.outofplane_modes > 0) planes.emplace_back(Plane::OutOfPlane, request.outofplane_modes);
  const bool forced_out_of_plane =
      request.forced && request.forced->direction == ForcingDirection::OutOfPlane;
  const Plane forced_plane = forced_out_of_plane ? Plane::OutOfPlane : Plane::InPlane;

  // Bad input first: every requested mode must exist on the coarsest mesh that feeds the result.
  for (const auto& [plane, modes] : planes) {
    const int coarse = options.elements;
    if (unknowns(plane, coarse) < modes) {
      throw InvalidInput(fmt::format(
          "Invalid FeSolverOptions::elements = {}: too few for {} {} modes (a chain of {} elements "
          "has {} {} unknowns). Violated constraint: {} (elements - 1) >= modes.",
          coarse, modes, plane_name(plane), coarse, unknowns(plane, coarse), plane_name(plane),
          plane == Plane::InPlane ? 2 : 1));
    }
  }
  const Plan plan = make_plan(problem, statics, options, request.inplane_modes,
                              request.outofplane_modes);
  const std::size_t num_penalties = plan.axial_stiffness_n.size();

  // Rounding floor of the in-plane chain: K holds axial springs EA/l0 beside geometric ones T/l0,
  // so an eigenvalue's backward error eps_mach ||K|| is, relative to omega_n^2, about
  // eps_mach (EA/T0) N^2 / (pi n)^2 (half of that in omega). A conservative bound (observed errors
  // are 10-200x smaller), added to every in-plane error estimate; when it exceeds 1e-2 for mode 1
  // the in-plane answer would be noise, and the solver says so instead of returning it.
  const int finest_elements = plan.meshes[static_cast<std::size_t>(plan.main_fine)];
  const double stiffness_ratio = plan.axial_stiffness_n[0] / std::max(groups.t0_n, 1e-300);
  auto rounding_floor = [&](int mode_number) {
    const double n = static_cast<double>(mode_number);
    return 0.5 * std::numeric_limits<double>::epsilon() * stiffness_ratio *
           static_cast<double>(finest_elements) * static_cast<double>(finest_elements) / (kPi * kPi * n * n);
  };
  constexpr double kMaxRoundingFloor = 1e-2;
  const bool inplane_asked = request.inplane_modes > 0 || (request.forced && !forced_out_of_plane);
  if (inplane_asked && rounding_floor(1) > kMaxRoundingFloor) {
    output.summary.termination = Termination::NoConvergence;
    output.summary.message = fmt::format(
        "No convergence: the in-plane chain is too stiff for double precision: EA/T0 = {:.2e} with "
        "N = {} elements gives a rounding floor of {:.1e} relative on mode 1 (> {:.0e}); use fewer "
        "elements, or the shooting solver (exact in EA, no discretisation)",
        stiffness_ratio, finest_elements, rounding_floor(1), kMaxRoundingFloor);
    output.summary.resolution = fmt::format("N = {} elements", finest_elements);
    return output;
  }

  // levels[mesh][penalty]
  std::vector<std::vector<Level>> levels(plan.meshes.size(), std::vector<Level>(num_penalties));
  SolverSummary& summary = output.summary;
  summary.termination = Termination::Converged;
  try {
    for (std::size_t m = 0; m < plan.meshes.size(); ++m) {
      for (std::size_t k = 0; k < num_penalties; ++k) {
        auto start = Clock::now();
        levels[m][k].chain =
            solve_chain_statics(problem, statics, plan.meshes[m], plan.axial_stiffness_n[k]);
        timings.statics_s += seconds_since(start);
      }
    }
  } catch (const std::runtime_error& error) {
    summary.termination = Termination::NumericalFailure;
    summary.message = std::string("Numerical failure: ") + error.what();
    summary.wall_time_s = seconds_since(start_all);
    return output;
  }

  const Vector stations = request.stations_m(problem.cable.length_m);
  long total_restarts = 0, total_operations = 0;
  double max_residual = 0.0, max_orthogonality = 0.0, max_error = 0.0, max_backward = 0.0;
  std::vector<std::string> plane_messages;

  for (const auto& [plane, modes] : planes) {
    ModalResult result;
    result.plane = plane;
    result.summary.solver = "fe";
    result.summary.termination = Termination::Converged;
    const auto start_plane = Clock::now();
    double plane_backward = 0.0, plane_orthogonality = 0.0;
    for (std::size_t m = 0; m < plan.meshes.size(); ++m) {
      for (std::size_t k = 0; k < num_penalties; ++k) {
        Level& level = levels[m][k];
        auto start = Clock::now();
        level.matrices[plane] =
            plane == Plane::InPlane ? assemble_inplane(level.chain) : assemble_outofplane(level.chain);
        timings.assembly_s += seconds_since(start);
        FeEigenSolution eigen = solve_lowest_modes(level.matrices[plane], modes,
                                                   options.eigen_tolerance, options.max_restarts);
        timings.factorization_s += eigen.factorization_time_s;
        timings.eigen_iterations_s += eigen.iteration_time_s;
        total_restarts += eigen.restarts;
        total_operations += eigen.operations;
        result.summary.iterations = std::max(0L, result.summary.iterations) + eigen.restarts;
        result.summary.operations = std::max(0L, result.summary.operations) + eigen.operations;
        for (const auto& warning : eigen.warnings)
          result.summary.warnings.push_back(fmt::format("N = {}: {}", plan.meshes[m], warning));
        if (eigen.termination != Termination::Converged) {
          result.summary.termination = worse(result.summary.termination, eigen.termination);
          result.summary.warnings.push_back(fmt::format("N = {}: {}", plan.meshes[m], eigen.message));
        } else {
          result.summary.max_residual = std::max(result.summary.max_residual, eigen.max_residual);
          max_orthogonality = std::max(max_orthogonality, eigen.max_orthogonality_error);
          max_backward = std::max(max_backward, eigen.max_backward_error);
          plane_backward = std::max(plane_backward, eigen.max_backward_error);
          plane_orthogonality = std::max(plane_orthogonality, eigen.max_orthogonality_error);
        }
        level.eigen[plane] = std::move(eigen);
      }
    }
    if (result.summary.termination == Termination::NumericalFailure) {
      result.summary.message = fmt::format("Numerical failure: {} eigenproblem: {}", plane_name(plane),
                                           result.summary.warnings.empty() ? std::string("?")
                                                                           : result.summary.warnings.back());
      summary.termination = worse(summary.termination, result.summary.termination);
      plane_messages.push_back(result.summary.message);
      if (plane == Plane::InPlane) output.inplane = result; else output.outofplane = result;
      continue;
    }

    // Number of modes every level delivered.
    int available = modes;
    for (const auto& row : levels)
      for (const auto& level : row)
        available = std::min(available, static_cast<int>(level.eigen.at(plane).eigenvalues.size()));

    const auto start_post = Clock::now();
    const auto fine = static_cast<std::size_t>(plan.main_fine);
    // Pair every level's modes with the reference level's (finest main mesh, first penalty) by
    // shape, not by rank: near a cross-over the order of two close modes can differ between
    // meshes (the discretisation error moves the crossing), and pairing by rank would then
    // extrapolate one mode's frequency with the other's.
    std::vector<std::vector<std::vector<int>>> match(levels.size(),
                                                     std::vector<std::vector<int>>(num_penalties));
    const Level& reference = levels[fine][0];
    for (std::size_t m = 0; m < levels.size(); ++m)
      for (std::size_t k = 0; k < num_penalties; ++k)
        match[m][k] = match_modes(reference.eigen.at(plane).eigenvectors.leftCols(available),
                                  reference.chain.elements,
                                  levels[m][k].eigen.at(plane).eigenvectors.leftCols(available),
                                  levels[m][k].chain.elements, plane);
    auto omega_at = [&](std::size_t m, std::size_t k, int i) {
      const int j = match[m][k][static_cast<std::size_t>(i)];
      return std::sqrt(std::max(0.0, levels[m][k].eigen.at(plane).eigenvalues[j]));
    };
    const bool has_coarse = plan.main_coarse >= 0;
    const auto coarse = static_cast<std::size_t>(std::max(0, plan.main_coarse));
    std::vector<double> observed_orders;
    for (int i = 0; i < available; ++i) {
      double omega = 0.0, error = -1.0;
      std::vector<double> per_penalty, per_penalty_error;
      for (std::size_t k = 0; k < num_penalties; ++k) {
        const double w_fine = omega_at(fine, k, i);
        double value = w_fine, estimate = -1.0;
        if (has_coarse) {
          const double w_coarse = omega_at(coarse, k, i);
          const double correction = (w_fine - w_coarse) / 3.0;  // order 2, mesh ratio 2
          estimate = std::abs(correction);
          if (plan.richardson) value = w_fine + correction;
        }
        per_penalty.push_back(value);
        per_penalty_error.push_back(estimate);
      }
      if (plan.inextensible) {
        omega = 2.0 * per_penalty[0] - per_penalty[1];
        error = per_penalty_error[0] < 0.0 ? -1.0
                                           : per_penalty_error[0] + std::abs(per_penalty[0] - per_penalty[1]);
      } else {
        omega = per_penalty[0];
        error = per_penalty_error[0];
      }
      if (options.observed_order && plan.meshes.size() >= 3) {
        const std::size_t last = plan.meshes.size() - 1;
        const double d1 = omega_at(last - 2, 0, i) - omega_at(last - 1, 0, i);
        const double d2 = omega_at(last - 1, 0, i) - omega_at(last, 0, i);
        observed_orders.push_back(d2 != 0.0 && d1 / d2 > 0.0 ? std::log2(d1 / d2) : 0.0);
      }

      Mode mode;
      mode.index = i + 1;
      set_mode_frequency(mode, omega, groups);
      mode.relative_error_estimate = (error >= 0.0 && omega > 0.0) ? error / omega : -1.0;
      if (plane == Plane::InPlane && mode.relative_error_estimate >= 0.0) {
        mode.relative_error_estimate += rounding_floor(mode.index);
      }
      if (mode.relative_error_estimate >= 0.0)
        max_error = std::max(max_error, mode.relative_error_estimate);
      result.summary.max_error_estimate =
          std::max(result.summary.max_error_estimate, mode.relative_error_estimate);

      // Shapes and tension from the finest main mesh (extrapolated in kappa when penalised).
      const bool with_tension = request.tension;
      Mode shaped = make_mode(plane, levels[fine][0].chain,
                              levels[fine][0].eigen.at(plane).eigenvectors.col(i), stations,
                              statics, with_tension);
      if (plan.inextensible) {
        const Mode other = make_mode(plane, levels[fine][1].chain,
                                     levels[fine][1].eigen.at(plane).eigenvectors.col(match[fine][1][static_cast<std::size_t>(i)]),
                                     stations, statics, with_tension);
        extrapolate_mode_in_kappa(shaped, other);
      }
      mode.normalised_by = shaped.normalised_by;
      if (with_tension) mode.max_abs_tension_n = shaped.max_abs_tension_n;
      if (request.shapes) {
        mode.s_m = shaped.s_m;
        mode.u = shaped.u;
        mode.w = shaped.w;
        mode.v = shaped.v;
        if (with_tension) mode.tension_n = shaped.tension_n;
        mode.modal_mass_kg =
            plane == Plane::InPlane
                ? inplane_modal_mass(mode, problem.cable.mass_kg_per_m,
                                     problem.cable.normal_mass_kg_per_m())
                : outofplane_modal_mass(mode, problem.cable.normal_mass_kg_per_m());
      }
      result.modes.push_back(std::move(mode));
    }
    // Extrapolation may reorder two modes closer than their discretisation errors: report them
    // lowest first.
    std::stable_sort(result.modes.begin(), result.modes.end(),
                     [](const Mode& a, const Mode& b) { return a.omega_rad_s < b.omega_rad_s; });
    for (std::size_t i = 0; i < result.modes.size(); ++i) result.modes[i].index = static_cast<int>(i) + 1;
    timings.postprocessing_s += seconds_since(start_post);

    if (!has_coarse && !result.modes.empty()) {
      result.summary.warnings.push_back(fmt::format(
          "no error estimate: without Richardson the estimate needs N/2 = {} elements, too few for "
          "{} {} modes (relative_error_estimate = -1)",
          options.elements / 2, modes, plane_name(plane)));
    }
    const FeEigenSolution& finest = levels[fine][0].eigen.at(plane);
    result.proved_count_below_top = finest.inertia_count;
    bool all_proved = true;
    for (const auto& row : levels)
      for (const auto& level : row)
        all_proved = all_proved && level.eigen.at(plane).inertia_count ==
                                       static_cast<int>(level.eigen.at(plane).eigenvalues.size());
    if (available < modes) result.summary.termination = worse(result.summary.termination, Termination::NoConvergence);
    result.summary.resolution = summary.resolution;
    result.summary.notes.push_back(fmt::format(
        "mode count proved by Sylvester inertia: LDLT(K - sigma M) at sigma = {:.9e} rad^2/s^2 "
        "(just above the top eigenvalue, N = {}) has {} negative pivots for {} modes{}",
        finest.inertia_shift, plan.meshes[fine], finest.inertia_count,
        finest.eigenvalues.size(), all_proved ? "; same on every mesh" : "; NOT on every mesh"));
    result.summary.notes.push_back(fmt::format(
        "max mass-orthogonality error {:.2e} (M-normalised); max normwise backward error {:.2e} "
        "(the relative residual ||K phi - w^2 M phi|| / ||K phi|| has a rounding floor of about "
        "eps ||K|| / ||K phi||, large for a stiff chain)",
        plane_orthogonality, plane_backward));
    if (options.observed_order && !observed_orders.empty()) {
      std::string list;
      for (double p : observed_orders) list += fmt::format("{}{:.3f}", list.empty() ? "" : ", ", p);
      result.summary.notes.push_back(fmt::format(
          "observed order of the unextrapolated frequencies from N = {}, {}, {}: {}",
          plan.meshes[plan.meshes.size() - 3], plan.meshes[plan.meshes.size() - 2],
          plan.meshes.back(), list));
    }
    if (result.summary.termination == Termination::Converged) {
      result.summary.message = fmt::format(
          "Converged: {} of {} {} modes, max relative residual {:.1e} (normwise backward error "
          "{:.1e}), mode count proved by inertia ({}), max relative error estimate {:.1e}",
          available, modes, plane_name(plane), result.summary.max_residual, plane_backward,
          finest.inertia_count, result.summary.max_error_estimate);
    } else {
      result.summary.message = fmt::format(
          "No convergence: {} of {} {} modes ({})", available, modes, plane_name(plane),
          result.summary.warnings.empty() ? std::string("see warnings") : result.summary.warnings.back());
    }
    result.summary.wall_time_s = seconds_since(start_plane);
    max_residual = std::max(max_residual, result.summary.max_residual);
    summary.termination = worse(summary.termination, result.summary.termination);
    plane_messages.push_back(result.summary.message);
    if (plane == Plane::InPlane) {
      output.inplane = std::move(result);
    } else {
      output.outofplane = std::move(result);
    }
  }

  // Forced response on the finest main mesh (penalised: both kappas, extrapolated).
  if (request.forced) {
    const auto start_forced = Clock::now();
    const ForcedRequest& forced = *request.forced;
    const double s_end = forced.end == CableEnd::A ? 0.0 : problem.cable.length_m;
    Vec2 direction = Vec2(1.0, 0.0);
    switch (forced.direction) {
      case ForcingDirection::Tangential: direction = statics.tangent(s_end); break;
      case ForcingDirection::Normal: direction = statics.normal(s_end); break;
      case ForcingDirection::GivenVector: direction = forced.vector.normalized(); break;
      case ForcingDirection::OutOfPlane: break;  // amplitude carried in x
    }
    const Vec2 d = forced.amplitude_m * direction;
    const Vec2 end_a = forced.end == CableEnd::A ? d : Vec2::Zero();
    const Vec2 end_b = forced.end == CableEnd::B ? d : Vec2::Zero();
    const auto fine = static_cast<std::size_t>(plan.main_fine);
    // The coarse mesh of the pair (N when the result is on 2N) gives the error estimate: the
    // response converges as O(h^2), so |fine - coarse| bounds the fine mesh's error.
    const bool forced_has_coarse = plan.main_coarse >= 0;
    const auto coarse = static_cast<std::size_t>(std::max(0, plan.main_coarse));
    for (std::size_t level_index : {fine, coarse}) {
      if (level_index == coarse && !forced_has_coarse) continue;
      for (std::size_t k = 0; k < num_penalties; ++k) {
        Level& level = levels[level_index][k];
        if (!level.matrices.count(forced_plane)) {
          level.matrices[forced_plane] = forced_plane == Plane::InPlane ? assemble_inplane(level.chain)
                                                                        : assemble_outofplane(level.chain);
        }
      }
    }
    const std::optional<ModalResult>& modal = forced_out_of_plane ? output.outofplane : output.inplane;
    for (double omega : forced.omegas_rad_s) {
      ForcedResponse response;
      response.omega_rad_s = omega;
      response.s_m = stations;
      // A forcing frequency indistinguishable from a computed natural frequency (within that
      // frequency's own error estimate) has no meaningful finite answer.
      if (modal) {
        for (const Mode& mode : modal->modes) {
          const double window =
              std::max(1e-9, 3.0 * std::max(0.0, mode.relative_error_estimate)) * mode.omega_rad_s;
          if (std::abs(omega - mode.omega_rad_s) <= window) {
            response.diagnostic = fmt::format(
                "forcing at omega = {:.9g} rad/s is within {:.2e} rad/s of {} natural frequency {} "
                "({:.9g} rad/s, relative error estimate {:.1e}): resonance, no finite response",
                omega, std::abs(omega - mode.omega_rad_s), plane_name(forced_plane), mode.index,
                mode.omega_rad_s, mode.relative_error_estimate);
            break;
          }
        }
      }
      std::vector<RawForced> raw;
      if (response.diagnostic.empty()) {
        for (std::size_t k = 0; k < num_penalties; ++k) {
          raw.push_back(forced_on_level(forced_plane, levels[fine][k].chain,
                                        levels[fine][k].matrices.at(forced_plane), omega, end_a,
                                        end_b, stations, statics));
          if (!raw.back().ok) {
            response.diagnostic = raw.back().diagnostic;
            break;
          }
        }
      }
      if (response.diagnostic.empty()) {
        Sampled result = raw[0].sampled;
        if (plan.inextensible) {
          auto extrapolate = [](Vector& a, const Vector& b) {
            if (a.size() && a.size() == b.size()) a = 2.0 * a - b;
          };
          extrapolate(result.u, raw[1].sampled.u);
          extrapolate(result.w, raw[1].sampled.w);
          extrapolate(result.v, raw[1].sampled.v);
          extrapolate(result.tension, raw[1].sampled.tension);
        }
        response.u = result.u;
        response.w = result.w;
        response.v = result.v;
        response.tension_n = result.tension;
        response.max_abs_tension_n = result.tension.size() ? result.tension.cwiseAbs().maxCoeff() : 0.0;
        const double scale = std::max({response.u.size() ? response.u.cwiseAbs().maxCoeff() : 0.0,
                                       response.w.size() ? response.w.cwiseAbs().maxCoeff() : 0.0,
                                       response.v.size() ? response.v.cwiseAbs().maxCoeff() : 0.0});
        if (forced_has_coarse && response.max_abs_tension_n > 0.0) {
          // Same penalty as the result's first level: the estimate is of the mesh error.
          const RawForced coarse_raw = forced_on_level(forced_plane, levels[coarse][0].chain,
                                                       levels[coarse][0].matrices.at(forced_plane), omega,
                                                       end_a, end_b, stations, statics);
          const RawForced& fine_raw = raw[0];
          if (coarse_raw.ok && coarse_raw.sampled.tension.size()) {
            const double fine_max = fine_raw.sampled.tension.cwiseAbs().maxCoeff();
            const double coarse_max = coarse_raw.sampled.tension.cwiseAbs().maxCoeff();
            response.relative_error_estimate = std::abs(fine_max - coarse_max) / std::max(fine_max, 1e-300);
          }
        }
        if (!std::isfinite(scale) || !std::isfinite(response.max_abs_tension_n)) {
          response = ForcedResponse{};
          response.omega_rad_s = omega;
          response.s_m = stations;
          response.diagnostic = "non-finite response (resonance)";
        }
      }
      if (!response.diagnostic.empty()) summary.warnings.push_back(response.diagnostic);
      output.forced.push_back(std::move(response));
    }
    timings.forced_s += seconds_since(start_forced);
  }

  // Overall summary.
  std::string meshes;
  for (int N : plan.meshes) meshes += fmt::format("{}{}", meshes.empty() ? "" : ", ", N);
  summary.resolution = fmt::format("N = {} elements{}", meshes,
                                   plan.richardson ? ", Richardson (order 2 -> 4)" : ", no Richardson");
  if (plan.inextensible) {
    summary.resolution += fmt::format("; penalty kappa = {:.1e} and {:.1e}, extrapolated to 0",
                                      plan.kappas[0], plan.kappas[1]);
    summary.warnings.push_back(fmt::format(
        "inextensible cable: penalty EA = H/kappa = {:.4e} N and {:.4e} N (kappa = {:.1e}, {:.1e}), "
        "results extrapolated linearly to kappa = 0",
        plan.axial_stiffness_n[0], plan.axial_stiffness_n[1], plan.kappas[0], plan.kappas[1]));
  }
  if (output.inplane) output.inplane->summary.resolution = summary.resolution;
  if (output.outofplane) output.outofplane->summary.resolution = summary.resolution;
  summary.iterations = total_restarts;
  summary.operations = total_operations;
  summary.max_residual = planes.empty() ? -1.0 : max_residual;
  summary.max_error_estimate = planes.empty() ? -1.0 : max_error;
  const FeChain& finest_chain = levels[static_cast<std::size_t>(plan.main_fine)][0].chain;
  summary.notes.push_back(fmt::format(
      "discrete statics (N = {}): H = {:.12g} N, V_A = {:.12g} N, {} Newton iterations, closure "
      "{:.2e} m ({})",
      finest_chain.elements, finest_chain.horizontal_force_n, finest_chain.vertical_force_a_n,
      finest_chain.newton_iterations, finest_chain.closure_error_m,
      problem.prescribed_forces ? "prescribed end forces kept" : "Newton on the chain's closure"));
  summary.notes.push_back(fmt::format("max mass-orthogonality error {:.2e}", max_orthogonality));
  summary.notes.push_back(fmt::format(
      "time: statics {}, assembly {}, factorization {}, eigen iterations {}, shapes {}, forced {}",
      format_seconds(timings.statics_s), format_seconds(timings.assembly_s),
      format_seconds(timings.factorization_s), format_seconds(timings.eigen_iterations_s),
      format_seconds(timings.postprocessing_s), format_seconds(timings.forced_s)));
  for (const auto& plane_result : {&output.inplane, &output.outofplane}) {
    if (*plane_result) {
      for (const auto& note : (*plane_result)->summary.notes) summary.notes.push_back(note);
      for (const auto& warning : (*plane_result)->summary.warnings) summary.warnings.push_back(warning);
    }
  }
  if (planes.empty()) {
    summary.message = request.forced ? fmt::format("Converged: forced response at {} frequencies",
                                                   request.forced->omegas_rad_s.size())
                                     : std::string("Converged: nothing was asked");
  } else {
    summary.message.clear();
    for (const auto& message : plane_messages)
      summary.message += (summary.message.empty() ? "" : "; ") + message;
  }
  summary.wall_time_s = seconds_since(start_all);
  return output;
}

// Registry: the scene knobs `elements`, `richardson`, `kappa`, `observed_order`.
namespace {
FeSolverOptions read_options(const SolverKnobs& knobs) {
  KnobReader reader("fe", knobs);
  FeSolverOptions options;
  const long elements = reader.get_integer("elements", options.elements);
  if (elements < 2 || elements > 50'000'000)
    throw InvalidInput(fmt::format("{} = {}: must be in [2, 5e7]", reader.key("elements"), elements));
  options.elements = static_cast<int>(elements);
  options.richardson = reader.get_bool("richardson", options.richardson);
  options.observed_order = reader.get_bool("observed_order", options.observed_order);
  options.kappa = reader.get_double("kappa", options.kappa);
  if (!(options.kappa > 0.0) || !(options.kappa <= 1e-2))
    throw InvalidInput(fmt::format("{} = {}: must be in (0, 1e-2]", reader.key("kappa"), options.kappa));
  reader.reject_unknown();
  options.validate();
  return options;
}
}  // namespace

SolverEntry make_fe_entry() {
  SolverEntry entry;
  entry.name = "fe";
  entry.description =
      "lumped-mass chain of N bar elements about its own exact statics; sparse shift-invert "
      "eigensolver (Spectra), Sylvester-inertia mode count, Richardson N/2N extrapolation";
  entry.knobs = {
      {"elements", "number of bar elements N (coarse mesh with Richardson), >= 2, default 400"},
      {"richardson", "solve N and 2N and extrapolate (order 2 -> 4), default true"},
      {"kappa", "inextensible cables: penalty H/EA, in (0, 1e-2], default 1e-6 (and 2 kappa, "
                "extrapolated to 0)"},
      {"observed_order", "also solve 4N and report the observed convergence order, default false"},
  };
  entry.not_applicable_reason = [](const SolveContext&) -> std::optional<std::string> {
    return std::nullopt;
  };
  entry.validate_knobs = [](const SolverKnobs& knobs) { read_options(knobs); };
  entry.run = [](const SolveContext& context, const SolverKnobs& knobs) {
    return solve_fe(context.problem, context.statics, context.groups, context.request,
                    read_options(knobs));
  };
  return entry;
}

}  // namespace internal

SolverOutput solve_fe(const Problem& problem,
                      const StaticSolution& statics,
                      const DimensionlessGroups& groups,
                      const SolveRequest& request,
                      const FeSolverOptions& options) {
  internal::FeTimings timings;
  return internal::solve_fe_timed(problem, statics, groups, request, options, timings);
}

}  // namespace catena
