// SPDX-License-Identifier: MIT
// The damped shot: see shooting_damped_integrator.hpp.
#include "solvers/shooting/shooting_damped_integrator.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "solvers/shooting/shooting_damped_grounded.hpp"
#include "solvers/shooting/shooting_grounded.hpp"
#include "solvers/shooting/shooting_shot_setup.hpp"
#include "solvers/shooting/shooting_steppers.hpp"
#include "solvers/shooting/shooting_sundials_handles.hpp"

namespace catena::internal {

namespace {

using Complex = std::complex<double>;

// [Phi^; F^] of the carried complex basis [Phi~; F~]: undoes the balancing and the axial frame,
// as to_physical does for the undamped shot (from b the force was carried as -F^).
template <int D>
ComplexBasis<D> damped_to_physical(const ComplexBasis<D>& carried, const RhsData& data) {
  const double kappa = std::sqrt(data.kappa2);
  ComplexBasis<D> out = carried;
  out.template topRows<D>() /= kappa;
  out.template bottomRows<D>() *= data.from_b ? -kappa : kappa;
  if constexpr (D == 2) {
    out.template topRows<D>() =
        data.to_axial_force.transpose().cast<Complex>() * out.template topRows<D>();
    out.template bottomRows<D>() =
        data.to_axial.transpose().cast<Complex>() * out.template bottomRows<D>();
  }
  return out;
}

// The carried basis [Phi~; F~] of a physical one (the inverse of damped_to_physical, from a).
template <int D>
ComplexBasis<D> damped_to_carried(const ComplexBasis<D>& physical, const RhsData& data) {
  const double kappa = std::sqrt(data.kappa2);
  ComplexBasis<D> out = physical;
  if constexpr (D == 2) {
    out.template topRows<D>() = data.to_axial.cast<Complex>() * physical.template topRows<D>();
    out.template bottomRows<D>() =
        data.to_axial_force.cast<Complex>() * physical.template bottomRows<D>();
  }
  out.template topRows<D>() *= kappa;
  out.template bottomRows<D>() /= kappa;
  return out;
}

// Whether the complex basis has lost independence (cond(Y^H Y) > max_condition) or left the scale
// [1e-6, 1e6] (the Hermitian 2x2 Gram matrix's eigenvalues in closed form).
template <int D>
bool damped_needs_restart(const ComplexBasis<D>& Y, double max_condition) {
  const ComplexSquare<D> G = Y.adjoint() * Y;
  if constexpr (D == 2) {
    const double a = G(0, 0).real(), d = G(1, 1).real();
    const double hi = 0.5 * (a + d) + std::hypot(0.5 * (a - d), std::abs(G(0, 1)));
    const double lo = (a * d - std::norm(G(0, 1))) / hi;
    return !(lo > 0.0) || hi > max_condition * lo || hi > 1e6 || lo < 1e-6;
  } else {
    return G(0, 0).real() > 1e6 || G(0, 0).real() < 1e-6;
  }
}

// Y = Q R with R's diagonal real and positive (det R > 0: arg det Phi unchanged); Y <- Q.
template <int D>
ComplexSquare<D> damped_orthonormalise(Eigen::Map<ComplexBasis<D>>& Y, double x) {
  const Eigen::HouseholderQR<ComplexBasis<D>> qr(Y);
  ComplexSquare<D> R = qr.matrixQR().template topRows<D>().template triangularView<Eigen::Upper>();
  ComplexBasis<D> Q = qr.householderQ() * ComplexBasis<D>::Identity();
  for (int j = 0; j < D; ++j) {
    const double modulus = std::abs(R(j, j));
    if (!(modulus > 0.0)) {
      throw ShootingFailure(
          fmt::format("damped principal solutions became dependent at s/L = {:.6g}", x));
    }
    const Complex phase = R(j, j) / modulus;
    R.row(j) /= phase;
    Q.col(j) *= phase;
  }
  Y = Q;
  return R;
}

}  // namespace

struct DampedShootingIntegrator::Impl {
  Impl(Plane plane, const ShootingCoefficients& coefficients, const IntegratorSettings& s)
      : settings(s), dimension(plane == Plane::InPlane ? 2 : 1) {
    data.coefficients = coefficients;
    data.coefficients.pieces = coefficients.all_pieces();
    original = data.coefficients.pieces;
    data.dimension = dimension;
    if (dimension == 2) set_axial_frame(data.coefficients, data);
    if (!context.ok()) throw ShootingFailure("could not allocate the SUNDIALS objects");
    stepper = make_damped_stepper(settings, context.get(), dimension, data);
    // A shot from A of a line on the seabed starts with the grounded run
    // (shooting_damped_grounded.hpp); from b the general stepper crosses the grounded pieces
    // (correct, but its cost grows with the foundation's stiffness).
    const std::size_t run = grounded_run_length(data.coefficients, dimension);
    if (run > 0) grounded = std::make_unique<DampedGroundedRun>(data, run, settings.max_steps);
  }

