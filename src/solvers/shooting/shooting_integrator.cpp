// SPDX-License-Identifier: MIT
#include "solvers/shooting/shooting_integrator.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>

#include "solvers/shooting/shooting_conjugate_count.hpp"
#include "solvers/shooting/shooting_grounded.hpp"
#include "solvers/shooting/shooting_shot_setup.hpp"
#include "solvers/shooting/shooting_steppers.hpp"
#include "solvers/shooting/shooting_sundials_handles.hpp"

namespace catena::internal {

namespace {

// [Phi^; F^] of the carried basis [Phi~; F~]: undoes the balancing and the axial frame; from b
// the force was carried as -F^.
template <int D>
Basis<D> to_physical(const Basis<D>& carried, const RhsData& data) {
  const double kappa = std::sqrt(data.kappa2);
  Basis<D> out = carried;
  out.template topRows<D>() /= kappa;
  out.template bottomRows<D>() *= data.from_b ? -kappa : kappa;
  if constexpr (D == 2) {
    out.template topRows<D>() = data.to_axial_force.transpose() * out.template topRows<D>();
    out.template bottomRows<D>() = data.to_axial.transpose() * out.template bottomRows<D>();
  }
  return out;
}

// The carried basis [Phi~; F~] of a physical one [Phi^; F^] shot from a (the inverse of
// to_physical): Phi~ = kappa P Phi^, F~ = P^{-T} F^ / kappa.
template <int D>
Basis<D> to_carried(const Basis<D>& physical, const RhsData& data) {
  const double kappa = std::sqrt(data.kappa2);
  Basis<D> out = physical;
  if constexpr (D == 2) {
    out.template topRows<D>() = data.to_axial * physical.template topRows<D>();
    out.template bottomRows<D>() = data.to_axial_force * physical.template bottomRows<D>();
  }
  out.template topRows<D>() *= kappa;
  out.template bottomRows<D>() /= kappa;
  return out;
}

// The basis at the requested stations of one shot, unscaled, with the segment each belongs to.
template <int D>
class StationRecorder {
 public:
  StationRecorder(Shot& shot, const std::vector<double>* stations, const RhsData& data)
      : shot_(shot), stations_(stations), data_(data) {}

  /// Whether the next station lies at or before x.
  bool next_at_or_before(double x) const {
    return stations_ && next_ < stations_->size() && (*stations_)[next_] <= x;
  }
  double next_station() const { return (*stations_)[next_]; }

  /// Records `basis` at the next station.
  void record(const Basis<D>& basis) {
    shot_.station_y.emplace_back(to_physical<D>(basis, data_));
    shot_.station_segment.push_back(static_cast<int>(shot_.segment_r.size()));
    ++next_;
  }

  /// Records `basis` at every station left (those at the far end).
  void record_rest(const Basis<D>& basis) {
    while (stations_ && next_ < stations_->size()) record(basis);
  }

