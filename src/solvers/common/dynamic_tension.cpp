// SPDX-License-Identifier: MIT
// The fixed point of the drag linearisation and the dynamic tension it gives: see
// dynamic_tension.hpp and docs/explanation/dynamic-tension.md.
#include "solvers/common/dynamic_tension.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "catena/statics/elastic_catenary.hpp"
#include "solvers/common/anderson_fixed_point.hpp"
#include "solvers/common/drag_profile.hpp"
#include "solvers/common/motion_spectrum.hpp"

namespace catena::internal {
namespace {

constexpr double kPi = std::numbers::pi;

// A linear solve inside the fixed point that gave no finite response.
struct LinearSolveFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One excitation: the forced request of the linear solves (unit amplitude when irregular) and,
// when irregular, the motion spectrum with its quadrature weights.
struct Excitation {
  ForcedRequest request;
  bool irregular = false;
  double period_s = 0.0;
  MotionSpectrum spectrum;
  // The velocity scale of end b [m/s]: omega A, or the standard deviation of its velocity.
  double end_velocity = 0.0;
};

// |a + i b|^2 per station; b may be empty (an undamped response).
Vector modulus2(const Vector& a, const Vector& b) {
  if (a.size() == 0) return Vector();
  return b.size() ? Vector(a.cwiseAbs2() + b.cwiseAbs2()) : Vector(a.cwiseAbs2());
}

struct Components {
  Vector normal2;      // |w|^2 in plane, |v|^2 out of plane
  Vector tangential2;  // |u|^2 (zero out of plane)
  Vector tension2;     // |tau|^2
};

Components components(const ForcedResponse& r, Plane plane) {
  Components c;
  const Eigen::Index n = r.s_m.size();
  c.normal2 = plane == Plane::InPlane ? modulus2(r.w, r.w_imag) : modulus2(r.v, r.v_imag);
  c.tangential2 = plane == Plane::InPlane ? modulus2(r.u, r.u_imag) : Vector(Vector::Zero(n));
  c.tension2 = r.tension_n.size() ? modulus2(r.tension_n, r.tension_imag_n) : Vector::Zero(n);
  return c;
}

Plane plane_of(const MotionRequest& motion) {
  return motion.direction == ForcingDirection::OutOfPlane ? Plane::OutOfPlane : Plane::InPlane;
}

// The spectral weight q_k S_k of frequency k (1 for a regular motion).
double weight_of(const Excitation& e, Eigen::Index k) {
  return e.irregular ? e.spectrum.weight_rad_s[k] * e.spectrum.density_m2_s_per_rad[k] : 1.0;
}

// The velocity scales [V_n; V_t] of a set of responses: omega |x| (regular) or the standard
// deviation sqrt(sum_k q_k S_k omega_k^2 |x_k|^2) (irregular).
Vector velocity_scales(const std::vector<ForcedResponse>& responses,
                       const Excitation& e,
                       Plane plane,
                       Eigen::Index stations) {
  Vector normal = Vector::Zero(stations), tangential = Vector::Zero(stations);
  for (std::size_t k = 0; k < responses.size(); ++k) {
    const Components c = components(responses[k], plane);
    const double omega = responses[k].omega_rad_s;
    const double q = weight_of(e, Eigen::Index(k)) * omega * omega;
    normal += q * c.normal2;
    tangential += q * c.tangential2;
  }
  Vector scales(2 * stations);
  scales << normal.cwiseSqrt(), tangential.cwiseSqrt();
  return scales;
}

// The responses to `profile`, or LinearSolveFailure naming the first frequency without one.
std::vector<ForcedResponse> linear_responses(SolverNumerics& numerics,
                                             const Excitation& e,
                                             const DragProfile& profile) {
  ForcedOutcome outcome = numerics.forced_with_drag(e.request, profile);
  if (outcome.responses.size() != e.request.omegas_rad_s.size()) {
    throw LinearSolveFailure(outcome.summary.message.empty() ? "the linear solve failed"
                                                             : outcome.summary.message);
  }
  for (const ForcedResponse& r : outcome.responses) {
    if (!r.diagnostic.empty() || r.s_m.size() != profile.stations().size()) {
      throw LinearSolveFailure(
          fmt::format("no response at omega = {:.6g} rad/s: {}", r.omega_rad_s, r.diagnostic));
    }
  }
  return std::move(outcome.responses);
}

// One end's values (station j) from the responses.
DynamicTensionEnd end_values(const DynamicTension& t, Eigen::Index j, double duration_s) {
  DynamicTensionEnd end;
  end.s_m = t.s_m[j];
  end.mean_n = t.mean_n[j];
  if (!t.irregular) {
    end.amplitude_n = t.amplitude_n[j];
    end.phase_deg = t.phase_deg[j];
    return end;
  }
  end.std_n = t.std_n[j];
  const Vector& S = j == 0 ? t.anchor_spectrum_n2_s_per_rad : t.fairlead_spectrum_n2_s_per_rad;
  const Vector& omega = t.spectrum_omega_rad_s;
  const Vector w = trapezoid_weights(omega);
  const double m0 = w.dot(S), m2 = w.dot(Vector(S.cwiseProduct(omega.cwiseAbs2())));
  end.zero_upcrossing_period_s = m2 > 0.0 ? 2.0 * kPi * std::sqrt(m0 / m2) : -1.0;
  const double crossings =
      end.zero_upcrossing_period_s > 0.0 ? duration_s / end.zero_upcrossing_period_s : 0.0;
  const double peak = crossings > std::exp(1.0) ? std::sqrt(2.0 * std::log(crossings)) : 1.0;
  end.most_probable_max_n = end.mean_n + end.std_n * peak;
  return end;
}

// The tension and motion fields of the final responses.
void set_fields(DynamicTension& t,
                const std::vector<ForcedResponse>& responses,
                const Excitation& e,
                Plane plane) {
  const Eigen::Index n = t.s_m.size();
  if (!e.irregular) {
    const ForcedResponse& r = responses.front();
    const Components c = components(r, plane);
    t.amplitude_n = c.tension2.cwiseSqrt();
    t.phase_deg.resize(n);
    for (Eigen::Index j = 0; j < n; ++j) {
      const double im = r.tension_imag_n.size() ? r.tension_imag_n[j] : 0.0;
      const double re = r.tension_n.size() ? r.tension_n[j] : 0.0;
      t.phase_deg[j] = std::atan2(im, re) * 180.0 / kPi;
    }
    const Vector out = plane == Plane::OutOfPlane ? Vector::Zero(n) : Vector(c.tangential2);
    t.motion_m = (c.normal2 + out).cwiseSqrt();
    return;
  }
  Vector var_t = Vector::Zero(n), var_x = Vector::Zero(n);
  const Eigen::Index K = Eigen::Index(responses.size());
  t.spectrum_omega_rad_s = e.spectrum.omega_rad_s;
  t.fairlead_spectrum_n2_s_per_rad.resize(K);
  t.anchor_spectrum_n2_s_per_rad.resize(K);
  for (Eigen::Index k = 0; k < K; ++k) {
    const Components c = components(responses[std::size_t(k)], plane);
    const double S = e.spectrum.density_m2_s_per_rad[k];
    var_t += weight_of(e, k) * c.tension2;
    var_x += weight_of(e, k) * (c.normal2 + c.tangential2);
    t.anchor_spectrum_n2_s_per_rad[k] = S * c.tension2[0];
    t.fairlead_spectrum_n2_s_per_rad[k] = S * c.tension2[n - 1];
  }
  t.std_n = var_t.cwiseSqrt();
  t.motion_m = var_x.cwiseSqrt();
}

// The estimated relative error of the tension: regular, the response's own; irregular, the
// responses' estimates weighted by their share of the tension variance, sum q S tau^2 e /
// sum q S tau^2 (the relative error of sigma^2 is twice that, of sigma the same), so that a
// frequency where the spectrum carries no energy does not set it. -1 when a response with weight
// has none.
double response_estimate(const std::vector<ForcedResponse>& responses, const Excitation& e) {
  double weighted = 0.0, total = 0.0, largest = 0.0;
  for (std::size_t k = 0; k < responses.size(); ++k) {
    const double q = weight_of(e, Eigen::Index(k));
    if (q == 0.0) continue;
    const double estimate = responses[k].relative_error_estimate;
    if (estimate < 0.0) return -1.0;
    const double share = q * responses[k].max_abs_tension_n * responses[k].max_abs_tension_n;
    weighted += share * estimate;
    total += share;
    largest = std::max(largest, estimate);
  }
  return total > 0.0 ? weighted / total : largest;
}

// The relative residual max |G(V) - V| / max |G(V)|.
double relative_residual(const Vector& V, const Vector& G) {
  const double scale = G.cwiseAbs().maxCoeff();
  if (!(scale > 0.0)) return (V - G).cwiseAbs().maxCoeff() > 0.0 ? 1.0 : 0.0;
  return (V - G).cwiseAbs().maxCoeff() / scale;
}

struct FixedPoint {
  Vector scales;  // [V_n; V_t] [m/s]
  int evaluations = 0;
  std::string reason;
};

// Iterates the linearisation from the end's velocity everywhere: KINSOL in units of the end's
// velocity, once more from where it stopped with the tolerance rescaled when its own measure
// (absolute, in those units) stopped short of the relative one.
FixedPoint iterate(SolverNumerics& numerics,
                   const Excitation& e,
                   DragProfile& profile,
                   const MotionRequest& motion,
                   Plane plane) {
  const Eigen::Index n = profile.stations().size();
  const double v_ref = e.end_velocity > 0.0 ? e.end_velocity : 1.0;
  auto G = [&](const Vector& scaled) {
    const Vector V = scaled.cwiseMax(0.0) * v_ref;
    profile.set_velocity_scales(V.head(n), V.tail(n));
    return Vector(velocity_scales(linear_responses(numerics, e, profile), e, plane, n) / v_ref);
  };
  FixedPoint out;
  Vector u = Vector::Ones(2 * n);
  if (!profile.has_drag()) {  // linear damping only: one solve is the answer
    out.scales = u * v_ref;
    return out;
  }
  double tolerance = 0.25 * motion.tolerance;
  long left = motion.max_iterations;
  for (int round = 0; round < 2 && left > 0; ++round) {
    const FixedPointOutcome fp = anderson_fixed_point(G, u, tolerance, left);
    out.evaluations += int(fp.evaluations);
    left -= fp.evaluations;
    u = fp.u;
    out.reason = fp.reason;
    if (!fp.reached) break;
    const Vector g = G(u);  // one evaluation to rescale the tolerance to the relative measure
    ++out.evaluations;
    --left;
    const double scale = g.cwiseAbs().maxCoeff();
    if (relative_residual(u, g) <= motion.tolerance || !(scale > 0.0)) break;
    u = g;
    tolerance = 0.25 * motion.tolerance * scale;
  }
  out.scales = u.cwiseMax(0.0) * v_ref;
  return out;
}

DynamicTension solve_excitation(const SolveContext& context,
                                SolverNumerics& numerics,
                                const Excitation& e) {
  const MotionRequest& motion = *context.request.motion;
  const Plane plane = plane_of(motion);
  DynamicTension t;
  t.irregular = e.irregular;
  t.period_s = e.period_s;
  t.omega_rad_s = e.irregular ? 0.0 : 2.0 * kPi / e.period_s;
  t.s_m = context.request.stations_m(context.problem.length_m());
  t.mean_n = t.s_m.unaryExpr([&](double s) { return context.statics.tension_n(s); });
  DragProfile profile(context.problem, t.s_m,
                      e.irregular ? DragLinearisation::Stochastic : DragLinearisation::Harmonic);
  try {
    const FixedPoint fp = iterate(numerics, e, profile, motion, plane);
    const Eigen::Index n = t.s_m.size();
    profile.set_velocity_scales(fp.scales.head(n), fp.scales.tail(n));
    profile.set_final(true);
    const std::vector<ForcedResponse> responses = linear_responses(numerics, e, profile);
    t.iterations = fp.evaluations + 1;
    t.residual = profile.has_drag()
                     ? relative_residual(fp.scales, velocity_scales(responses, e, plane, n))
                     : 0.0;
    t.converged = t.residual <= motion.tolerance;
    if (!t.converged) {
      t.diagnostic =
          fmt::format("no fixed point: residual {:.3g} > tolerance {:.3g} ({})", t.residual,
                      motion.tolerance, fp.reason.empty() ? "stopped" : fp.reason);
    }
    t.normal_damping_n_s_per_m2 = profile.normal_at_stations();
    t.tangential_damping_n_s_per_m2 = profile.tangential_at_stations();
    set_fields(t, responses, e, plane);
    const double estimate = response_estimate(responses, e);
    t.relative_error_estimate = estimate < 0.0 ? -1.0 : estimate + t.residual;
    t.anchor = end_values(t, 0, motion.duration_s);
    t.fairlead = end_values(t, n - 1, motion.duration_s);
  } catch (const LinearSolveFailure& failure) {
    t.converged = false;
    t.diagnostic = std::string("linear solve failed: ") + failure.what();
  }
  return t;
}

std::vector<Excitation> excitations(const MotionRequest& motion) {
  ForcedRequest request;
  request.end = CableEnd::B;
  request.direction = motion.direction;
  request.vector = motion.vector;
  std::vector<Excitation> out;
  if (motion.is_irregular()) {
    Excitation e;
    e.irregular = true;
    e.spectrum = motion_spectrum(motion);
    e.request = request;
    e.request.amplitude_m = 1.0;
    const Vector& omega = e.spectrum.omega_rad_s;
    e.request.omegas_rad_s.assign(omega.data(), omega.data() + omega.size());
    e.end_velocity = std::sqrt(e.spectrum.weight_rad_s.dot(
        Vector(e.spectrum.density_m2_s_per_rad.cwiseProduct(omega.cwiseAbs2()))));
    out.push_back(std::move(e));
    return out;
  }
  for (double period : motion.periods_s) {
    Excitation e;
    e.period_s = period;
    e.request = request;
    e.request.amplitude_m = motion.amplitude_m;
    e.request.omegas_rad_s = {2.0 * kPi / period};
    e.end_velocity = 2.0 * kPi / period * motion.amplitude_m;
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace

SolverSummary solve_dynamic_tension(const SolveContext& context,
                                    SolverNumerics& numerics,
                                    std::vector<DynamicTension>& results) {
  SolverSummary summary;
  const std::vector<Excitation> cases = excitations(*context.request.motion);
  if (!numerics.handles_drag()) {
    summary.termination = Termination::NotApplicable;
    summary.message =
        fmt::format("dynamic tension not computed ({} excitations asked)", cases.size());
    summary.warnings.push_back(
        "this method has no damped forced response with linearised drag: dynamic tension not "
        "computed");
    return summary;
  }
  int converged = 0, failed = 0;
  long iterations = 0;
  for (const Excitation& e : cases) {
    results.push_back(solve_excitation(context, numerics, e));
    const DynamicTension& t = results.back();
    converged += t.converged ? 1 : 0;
    failed += t.s_m.size() && t.residual < 0.0 ? 1 : 0;
    iterations += t.iterations;
    summary.max_error_estimate = std::max(summary.max_error_estimate, t.relative_error_estimate);
    if (!t.converged) {
      summary.warnings.push_back(e.irregular
                                     ? "irregular motion: " + t.diagnostic
                                     : fmt::format("period {:g} s: {}", e.period_s, t.diagnostic));
    }
  }
  const int total = int(cases.size());
  summary.iterations = iterations;
  summary.termination = converged == total ? Termination::Converged
                        : failed < total   ? Termination::NoConvergence
                                           : Termination::NumericalFailure;
  summary.message = fmt::format("{}dynamic tension: {} of {} excitations at their fixed point",
                                converged == total ? "" : "No convergence: ", converged, total);
  return summary;
}

}  // namespace catena::internal
