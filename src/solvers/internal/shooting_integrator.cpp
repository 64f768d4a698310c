#include "solvers/internal/shooting_integrator.hpp"

#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>
#include <fmt/format.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>

#include "solvers/internal/shooting_sundials_handles.hpp"

namespace catena::internal {

ShootingCoefficients ShootingCoefficients::from_statics(const StaticSolution& statics) {
  const CableProperties& cable = statics.cable();
  ShootingCoefficients c;
  c.length_m = cable.length_m;
  c.H = statics.horizontal_force_n();
  c.V_A = statics.vertical_force_a_n();
  c.W0 = cable.weight_n_per_m;
  c.compliance = cable.is_inextensible() ? 0.0 : 1.0 / cable.axial_stiffness_n;
  c.m = cable.mass_kg_per_m;
  c.M = cable.normal_mass_kg_per_m();
  c.t_ref = std::max(statics.tension_n(0.0), statics.tension_n(cable.length_m));
  return c;
}

double ShootingCoefficients::tension(double s) const { return std::hypot(H, V_A + W0 * s); }

Vec2 ShootingCoefficients::tangent(double s) const {
  const double V = V_A + W0 * s;
  const double T = std::hypot(H, V);
  return Vec2(H / T, V / T);
}

Vec2 ShootingCoefficients::normal(double s) const {
  const double V = V_A + W0 * s;
  const double T = std::hypot(H, V);
  return Vec2(-V / T, H / T);
}

double ShootingCoefficients::scaled_omega2(double omega_rad_s) const {
  return omega_rad_s * omega_rad_s * length_m * length_m * M / t_ref;
}

namespace {

template <int D>
using Basis = Eigen::Matrix<double, 2 * D, D>;
template <int D>
using Square = Eigen::Matrix<double, D, D>;

// Everything the C callbacks need (passed as CVODE user data).
struct RhsData {
  ShootingCoefficients coefficients;
  int dimension = 2;
  double omega2 = 0.0;  // scaled Omega^2
  // Symplectic rescaling Phi~ = kappa Phi^, F~ = F^ / kappa with kappa^2 = max(Omega, 1): it
  // balances B and C for the transverse wave, so that the phase turns at a nearly uniform rate
  // (a Pruefer angle of unbalanced variables turns in bursts and costs CVODE many steps).
  double kappa2 = 1.0;
  bool from_b = false;
};

// B and C of the scaled system at x (see the header). From b the variable is x' = 1 - s/L and the
// force is carried as -F^, which leaves the equations unchanged.
template <int D>
void coefficients_at(const RhsData& data, double x, Square<D>& B, Square<D>& C) {
  const ShootingCoefficients& k = data.coefficients;
  const double s = k.length_m * (data.from_b ? 1.0 - x : x);
  const double V = k.V_A + k.W0 * s;
  const double T = std::hypot(k.H, V);
  const double e = T * k.compliance;
  const double b_normal = k.t_ref * (1.0 + e) / T;
  if constexpr (D == 1) {
    B(0, 0) = data.kappa2 * b_normal;
    C(0, 0) = data.omega2 / data.kappa2;
  } else {
    const double b_tangent = k.t_ref * k.compliance;
    const Vec2 t(k.H / T, V / T);
    const Vec2 n(-t.y(), t.x());
    const double mass_ratio = k.m / k.M;
    B = data.kappa2 * (b_tangent * t * t.transpose() + b_normal * n * n.transpose());
    C = (data.omega2 / data.kappa2) * (mass_ratio * t * t.transpose() + n * n.transpose());
  }
}

template <int D>
int rhs(double x, N_Vector y, N_Vector ydot, void* user_data) {
  const auto& data = *static_cast<const RhsData*>(user_data);
  Eigen::Map<const Basis<D>> Y(N_VGetArrayPointer(y));
  Eigen::Map<Basis<D>> dY(N_VGetArrayPointer(ydot));
  Square<D> B, C;
  coefficients_at<D>(data, x, B, C);
  const auto Phi = Y.template topRows<D>();
  const auto F = Y.template bottomRows<D>();
  dY.template topRows<D>() = B * F;
  dY.template bottomRows<D>() = -C * Phi;
  // Phase theta = arg det(Phi + i F); its derivative is -tr(G^{-1} N) (header).
  const Square<D> G = Phi.transpose() * Phi + F.transpose() * F;
  const Square<D> N = Phi.transpose() * C * Phi + F.transpose() * B * F;
  N_VGetArrayPointer(ydot)[2 * D * D] = -(G.inverse() * N).trace();
  return 0;
}

// Analytic Jacobian of the linear part; the phase row is left zero (the phase feeds back into
// nothing, so the modified Newton iteration still converges for it).
template <int D>
int jacobian(
    double x, N_Vector, N_Vector, SUNMatrix J, void* user_data, N_Vector, N_Vector, N_Vector) {
  const auto& data = *static_cast<const RhsData*>(user_data);
  Square<D> B, C;
  coefficients_at<D>(data, x, B, C);
  SUNMatZero(J);
  for (int column = 0; column < D; ++column) {
    const int base = 2 * D * column;
    for (int r = 0; r < D; ++r) {
      for (int k = 0; k < D; ++k) {
        SM_ELEMENT_D(J, base + r, base + D + k) = B(r, k);
        SM_ELEMENT_D(J, base + D + r, base + k) = -C(r, k);
      }
    }
  }
  return 0;
}

// Eigen-angles of U = conj(Z) Z^{-1}, Z = Phi + i F, mapped to [pi, 3 pi), ascending.
// The quadratic formula on U loses half the digits at a double eigenvalue (a double root of the
// cable), so the angles come from a real symmetric matrix instead: with e^{i beta} Z = P + i Q,
// U = e^{2 i beta} (V - i)(V + i)^{-1}, V = P Q^{-1} symmetric, and each eigenvalue nu of V gives
// alpha = 2 beta - 2 atan2(1, nu). beta is chosen from {0, pi/4, pi/2, 3 pi/4} to make Q best
// conditioned; the symmetric eigenproblem is then accurate to rounding.
template <int D>
Eigen::Matrix<double, D, 1> unitary_angles(const Square<D>& Phi, const Square<D>& F) {
  // Into [pi - delta, 3 pi - delta). An angle at pi to rounding is one that has not moved (the
  // tangential angle of a nearly straight inextensible cable barely leaves pi, where every angle
  // starts): it must count as not yet crossed. The shift delta moves the count threshold of a
  // genuine crossing by 1e-12 rad, far inside the root brackets, which use the determinant.
  constexpr double kDelta = 1e-12;
  auto to_range = [](double alpha) {
    while (alpha < kPi - kDelta) alpha += 2.0 * kPi;
    while (alpha >= 3.0 * kPi - kDelta) alpha -= 2.0 * kPi;
    return alpha;
  };
  Eigen::Matrix<double, D, 1> angles;
  if constexpr (D == 1) {
    angles(0) = to_range(-2.0 * std::atan2(F(0, 0), Phi(0, 0)));
  } else {
    double best_quality = -1.0, best_beta = 0.0;
    const double scale = Phi.squaredNorm() + F.squaredNorm();
    for (int k = 0; k < 4; ++k) {
      const double beta = 0.25 * kPi * k;
      const Square<D> Q = std::sin(beta) * Phi + std::cos(beta) * F;
      const double quality = std::abs(Q.determinant()) / scale;
      if (quality > best_quality) {
        best_quality = quality;
        best_beta = beta;
      }
    }
    const Square<D> best_P = std::cos(best_beta) * Phi - std::sin(best_beta) * F;
    const Square<D> best_Q = std::sin(best_beta) * Phi + std::cos(best_beta) * F;
    Square<D> V = best_P * best_Q.inverse();
    V = 0.5 * (V + V.transpose()).eval();
    const Eigen::SelfAdjointEigenSolver<Square<D>> eig(V, Eigen::EigenvaluesOnly);
    for (int j = 0; j < D; ++j) {
      angles(j) = to_range(2.0 * best_beta - 2.0 * std::atan2(1.0, eig.eigenvalues()(j)));
    }
    if (angles(0) > angles(1)) std::swap(angles(0), angles(1));
  }
  return angles;
}

template <int D>
double phase_of(const Square<D>& Phi, const Square<D>& F) {
  using Complex = std::complex<double>;
  if constexpr (D == 1) {
    return std::arg(Complex(Phi(0, 0), F(0, 0)));
  } else {
    const Eigen::Matrix<Complex, 2, 2> Z =
        Phi.template cast<Complex>() + Complex(0.0, 1.0) * F.template cast<Complex>();
    return std::arg(Z.determinant());
  }
}

}  // namespace

struct ShootingIntegrator::Impl {
  Impl(Plane plane, const ShootingCoefficients& coefficients, const IntegratorSettings& s)
      : settings(s),
        dimension(plane == Plane::InPlane ? 2 : 1),
        state_size(2 * dimension * dimension + 1),
        y(state_size, context.get()),
        scratch(state_size, context.get()),
        matrix(SUNDenseMatrix(state_size, state_size, context.get())),
        linear_solver(SUNLinSol_Dense(y.get(), matrix.get(), context.get())),
        nonlinear_solver(s.fixed_point ? SUNNonlinSol_FixedPoint(y.get(), 0, context.get())
                                       : nullptr),
        cvode(s.use_bdf ? CV_BDF : CV_ADAMS, context.get()) {
    data.coefficients = coefficients;
    data.dimension = dimension;
    if (!context.ok() || !y.ok() || !scratch.ok() || !matrix.ok() || !linear_solver.ok() ||
        !cvode.ok()) {
      throw ShootingFailure("could not allocate the SUNDIALS objects");
    }
    N_VConst(0.0, y.get());
    check(CVodeInit(cvode.get(), dimension == 2 ? rhs<2> : rhs<1>, 0.0, y.get()), "CVodeInit");
    check(CVodeSetUserData(cvode.get(), &data), "CVodeSetUserData");
    if (settings.fixed_point) {
      // Functional iteration (no Jacobian, no linear solve): the system is not stiff.
      if (!nonlinear_solver.get())
        throw ShootingFailure("could not allocate SUNNonlinSol_FixedPoint");
      check(CVodeSetNonlinearSolver(cvode.get(), nonlinear_solver.get()),
            "CVodeSetNonlinearSolver");
    } else {
      check(CVodeSetLinearSolver(cvode.get(), linear_solver.get(), matrix.get()),
            "CVodeSetLinearSolver");
      check(CVodeSetJacFn(cvode.get(), dimension == 2 ? jacobian<2> : jacobian<1>),
            "CVodeSetJacFn");
    }
    check(CVodeSetMaxNumSteps(cvode.get(), settings.max_steps), "CVodeSetMaxNumSteps");
  }