 private:
  Shot& shot_;
  const std::vector<double>* stations_;
  const RhsData& data_;
  std::size_t next_ = 0;
};

// Whether the basis has lost independence (cond(G) > max_condition) or left the scale
// [1e-6, 1e6], so that it must be re-orthonormalised.
template <int D>
bool needs_restart(const Basis<D>& Y, double max_condition) {
  const Square<D> G = Y.transpose() * Y;
  if constexpr (D == 2) {
    // The eigenvalues of the symmetric 2x2 G in closed form (checked after every step); the
    // smaller from det G / the larger, which keeps its relative accuracy.
    const double half_difference = 0.5 * (G(0, 0) - G(1, 1));
    const double hi = 0.5 * (G(0, 0) + G(1, 1)) + std::hypot(half_difference, G(0, 1));
    const double lo = (G(0, 0) * G(1, 1) - G(0, 1) * G(1, 0)) / hi;
    return !(lo > 0.0) || hi > max_condition * lo || hi > 1e6 || lo < 1e-6;
  } else {
    return G(0, 0) > 1e6 || G(0, 0) < 1e-6;
  }
}

// Replaces Y by the Q of Y = Q R with positive diagonal R (det R > 0: the sign of det Phi and the
// phase are unchanged) and returns R.
template <int D>
Square<D> orthonormalise(Eigen::Map<Basis<D>>& Y, double x) {
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
    throw ShootingFailure(fmt::format("principal solutions became dependent at s/L = {:.6g}", x));
  }
  Y = Q;
  return R;
}

// The point's inertia jump in the carried variables: F~ -> F~ - K Phi~ with
// K = Q J Q^T / kappa^2, J = Omega^2 Mp / (L M) (the scaled F^ jumps by -J Phi^; from b the
// carried -F^ jumps the same way). Returns K (symmetric, >= 0).
template <int D>
Square<D> point_jump(const RhsData& data, const ShootingPoint& point) {
  const ShootingCoefficients& k = data.coefficients;
  const double scale = data.omega2 / (k.length_m * k.M * data.kappa2);
  Square<D> K;
  if constexpr (D == 1) {
    K(0, 0) = scale * point.mass_outofplane;
  } else {
    const Vec2 n(-point.t.y(), point.t.x());
    const Vec2 tq = data.to_axial_force * point.t, nq = data.to_axial_force * n;
    K = scale *
        (point.mass_tangential * tq * tq.transpose() + point.mass_normal * nq * nq.transpose());
  }
  return K;
}

// Applies the jump F -> F - K Phi to the carried basis and returns the exact change of the phase
// theta = arg det(Phi + i F): det Z' = det Z prod_j (1 - i mu_j), mu_j the eigenvalues of
// Z^{-1} K Phi; along F - tau K Phi (tau from 0 to 1) no factor vanishes (Z stays invertible), so
// each turns by the principal arg of its end value. The change is <= 0: the jump adds conjugate
// points as the continuous mass does.
template <int D>
double apply_jump(Eigen::Map<Basis<D>>& Y, const Square<D>& K) {
  using Complex = std::complex<double>;
  using ComplexSquare = Eigen::Matrix<Complex, D, D>;
  const Square<D> Phi = Y.template topRows<D>();
  const ComplexSquare Z = Phi.template cast<Complex>() +
                          Complex(0.0, 1.0) * Y.template bottomRows<D>().template cast<Complex>();
  const ComplexSquare A = Z.inverse() * (K * Phi).template cast<Complex>();
  Eigen::Matrix<Complex, D, 1> mu;
  if constexpr (D == 1) {
    mu(0) = A(0, 0);
  } else {
    mu = Eigen::ComplexEigenSolver<ComplexSquare>(A, false).eigenvalues();
  }
  double change = 0.0;
  for (int j = 0; j < D; ++j) change += std::arg(Complex(1.0, 0.0) - Complex(0.0, 1.0) * mu(j));
  Y.template bottomRows<D>() -= K * Phi;
  return change;
}

}  // namespace

struct ShootingIntegrator::Impl {
  Impl(Plane plane, const ShootingCoefficients& coefficients, const IntegratorSettings& s)
      : settings(s), dimension(plane == Plane::InPlane ? 2 : 1) {
    data.coefficients = coefficients;
    data.coefficients.pieces = coefficients.all_pieces();
    data.dimension = dimension;
    if (dimension == 2) set_axial_frame(data.coefficients, data);
    if (!context.ok()) throw ShootingFailure("could not allocate the SUNDIALS objects");
    plain = make_stepper(false);
    stepper = plain.get();
    const std::size_t run = grounded_run_length(data.coefficients, dimension);
    if (run > 0) {
      grounded =
          std::make_unique<GroundedRun>(data.coefficients, dimension, run, settings.max_steps);
    }
  }

  // The stepper of the plain shot (Y and the phase) or of the shot with the frequency
  // derivative (Y, the phase and the scaled derivative of Y: header, "Frequency derivative").
  std::unique_ptr<ShotStepper> make_stepper(bool slope) {
    return make_shot_stepper(settings, context.get(), dimension, slope, data);
  }