  template <int D>
  DampedShot shoot(Complex lambda, double factor, const std::vector<double>* stations, bool from_b);
  template <int D>
  void record(DampedShot& shot, const double* state) const {
    const Eigen::Map<const ComplexBasis<D>> Y(reinterpret_cast<const Complex*>(state));
    shot.station_y.emplace_back(damped_to_physical<D>(Y, data));
    shot.station_segment.push_back(static_cast<int>(shot.segment_r.size()));
  }
  template <int D>
  void cross_break(const Break& b, double x);
  template <int D>
  void set_grounded_state(const DampedGroundedFrame& frame,
                          DampedShot& shot,
                          Eigen::VectorXd& pushed);
  double stop_time() const { return next_break < breaks.size() ? breaks[next_break].x : 1.0; }

  IntegratorSettings settings;
  int dimension;
  std::vector<ShootingPiece> original;  // the pieces with the damping as given
  // Declaration order = construction order; destruction runs in reverse (stepper first).
  SundialsContext context;
  RhsData data;
  std::unique_ptr<ShotStepper> stepper;
  // The seabed part of a shot from A; null when the line starts off the seabed.
  std::unique_ptr<DampedGroundedRun> grounded;
  std::vector<Break> breaks;
  std::size_t next_break = 0;
  long shots = 0;
  long total_steps = 0;
  long total_rhs = 0;
};

// A break: the next piece, and at a point the jump F~ -> F~ - K Phi~ with the point's inertia
// K = -lambda^2 L Q Mp Q^T / (T_ref kappa^2) (the undamped point_jump with w^2 -> -lambda^2; point
// attachments carry no damping).
template <int D>
void DampedShootingIntegrator::Impl::cross_break(const Break& b, double x) {
  data.piece = b.next_piece;
  if (b.point >= 0) {
    const ShootingCoefficients& k = data.coefficients;
    const ShootingPoint& point = k.points[static_cast<std::size_t>(b.point)];
    const Complex scale = -data.lambda * data.lambda * k.length_m / (k.t_ref * data.kappa2);
    ComplexSquare<D> K;
    if constexpr (D == 1) {
      K(0, 0) = scale * point.mass_outofplane;
    } else {
      const Vec2 n(-point.t.y(), point.t.x());
      const Vec2 tq = data.to_axial_force * point.t, nq = data.to_axial_force * n;
      const Eigen::Matrix2d mass =
          point.mass_tangential * tq * tq.transpose() + point.mass_normal * nq * nq.transpose();
      K = scale * mass.cast<Complex>();
    }
    Eigen::Map<ComplexBasis<D>> Y(reinterpret_cast<Complex*>(stepper->state()));
    const ComplexSquare<D> Phi = Y.template topRows<D>();
    Y.template bottomRows<D>() -= K * Phi;
  }
  stepper->restart(x, stop_time());
}

// The grounded run's frame as the carried state: the growth since the last R factor goes into new
// diagonal R factors (real, each at most e^600 so that they stay finite), the phase of the complex
// log scale stays in the column (R keeps its real positive diagonal: arg D = arg determinant).
template <int D>
void DampedShootingIntegrator::Impl::set_grounded_state(const DampedGroundedFrame& frame,
                                                        DampedShot& shot,
                                                        Eigen::VectorXd& pushed) {
  constexpr double kLargestLogFactor = 600.0;
  Eigen::VectorXd growth = frame.log_scale.real() - pushed;
  pushed = frame.log_scale.real();
  shot.log_scale += growth.sum();
  // Bounded memory whoever calls (the solver declines such a foundation before any shot).
  if (!(growth.cwiseAbs().maxCoeff() <= kMaxGroundedEfolds)) {
    throw ShootingFailure(fmt::format(
        "the seabed foundation's solution grows by {:.3g} e-folds on the grounded run, more than "
        "the {:.0e} a shot carries: [seabed] stiffness too large",
        growth.cwiseAbs().maxCoeff(), kMaxGroundedEfolds));
  }
  do {
    const Eigen::VectorXd step = growth.cwiseMax(-kLargestLogFactor).cwiseMin(kLargestLogFactor);
    shot.segment_r.emplace_back(
        step.array().exp().matrix().asDiagonal().toDenseMatrix().cast<Complex>());
    growth -= step;
  } while (growth.cwiseAbs().maxCoeff() > 0.0);
  ComplexBasis<D> physical = ComplexBasis<D>::Zero();
  for (int j = 0; j < D; ++j) {
    const Complex phase = std::polar(1.0, frame.log_scale(j).imag());
    physical(j, j) = frame.phi(j) * phase;
    physical(D + j, j) = frame.force(j) * phase;
  }
  Eigen::Map<ComplexBasis<D>>(reinterpret_cast<Complex*>(stepper->state())) =
      damped_to_carried<D>(physical, data);
}

template <int D>
DampedShot DampedShootingIntegrator::Impl::shoot(Complex lambda,
                                                 double factor,
                                                 const std::vector<double>* stations,
                                                 bool from_b) {
  DampedShot shot;
  shot.lambda = lambda;
  const ShootingCoefficients& k = data.coefficients;
  data.lambda = lambda;
  // The balancing of the undamped shot with Omega = |lambda| L sqrt(M / T_ref).
  const double omega_scaled = std::abs(lambda) * k.length_m * std::sqrt(k.M / k.t_ref);
  set_balance(k, omega_scaled, settings.balance, data);
  data.from_b = from_b;
  data.piece = from_b ? k.pieces.size() - 1 : 0;
  breaks = breaks_of(k, from_b);
  next_break = 0;
  double* state = stepper->state();
  Eigen::Map<ComplexBasis<D>> Y(reinterpret_cast<Complex*>(state));
  // Phi^ = 0, F^ = I in the carried variables (F~ = P^{-T} / kappa), so that D(lambda) = det Phi^
  // is analytic (a start F~ = I would multiply it by det(kappa P^T), which is not). From b the
  // carried force is -F^: the sign of the start does not move the roots.
  Y.setZero();
  Eigen::Matrix<double, D, D> start = Eigen::Matrix<double, D, D>::Identity();
  if constexpr (D == 2) start = data.to_axial_force;
  Y.template bottomRows<D>() = (start / std::sqrt(data.kappa2)).template cast<Complex>();
  data.rtol = settings.relative_tolerance * factor;
  data.atol = settings.absolute_tolerance * factor;
  stepper->begin(data.rtol, data.atol, data.atol, stop_time());
  std::size_t next_station = 0;
  const auto station_due = [&](double x) {
    return stations && next_station < stations->size() && (*stations)[next_station] <= x;
  };
  while (station_due(0.0)) record<D>(shot, state), ++next_station;
  Eigen::Matrix<double, 4 * D * D, 1> buffer;
  double x = 0.0;
  const bool grounded_shot = grounded && !from_b;
  if (grounded_shot) {
    grounded->begin(data.rtol, data.atol);
    Eigen::VectorXd pushed = Eigen::VectorXd::Zero(D);
    const double end = grounded->end_x();
    while (station_due(end)) {
      set_grounded_state<D>(grounded->advance_to((*stations)[next_station]), shot, pushed);
      record<D>(shot, state), ++next_station;
    }
    set_grounded_state<D>(grounded->advance_to(end), shot, pushed);
    next_break = grounded->pieces();
    x = end;
    if (x < 1.0) {
      data.piece = next_break;
      stepper->restart(x, stop_time());
    }
  }
  long steps = 0;
  while (x < 1.0) {
    x = stepper->step(stop_time());
    if (++steps > settings.max_steps) {
      throw ShootingFailure(fmt::format(
          "more than {} integration steps (max_steps) at s/L = {:.6g}", settings.max_steps, x));
    }
    while (station_due(x)) {
      stepper->state_at((*stations)[next_station], buffer.data());
      record<D>(shot, buffer.data());
      ++next_station;
    }
    if (x >= 1.0) break;
    if (next_break < breaks.size() && x >= breaks[next_break].x) {
      cross_break<D>(breaks[next_break++], x);
    }
    if (damped_needs_restart<D>(Y, settings.max_condition)) {
      const ComplexSquare<D> R = damped_orthonormalise<D>(Y, x);
      for (int j = 0; j < D; ++j) shot.log_scale += std::log(R(j, j).real());
      shot.segment_r.emplace_back(R);
      stepper->restart(x, stop_time());
    }
  }
  while (station_due(1.0)) record<D>(shot, state), ++next_station;
  shot.y_end = damped_to_physical<D>(Y, data);
  shot.determinant = shot.y_end.topRows(D).determinant();
  shot.steps = stepper->steps();
  shot.rhs_evaluations = stepper->rhs_evaluations();
  if (grounded_shot) {
    shot.steps += grounded->steps();
    shot.rhs_evaluations += grounded->rhs_evaluations();
  }
  ++shots;
  total_steps += shot.steps;
  total_rhs += shot.rhs_evaluations;
  return shot;
}

DampedShootingIntegrator::DampedShootingIntegrator(Plane plane,
                                                   const ShootingCoefficients& coefficients,
                                                   const IntegratorSettings& settings)
    : impl_(std::make_unique<Impl>(plane, coefficients, settings)) {}

DampedShootingIntegrator::~DampedShootingIntegrator() = default;

void DampedShootingIntegrator::set_damping_scale(double scale) {
  std::vector<ShootingPiece>& pieces = impl_->data.coefficients.pieces;
  for (std::size_t j = 0; j < pieces.size(); ++j) {
    const ShootingPiece& given = impl_->original[j];
    pieces[j].damping_tangential = scale * given.damping_tangential;
    pieces[j].damping_normal = scale * given.damping_normal;
    pieces[j].damping_axial = scale * given.damping_axial;
    pieces[j].foundation_damping = scale * given.foundation_damping;
  }
}

void DampedShootingIntegrator::set_drag(const DragProfile* drag) {
  RhsData& data = impl_->data;
  data.drag = drag;
  data.drag_segment.clear();
  if (!drag) return;
  for (const ShootingPiece& p : data.coefficients.pieces) {
    data.drag_segment.push_back(drag->segment_of(0.5 * (p.s_begin + p.s_end)));
  }
}

DampedShot DampedShootingIntegrator::shoot(Complex lambda,
                                           double tolerance_factor,
                                           const std::vector<double>* stations_x,
                                           bool from_b) {
  if (impl_->dimension == 2) return impl_->shoot<2>(lambda, tolerance_factor, stations_x, from_b);
  return impl_->shoot<1>(lambda, tolerance_factor, stations_x, from_b);
}

long DampedShootingIntegrator::total_shots() const { return impl_->shots; }
long DampedShootingIntegrator::total_steps() const { return impl_->total_steps; }
long DampedShootingIntegrator::total_rhs_evaluations() const { return impl_->total_rhs; }

Eigen::VectorXcd combine_damped_at_station(const DampedShot& shot,
                                           std::size_t j,
                                           const Eigen::VectorXcd& c) {
  // c belongs to the last segment; segment k-1's coefficients are R_k^{-1} c_k.
  Eigen::VectorXcd coefficients = c;
  for (int k = static_cast<int>(shot.segment_r.size()); k > shot.station_segment[j]; --k) {
    const Eigen::MatrixXcd& R = shot.segment_r[static_cast<std::size_t>(k - 1)];
    coefficients = R.triangularView<Eigen::Upper>().solve(coefficients);
  }
  return shot.station_y[j] * coefficients;
}

}  // namespace catena::internal