  void check(int flag, const char* call, double x = 0.0) const {
    if (flag < 0) {
      throw ShootingFailure(
          fmt::format("{} returned {} ({}) at s/L = {:.6g}", call, cvode_flag_name(flag), flag, x));
    }
  }

  template <int D>
  Shot shoot(double omega,
             double tolerance_factor,
             const std::vector<double>* stations,
             bool from_b);

  IntegratorSettings settings;
  int dimension;
  sunindextype state_size;
  // Declaration order = construction order; destruction runs in reverse (cvode first).
  SundialsContext context;
  SerialVector y;
  SerialVector scratch;
  SundialsMatrix matrix;
  SundialsLinearSolver linear_solver;
  SundialsNonlinearSolver nonlinear_solver;
  CvodeMemory cvode;
  RhsData data;
  long total_steps = 0;
  long total_rhs = 0;
  long total_reorthonormalisations = 0;
  double max_log_growth = 0.0;
};

template <int D>
Shot ShootingIntegrator::Impl::shoot(double omega,
                                     double tolerance_factor,
                                     const std::vector<double>* stations,
                                     bool from_b) {
  Shot shot;
  shot.omega_rad_s = omega;
  data.omega2 = data.coefficients.scaled_omega2(omega);
  data.kappa2 = settings.balance ? std::max(std::sqrt(data.omega2), 1.0) : 1.0;
  data.from_b = from_b;
  const double kappa = std::sqrt(data.kappa2);

  double* state = y.data();
  Eigen::Map<Basis<D>> Y(state);
  Y.setZero();
  Y.template bottomRows<D>().setIdentity();
  state[2 * D * D] = (D == 2) ? kPi : 0.5 * kPi;  // arg det(i I)

  void* mem = cvode.get();
  const double rtol = settings.relative_tolerance * tolerance_factor;
  const double atol = settings.absolute_tolerance * tolerance_factor;
  double x = 0.0;
  check(CVodeReInit(mem, 0.0, y.get()), "CVodeReInit");
  {
    // The phase only has to be right to well within pi (it fixes the winding; the fractional
    // part comes from arg det Z at the end), so its absolute tolerance is looser: 1e-6 rad per
    // step. Tight control of it cost ~20% more steps for nothing.
    N_VConst(atol, scratch.get());
    scratch.data()[2 * D * D] = std::max(atol, 1e-6);
    check(CVodeSVtolerances(mem, rtol, scratch.get()), "CVodeSVtolerances");
  }
  check(CVodeSetStopTime(mem, 1.0), "CVodeSetStopTime");

  std::size_t next_station = 0;
  const std::size_t num_stations = stations ? stations->size() : 0;
  auto record = [&](const Basis<D>& basis) {
    Basis<D> out = basis;
    // Undo the rescaling; from b the force was carried as -F^.
    out.template topRows<D>() /= kappa;
    out.template bottomRows<D>() *= from_b ? -kappa : kappa;
    shot.station_y.emplace_back(out);
    shot.station_segment.push_back(static_cast<int>(shot.segment_r.size()));
  };
  while (next_station < num_stations && (*stations)[next_station] <= 0.0) {
    record(Y);
    ++next_station;
  }

  long steps_before = 0, rhs_before = 0;
  long steps_this_segment = 0, rhs_this_segment = 0;
  long steps_total = 0;
  while (x < 1.0) {
    const int flag = CVode(mem, 1.0, y.get(), &x, CV_ONE_STEP);
    check(flag, "CVode", from_b ? 1.0 - x : x);
    ++steps_total;
    if (steps_total > settings.max_steps) {
      throw ShootingFailure(fmt::format("more than {} CVODE steps (max_steps) at s/L = {:.6g}",
                                        settings.max_steps, from_b ? 1.0 - x : x));
    }
    // Stations passed by this step, from CVODE's interpolant.
    while (next_station < num_stations && (*stations)[next_station] <= x) {
      const double xs = (*stations)[next_station];
      if (xs >= x) {
        record(Y);
      } else {
        check(CVodeGetDky(mem, xs, 0, scratch.get()), "CVodeGetDky", xs);
        record(Eigen::Map<const Basis<D>>(scratch.data()));
      }
      ++next_station;
    }
    if (x >= 1.0) break;
    // Loss of independence / growth guard.
    const Square<D> G = Y.transpose() * Y;
    bool restart = false;
    if constexpr (D == 2) {
      const Eigen::SelfAdjointEigenSolver<Square<D>> eig(G, Eigen::EigenvaluesOnly);
      const double lo = eig.eigenvalues()(0), hi = eig.eigenvalues()(1);
      restart = !(lo > 0.0) || hi > settings.max_condition * lo || hi > 1e6 || lo < 1e-6;
    } else {
      restart = G(0, 0) > 1e6 || G(0, 0) < 1e-6;
    }
    if (restart) {
      const Eigen::HouseholderQR<Basis<D>> qr(Y);
      Square<D> R = qr.matrixQR().template topRows<D>().template triangularView<Eigen::Upper>();
      Basis<D> Q = qr.householderQ() * Basis<D>::Identity();
      for (int j = 0; j < D; ++j) {
        if (R(j, j) < 0.0) {
          R.row(j) *= -1.0;
          Q.col(j) *= -1.0;
        }
      }
      if (!(R.diagonal().minCoeff() > 0.0)) {
        throw ShootingFailure(
            fmt::format("principal solutions became dependent at s/L = {:.6g}", x));
      }
      Y = Q;
      shot.log_growth += R.diagonal().array().log().sum();
      shot.segment_r.emplace_back(R);
      long steps = 0, evaluations = 0;
      CVodeGetNumSteps(mem, &steps);
      CVodeGetNumRhsEvals(mem, &evaluations);
      steps_before += steps;
      rhs_before += evaluations;
      check(CVodeReInit(mem, x, y.get()), "CVodeReInit", x);
      check(CVodeSetStopTime(mem, 1.0), "CVodeSetStopTime");
    }
  }
  CVodeGetNumSteps(mem, &steps_this_segment);
  CVodeGetNumRhsEvals(mem, &rhs_this_segment);
  shot.steps = steps_before + steps_this_segment;
  shot.rhs_evaluations = rhs_before + rhs_this_segment;
  for (; next_station < num_stations; ++next_station) record(Y);

  Basis<D> end = Y;
  end.template topRows<D>() /= kappa;
  end.template bottomRows<D>() *= from_b ? -kappa : kappa;
  shot.y_end = end;
  // Count and determinant use the carried (Hamiltonian-form) basis Y.
  const Square<D> Phi = Y.template topRows<D>();
  const Square<D> F = Y.template bottomRows<D>();
  const Square<D> G = Phi.transpose() * Phi + F.transpose() * F;
  shot.determinant = Phi.determinant() / std::sqrt(G.determinant());
  const double theta_integrated = state[2 * D * D];
  const double theta_mod = phase_of<D>(Phi, F);
  const double winding = std::round((theta_integrated - theta_mod) / (2.0 * kPi));
  const double theta = theta_mod + 2.0 * kPi * winding;
  shot.phase_defect = std::abs(theta_integrated - theta);
  const double total_alpha = 2.0 * kPi * D - 2.0 * theta;
  const Eigen::Matrix<double, D, 1> angles = unitary_angles<D>(Phi, F);
  const double count = (total_alpha - angles.sum()) / (2.0 * kPi);
  shot.count = static_cast<int>(std::lround(count));
  shot.angle_min = angles(0);
  shot.angle_max = angles(D - 1);

  total_steps += shot.steps;
  total_rhs += shot.rhs_evaluations;
  total_reorthonormalisations += static_cast<long>(shot.segment_r.size());
  max_log_growth = std::max(max_log_growth, shot.log_growth);
  return shot;
}

ShootingIntegrator::ShootingIntegrator(Plane plane,
                                       const ShootingCoefficients& coefficients,
                                       const IntegratorSettings& settings)
    : impl_(std::make_unique<Impl>(plane, coefficients, settings)) {}

ShootingIntegrator::~ShootingIntegrator() = default;

Shot ShootingIntegrator::shoot(double omega_rad_s,
                               double tolerance_factor,
                               const std::vector<double>* stations_x,
                               bool from_b) {
  if (impl_->dimension == 2)
    return impl_->shoot<2>(omega_rad_s, tolerance_factor, stations_x, from_b);
  return impl_->shoot<1>(omega_rad_s, tolerance_factor, stations_x, from_b);
}

long ShootingIntegrator::total_steps() const { return impl_->total_steps; }
long ShootingIntegrator::total_rhs_evaluations() const { return impl_->total_rhs; }
long ShootingIntegrator::total_reorthonormalisations() const {
  return impl_->total_reorthonormalisations;
}
double ShootingIntegrator::max_log_growth() const { return impl_->max_log_growth; }

Eigen::VectorXd combine_at_station(const Shot& shot, std::size_t j, const Eigen::VectorXd& c) {
  // c belongs to the last segment; segment k-1's coefficients are R_k^{-1} c_k.
  Eigen::VectorXd coefficients = c;
  const int segment = shot.station_segment[j];
  for (int k = static_cast<int>(shot.segment_r.size()); k > segment; --k) {
    const Eigen::MatrixXd& R = shot.segment_r[static_cast<std::size_t>(k - 1)];
    coefficients = R.triangularView<Eigen::Upper>().solve(coefficients);
  }
  return shot.station_y[j] * coefficients;
}

}  // namespace catena::internal