  template <int D>
  Shot shoot(double omega,
             double tolerance_factor,
             const std::vector<double>* stations,
             bool from_b,
             bool slope);
  template <int D>
  void begin_shot(double omega, double tolerance_factor, bool from_b, bool slope);
  template <int D>
  void integrate(Shot& shot, StationRecorder<D>& recorder, bool from_b);
  template <int D>
  void record_passed_stations(StationRecorder<D>& recorder, double x, bool before_x_only = false);
  template <int D>
  void restart(Shot& shot, double x);
  template <int D>
  void finish_shot(Shot& shot);
  template <int D>
  void set_slopes(Shot& shot, const Square<D>& Phi, const Square<D>& F) const;
  template <int D>
  void cross_break(double x);
  template <int D>
  double shoot_grounded(Shot& shot, StationRecorder<D>& recorder);
  template <int D>
  void set_grounded_state(const GroundedFrame& frame, Shot& shot, Eigen::VectorXd& pushed);
  double stop_time() const { return next_break < breaks.size() ? breaks[next_break].x : 1.0; }

  IntegratorSettings settings;
  int dimension;
  // Declaration order = construction order; destruction runs in reverse (steppers first).
  SundialsContext context;
  RhsData data;  // the steppers' right-hand sides point to it
  std::unique_ptr<ShotStepper> plain;
  std::unique_ptr<ShotStepper> with_slope;  // made at the first shot that asks for the slope
  ShotStepper* stepper = nullptr;           // the stepper of the current shot
  std::vector<Break> breaks;                // of the current shot, in the order of integration
  std::size_t next_break = 0;
  // The seabed part of a shot from A (shooting_grounded.hpp); null when the line starts off it.
  std::unique_ptr<GroundedRun> grounded;
  bool grounded_shot = false;  // this shot starts with the grounded run
  bool slope_shot = false;     // this shot carries the frequency derivative
  long total_steps = 0;
  long total_rhs = 0;
  long total_reorthonormalisations = 0;
  double max_log_growth = 0.0;
};

// Sets the frequency and the balancing, starts the principal solutions at Phi = 0, F = I and
// starts the stepper with the tolerances scaled by `tolerance_factor`.
template <int D>
void ShootingIntegrator::Impl::begin_shot(double omega,
                                          double tolerance_factor,
                                          bool from_b,
                                          bool slope) {
  grounded_shot = grounded && !from_b;
  // The slope is carried on the general shot only (not through the grounded run), and only where
  // it is defined (w > 0) and asked for without stations.
  slope_shot = slope && !grounded_shot && omega > 0.0;
  if (slope_shot && !with_slope) with_slope = make_stepper(true);
  stepper = slope_shot ? with_slope.get() : plain.get();
  data.omega2 = data.coefficients.scaled_omega2(omega);
  set_balance(data.coefficients, std::sqrt(data.omega2), settings.balance, data);
  data.from_b = from_b;
  data.piece = from_b ? data.coefficients.pieces.size() - 1 : 0;
  breaks = breaks_of(data.coefficients, from_b);
  next_break = 0;
  double* state = stepper->state();
  Eigen::Map<Basis<D>> Y(state);
  Y.setZero();
  Y.template bottomRows<D>().setIdentity();
  state[2 * D * D] = initial_phase(D);
  const double rtol = settings.relative_tolerance * tolerance_factor;
  const double atol = settings.absolute_tolerance * tolerance_factor;
  if (slope_shot) {
    Eigen::Map<Basis<D>>(state + 2 * D * D + 1).setZero();
    data.slope_scale = std::max(atol, 1e-3 * rtol) / (kSlopeAccuracy * data.kappa2);
  }
  if (grounded_shot) {
    // The grounded run's columns start as F^ = I in the physical variables: in the carried ones
    // F~ = Q / kappa (det > 0, so the sign of det Phi and the phase are those of F~ = I).
    Y.template bottomRows<D>() = to_carried<D>(Basis<D>(Y), data).template bottomRows<D>();
    grounded->begin(data.omega2, rtol, atol);
  }
  // The phase only has to be right to well within pi (it fixes the winding; the fractional part
  // comes from arg det Z at the end), so its absolute tolerance is looser: 1e-6 rad per step.
  // Tight control of it cost ~20% more steps for nothing.
  data.rtol = rtol;
  data.atol = atol;
  data.atol_phase = std::max(atol, 1e-6);
  stepper->begin(rtol, atol, data.atol_phase, stop_time());
}

