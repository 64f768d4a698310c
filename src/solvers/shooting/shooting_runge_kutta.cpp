// SPDX-License-Identifier: MIT
#include "solvers/shooting/shooting_runge_kutta.hpp"

#include <arkode/arkode_butcher_erk.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace catena::internal {

namespace {

ButcherTableau load_erk_table(ARKODE_ERKTableID id, const char* name) {
  const ARKodeButcherTable table = ARKodeButcherTable_LoadERK(id);
  if (table == nullptr || table->d == nullptr) {
    throw std::runtime_error(fmt::format("ARKODE has no embedded table {}", name));
  }
  ButcherTableau t;
  t.name = name;
  t.stages = table->stages;
  t.order = table->q;
  t.embedded_order = table->p;
  t.a = Eigen::MatrixXd::Zero(t.stages, t.stages);
  t.b.resize(t.stages);
  t.c.resize(t.stages);
  t.error.resize(t.stages);
  for (int i = 0; i < t.stages; ++i) {
    for (int j = 0; j < i; ++j) t.a(i, j) = table->A[i][j];
    t.b(i) = table->b[i];
    t.c(i) = table->c[i];
    t.error(i) = table->b[i] - table->d[i];
  }
  ARKodeButcherTable_Free(table);
  return t;
}

// Step-size controller: the classical factor 0.9 err^(-1/(p+1)) for an embedding of order p,
// limited to [1/5, 5] per step (no growth right after a rejection).
constexpr double kSafety = 0.9;
constexpr double kMinFactor = 0.2;
constexpr double kMaxFactor = 5.0;

}  // namespace

const ButcherTableau& verner_6_5() {
  static const ButcherTableau table = load_erk_table(ARKODE_VERNER_8_5_6, "Verner 6(5)");
  return table;
}

RungeKuttaStepper::RungeKuttaStepper(const ButcherTableau& tableau,
                                     int size,
                                     Rhs rhs,
                                     const void* data)
    : tableau_(tableau),
      rhs_(rhs),
      data_(data),
      y_(Eigen::VectorXd::Zero(size)),
      y_start_(size),
      y_next_(size),
      stage_state_(size),
      k_(size, tableau.stages),
      atol_(Eigen::VectorXd::Constant(size, 1e-12)) {}

void RungeKuttaStepper::set_tolerances(double relative_tolerance,
                                       const Eigen::VectorXd& absolute_tolerances) {
  rtol_ = relative_tolerance;
  atol_ = absolute_tolerances;
}

void RungeKuttaStepper::begin(double x) {
  x_ = x_start_ = x;
  y_start_ = y_;
  h_ = 0.0;
  steps_ = evaluations_ = 0;
}

void RungeKuttaStepper::restart(double x) {
  x_ = x_start_ = x;
  y_start_ = y_;
}

void RungeKuttaStepper::evaluate(double x, const Eigen::VectorXd& y, int stage) {
  rhs_(data_, x, y.data(), k_.col(stage).data());
  ++evaluations_;
}

double RungeKuttaStepper::weighted_norm(const Eigen::VectorXd& v,
                                        const Eigen::VectorXd& reference) const {
  const Eigen::Index n = atol_.size();
  double sum = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double scaled = v(i) / (rtol_ * std::abs(reference(i)) + atol_(i));
    sum += scaled * scaled;
  }
  return std::sqrt(sum / static_cast<double>(n));
}

// Hairer, Norsett and Wanner's starting step (Solving ODEs I, II.4): the step whose Euler error
// and whose change of f would each be about the tolerance, at most 100x the first guess.
double RungeKuttaStepper::initial_step() {
  const double span = stop_ - x_;
  evaluate(x_, y_, 0);
  const double d0 = weighted_norm(y_, y_);
  const double d1 = weighted_norm(k_.col(0), y_);
  double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
  h0 = std::min(h0, span);
  stage_state_ = y_ + h0 * k_.col(0);
  evaluate(x_ + h0, stage_state_, 1);
  const double d2 = weighted_norm(k_.col(1) - k_.col(0), y_) / h0;
  const double largest = std::max(d1, d2);
  const double h1 = largest <= 1e-15 ? std::max(1e-6, 1e-3 * h0)
                                     : std::pow(0.01 / largest, 1.0 / (tableau_.order + 1));
  return std::min({100.0 * h0, h1, span});
}

double RungeKuttaStepper::attempt(
    double x0, const Eigen::VectorXd& y0, double h, Eigen::VectorXd& out, bool with_error) {
  const int s = tableau_.stages;
  for (int i = 1; i < s; ++i) {
    stage_state_ = y0;
    for (int j = 0; j < i; ++j) {
      const double a = tableau_.a(i, j);
      if (a != 0.0) stage_state_.noalias() += (h * a) * k_.col(j);
    }
    evaluate(x0 + tableau_.c(i) * h, stage_state_, i);
  }
  out = y0;
  out.noalias() += k_ * (h * tableau_.b);
  if (!with_error) return 0.0;
  stage_state_.noalias() = k_ * (h * tableau_.error);
  return weighted_norm(stage_state_, y0);
}

double RungeKuttaStepper::step() {
  if (h_ <= 0.0) h_ = initial_step();
  y_start_ = y_;
  x_start_ = x_;
  evaluate(x_, y_, 0);
  const double exponent = -1.0 / (tableau_.embedded_order + 1);
  bool rejected = false;
  for (;;) {
    const bool to_stop = h_ >= stop_ - x_;
    const double h = to_stop ? stop_ - x_ : h_;
    if (!(h > 1e-14 * std::max(1.0, std::abs(x_)))) {
      throw std::runtime_error(fmt::format("step size {:.3g} underflowed", h));
    }
    const double error = attempt(x_, y_start_, h, y_next_, true);
    if (error <= 1.0) {
      const double factor = error > 0.0 ? kSafety * std::pow(error, exponent) : kMaxFactor;
      // A step clipped to the stop point says nothing about the step after it: keep h_.
      if (!to_stop) h_ = h * std::clamp(factor, kMinFactor, rejected ? 1.0 : kMaxFactor);
      x_ = to_stop ? stop_ : x_ + h;
      y_ = y_next_;  // copied, not swapped: state() must keep pointing at y_'s storage
      ++steps_;
      return x_;
    }
    if (!std::isfinite(error) && h_ <= 1e-10) {
      throw std::runtime_error("the state is not finite");
    }
    const double factor = std::isfinite(error) ? kSafety * std::pow(error, exponent) : kMinFactor;
    h_ = h * std::clamp(factor, kMinFactor, 1.0);
    rejected = true;
  }
}

void RungeKuttaStepper::state_at(double xs, double* out) {
  Eigen::Map<Eigen::VectorXd> result(out, y_.size());
  if (xs <= x_start_) {
    result = y_start_;
  } else if (xs >= x_) {
    result = y_;
  } else {
    // k_.col(0) still holds f(x_start_, y_start_): step() evaluates it first, and attempt()
    // writes only the later stages.
    attempt(x_start_, y_start_, xs - x_start_, y_next_, false);
    result = y_next_;
  }
}

}  // namespace catena::internal