// Stations passed by the last step (ending at x), from the stepper's interpolant.
template <int D>
void ShootingIntegrator::Impl::record_passed_stations(StationRecorder<D>& recorder,
                                                      double x,
                                                      bool before_x_only) {
  while (recorder.next_at_or_before(x) && !(before_x_only && recorder.next_station() >= x)) {
    const double xs = recorder.next_station();
    if (xs >= x) {
      recorder.record(Eigen::Map<const Basis<D>>(stepper->state()));
    } else {
      // Room for the longer state of a slope shot; only Y (its head) is recorded.
      Eigen::Matrix<double, 4 * D * D + 1, 1> state;
      stepper->state_at(xs, state.data());
      recorder.record(Eigen::Map<const Basis<D>>(state.data()));
    }
  }
}

// Re-orthonormalises the basis at x, keeps R, and restarts the stepper there.
template <int D>
void ShootingIntegrator::Impl::restart(Shot& shot, double x) {
  Eigen::Map<Basis<D>> Y(stepper->state());
  const Square<D> R = orthonormalise<D>(Y, x);
  if (slope_shot) {
    // The slope of Y R0^{-1} for the constant R0 = R: the normalised determinant and the angles
    // are those of Y, so their slopes are too.
    Eigen::Map<Basis<D>> S(stepper->state() + 2 * D * D + 1);
    S = (S * R.inverse()).eval();
  }
  shot.log_growth += R.diagonal().array().log().sum();
  shot.segment_r.emplace_back(R);
  stepper->restart(x, stop_time());
}

// A break of a general line reached at x: the next piece's coefficients, the point's jump of the
// internal force (D continuous) with the phase carried across exactly, and the stepper restarted.
template <int D>
void ShootingIntegrator::Impl::cross_break(double x) {
  const Break& b = breaks[next_break++];
  data.piece = b.next_piece;
  double* state = stepper->state();
  if (b.point >= 0) {
    Eigen::Map<Basis<D>> Y(state);
    const Square<D> K =
        point_jump<D>(data, data.coefficients.points[static_cast<std::size_t>(b.point)]);
    if (slope_shot) {
      // K is proportional to w^2: S_F -> S_F - K S_Phi - 2 c K Phi (Phi is continuous).
      Eigen::Map<Basis<D>> S(state + 2 * D * D + 1);
      S.template bottomRows<D>() -=
          K * S.template topRows<D>() + (2.0 * data.slope_scale) * K * Y.template topRows<D>();
    }
    state[2 * D * D] += apply_jump<D>(Y, K);
  }
  stepper->restart(x, stop_time());
}

// The grounded run's frame as the carried state: the growth since the last R factor goes into
// new diagonal R factors (each at most e^600, so that they stay finite; the grounded columns grow
// by up to e^20000 on a stiff foundation), the unit columns become the carried basis, and the
// phase is the one whose count formula gives the run's count (the count is the same in every
// frame: it counts the zeros of det Phi).
template <int D>
void ShootingIntegrator::Impl::set_grounded_state(const GroundedFrame& frame,
                                                  Shot& shot,
                                                  Eigen::VectorXd& pushed) {
  constexpr double kLargestLogFactor = 600.0;
  Eigen::VectorXd growth = frame.log_scale - pushed;
  pushed = frame.log_scale;
  shot.log_growth += growth.sum();
  // Bounded memory whoever calls (the solver declines such a foundation before any shot).
  if (!(growth.cwiseAbs().maxCoeff() <= kMaxGroundedEfolds)) {
    throw ShootingFailure(fmt::format(
        "the seabed foundation's solution grows by {:.3g} e-folds on the grounded run, more than "
        "the {:.0e} a shot carries: [seabed] stiffness too large",
        growth.cwiseAbs().maxCoeff(), kMaxGroundedEfolds));
  }
  do {
    const Eigen::VectorXd step = growth.cwiseMax(-kLargestLogFactor).cwiseMin(kLargestLogFactor);
    shot.segment_r.emplace_back(step.array().exp().matrix().asDiagonal());
    growth -= step;
  } while (growth.cwiseAbs().maxCoeff() > 0.0);
  Basis<D> physical = Basis<D>::Zero();
  for (int j = 0; j < D; ++j) {
    physical(j, j) = frame.phi(j);
    physical(D + j, j) = frame.force(j);
  }
  Eigen::Map<Basis<D>> Y(stepper->state());
  Y = to_carried<D>(physical, data);
  const Square<D> Phi = Y.template topRows<D>(), F = Y.template bottomRows<D>();
  // The count formula fixes the phase only modulo pi (the unitary angles give 2 theta): the phase
  // carried is the value of arg det(Phi + i F) nearest to it, so that phase and basis agree to
  // rounding. They differ by pi only where a column's displacement is zero to rounding at the
  // run's end (the run counts that zero, the basis's sign may not): the end is then a root, on
  // whichever side of it the count falls. Taking the formula's value there left a phase defect of
  // pi, a re-shot and an off-by-one count at the tightened estimate shot (a line entirely on the
  // seabed, mode 5: estimate 7e-2 for a root right to 1e-13).
  const double from_count = kPi * (D - frame.count) - 0.5 * unitary_angles<D>(Phi, F).sum();
  const double modulo = frame_phase<D>(Phi, F);
  stepper->state()[2 * D * D] =
      modulo + 2.0 * kPi * std::round((from_count - modulo) / (2.0 * kPi));
}

// The grounded run from x = 0 to its end, recording the stations on it; the stepper restarted
// there on the next piece. Returns the x where the run ended.
template <int D>
double ShootingIntegrator::Impl::shoot_grounded(Shot& shot, StationRecorder<D>& recorder) {
  const double end = grounded->end_x();
  Eigen::VectorXd pushed = Eigen::VectorXd::Zero(D);
  const Eigen::Map<const Basis<D>> Y(stepper->state());
  while (recorder.next_at_or_before(end)) {
    set_grounded_state<D>(grounded->advance_to(recorder.next_station()), shot, pushed);
    recorder.record(Y);
  }
  set_grounded_state<D>(grounded->advance_to(end), shot, pushed);
  next_break = grounded->pieces();
  if (end >= 1.0) return 1.0;
  data.piece = next_break;
  stepper->restart(end, stop_time());
  return end;
}

// The stepper one step at a time from x = 0 to 1, recording stations and guarding independence.
template <int D>
void ShootingIntegrator::Impl::integrate(Shot& shot, StationRecorder<D>& recorder, bool from_b) {
  const Eigen::Map<const Basis<D>> Y(stepper->state());
  long steps_total = 0;
  double x = grounded_shot ? shoot_grounded<D>(shot, recorder) : 0.0;
  while (x < 1.0) {
    x = stepper->step(stop_time());
    if (++steps_total > settings.max_steps) {
      throw ShootingFailure(
          fmt::format("more than {} integration steps (max_steps) at s/L = {:.6g}",
                      settings.max_steps, from_b ? 1.0 - x : x));
    }
    // A station on a break gets the state on its b side, where the coefficients' tangent and
    // force are taken (ShootingCoefficients::piece_at): shot from a, it is recorded after the
    // point's jump, from the next step's interpolant.
    const bool at_break = next_break < breaks.size() && x >= breaks[next_break].x;
    record_passed_stations(recorder, x, at_break && !from_b);
    if (x >= 1.0) break;
    if (at_break) cross_break<D>(x);
    if (needs_restart<D>(Y, settings.max_condition)) restart<D>(shot, x);
  }
  shot.steps = stepper->steps();
  shot.rhs_evaluations = stepper->rhs_evaluations();
  if (grounded_shot) {
    shot.steps += grounded->steps();
    shot.rhs_evaluations += grounded->rhs_evaluations();
  }
}

// The unscaled end basis, the count and the determinant of the shot, and the running totals.
template <int D>
void ShootingIntegrator::Impl::finish_shot(Shot& shot) {
  const double* state = stepper->state();
  const Eigen::Map<const Basis<D>> Y(state);
  shot.y_end = to_physical<D>(Y, data);
  // Count and determinant use the carried (Hamiltonian-form) basis Y.
  const Square<D> Phi = Y.template topRows<D>();
  const Square<D> F = Y.template bottomRows<D>();
  const ConjugateCount count = count_conjugate_points<D>(Phi, F, state[2 * D * D]);
  shot.determinant = count.determinant;
  shot.phase_defect = count.phase_defect;
  shot.count = count.count;
  shot.angle_min = count.angle_min;
  shot.angle_max = count.angle_max;
  if (slope_shot) set_slopes<D>(shot, Phi, F);
  total_steps += shot.steps;
  total_rhs += shot.rhs_evaluations;
  total_reorthonormalisations += static_cast<long>(shot.segment_r.size());
  max_log_growth = std::max(max_log_growth, shot.log_growth);
}

// The frequency derivatives of the normalised end determinant h = det Phi / sqrt(det G) and of
// the end angle (D = 1: -2 arg(Phi + i F)) from the carried slope S = c w dY/dw and the balancing's
// own change with w (the start F~ = I is a right factor, which changes neither h nor the angle):
//   dh = [tr(adj(Phi) dPhi) - h sqrt(det G) tr(G^{-1} dG) / 2] / sqrt(det G),
//   dG = dPhi^T Phi + Phi^T dPhi + dF^T F + F^T dF,   d angle = -2 (Phi dF - F dPhi) / (Phi^2 +
//   F^2).
template <int D>
void ShootingIntegrator::Impl::set_slopes(Shot& shot,
                                          const Square<D>& Phi,
                                          const Square<D>& F) const {
  const Eigen::Map<const Basis<D>> S(stepper->state() + 2 * D * D + 1);
  const double to_slope = 1.0 / (data.slope_scale * shot.omega_rad_s);  // S -> dY/dw
  // The balancing kappa^2 moves with w as well (kappa ~ sqrt(w) where balance_moves): the
  // carried Phi~ = kappa Phi^ and F~ = F^ / kappa gain +-(dkappa/dw / kappa) = +-1/(2 w) of
  // themselves, so that the slopes are those of the function the shots evaluate.
  const double balance_rate = data.balance_moves ? 0.5 / shot.omega_rad_s : 0.0;
  const Square<D> dPhi = to_slope * S.template topRows<D>() + balance_rate * Phi;
  const Square<D> dF = to_slope * S.template bottomRows<D>() - balance_rate * F;
  const Square<D> G = Phi.transpose() * Phi + F.transpose() * F;
  const Square<D> dG =
      dPhi.transpose() * Phi + Phi.transpose() * dPhi + dF.transpose() * F + F.transpose() * dF;
  Square<D> adjugate;
  if constexpr (D == 1) {
    adjugate(0, 0) = 1.0;
  } else {
    adjugate << Phi(1, 1), -Phi(0, 1), -Phi(1, 0), Phi(0, 0);
  }
  const double root_det_g = std::sqrt(G.determinant());
  shot.has_slope = true;
  shot.determinant_slope =
      (adjugate * dPhi).trace() / root_det_g - 0.5 * shot.determinant * (G.inverse() * dG).trace();
  if constexpr (D == 1) {
    shot.angle_slope = -2.0 * (Phi(0, 0) * dF(0, 0) - F(0, 0) * dPhi(0, 0)) / G(0, 0);
  }
}

template <int D>
Shot ShootingIntegrator::Impl::shoot(double omega,
                                     double tolerance_factor,
                                     const std::vector<double>* stations,
                                     bool from_b,
                                     bool slope) {
  Shot shot;
  shot.omega_rad_s = omega;
  begin_shot<D>(omega, tolerance_factor, from_b, slope);
  StationRecorder<D> recorder(shot, stations, data);
  const Eigen::Map<const Basis<D>> Y(stepper->state());
  while (recorder.next_at_or_before(0.0)) recorder.record(Y);
  integrate<D>(shot, recorder, from_b);
  recorder.record_rest(Y);
  finish_shot<D>(shot);
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
                               bool from_b,
                               bool with_slope) {
  if (impl_->dimension == 2)
    return impl_->shoot<2>(omega_rad_s, tolerance_factor, stations_x, from_b, with_slope);
  return impl_->shoot<1>(omega_rad_s, tolerance_factor, stations_x, from_b, with_slope);
}

double axial_stretch(double axial_compliance, double tangent_spread) {
  const double axial_scale = std::max(std::sqrt(axial_compliance), tangent_spread);
  return axial_scale > 0.0 ? std::clamp(1.0 / axial_scale, 1.0, kMaxAxialStretch)
                           : kMaxAxialStretch;
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
