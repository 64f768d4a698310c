// SPDX-License-Identifier: MIT
// The fe solver's damped forced response: see fe_damped_forced.hpp and
// docs/explanation/methods/fe.md, "Damping".
#include "solvers/fe/fe_damped_forced.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <limits>

#include "solvers/common/work_meter.hpp"
#include "solvers/fe/fe_complex_banded_ldlt.hpp"
#include "solvers/fe/fe_structured_residual.hpp"
#include "solvers/fe/fe_summary.hpp"

namespace catena::internal {
namespace {

using Clock = std::chrono::steady_clock;
using Complex = std::complex<double>;

double max_abs(const Vector& x) { return x.size() ? x.cwiseAbs().maxCoeff() : 0.0; }

// max |a + i b| over the stations.
double max_modulus(const Vector& a, const Vector& b) {
  return a.size() ? (a.cwiseAbs2() + b.cwiseAbs2()).cwiseSqrt().maxCoeff() : 0.0;
}

// The complex residual b - Q(i omega) x: in plane from the chain's element forces on the real and
// imaginary parts (the stiff springs' rounding stays out of it), with the damping's products; out
// of plane normwise.
Eigen::VectorXcd damped_residual(Plane plane,
                                 const FeChain& chain,
                                 const FeMatrices& matrices,
                                 const FeDampingMatrix& damping,
                                 double omega,
                                 const Eigen::VectorXcd& x,
                                 const Eigen::VectorXcd& rhs,
                                 const Vec2& end_a,
                                 const Vec2& end_b) {
  if (plane != Plane::InPlane) {
    const SparseMatrix Q_real = matrices.stiffness - (omega * omega) * matrices.mass;
    const Eigen::VectorXcd qx =
        Q_real.cast<Complex>() * x + Complex(0.0, omega) * (damping.damping.cast<Complex>() * x);
    return rhs - qx;
  }
  const Vector a = x.real(), b = x.imag();
  Vector boundary(4);
  boundary << end_a, end_b;
  // Real: f - (K - w^2 M) a + w C b; imaginary: -(K - w^2 M) b - w C a - w C_ib d.
  const Vector re = inplane_structured_residual(chain, matrices, omega, a, end_a, end_b) +
                    omega * (damping.damping * b);
  const Vector im =
      inplane_structured_residual(chain, matrices, omega, b, Vec2::Zero(), Vec2::Zero()) -
      omega * (damping.damping * a) - omega * (damping.boundary_coupling * boundary);
  Eigen::VectorXcd r(a.size());
  r.real() = re;
  r.imag() = im;
  return r;
}

// Element tensions tau = (EA + i omega c_a) t . (D_{j+1} - D_j) / l0, split in parts.
void damped_tension(const FeChain& chain,
                    double omega,
                    const std::vector<Vec2>& re,
                    const std::vector<Vec2>& im,
                    Vector& tau_re,
                    Vector& tau_im) {
  tau_re.resize(chain.elements);
  tau_im.resize(chain.elements);
  for (int j = 0; j < chain.elements; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const Vec2& t = chain.direction[k];
    const Complex strain(t.dot(re[k + 1] - re[k]), t.dot(im[k + 1] - im[k]));
    const Complex tau = Complex(chain.axial_stiffness_n[j], omega * chain.axial_damping_n_s[j]) *
                        strain / chain.element_length_m[j];
    tau_re[j] = tau.real();
    tau_im[j] = tau.imag();
  }
}

}  // namespace

FeDampedLevelResponse respond_damped_on_level(Plane plane,
                                              const FeChain& chain,
                                              const FeMatrices& matrices,
                                              const FeDampingMatrix& damping,
                                              double omega,
                                              const Vec2& end_a,
                                              const Vec2& end_b,
                                              ComplexBandedLdlt* pencil) {
  FeDampedLevelResponse out;
  Vector boundary(plane == Plane::InPlane ? 4 : 2);
  if (plane == Plane::InPlane) {
    boundary << end_a, end_b;
  } else {
    boundary << end_a.x(), end_b.x();
  }
  Eigen::VectorXcd rhs(matrices.stiffness.rows());
  rhs.real() = -(matrices.boundary_coupling * boundary);
  rhs.imag() = -omega * (damping.boundary_coupling * boundary);
  ComplexBandedLdlt own;
  ComplexBandedLdlt& factor = pencil ? *pencil : own;
  const bool factored = pencil ? factor.factorize(Complex(0.0, omega))
                               : factor.factorize(matrices.stiffness, damping.damping,
                                                  matrices.mass, Complex(0.0, omega));
  bool singular = !factored || factor.pivot_ratio() <= 1e-13;
  Eigen::VectorXcd x = rhs;
  if (!singular) {
    factor.solve_in_place(x.data());
    Eigen::VectorXcd correction =
        damped_residual(plane, chain, matrices, damping, omega, x, rhs, end_a, end_b);
    factor.solve_in_place(correction.data());
    x += correction;
    singular = !x.allFinite();
  }
  if (singular) {
    out.diagnostic = fmt::format(
        "K + i omega C - omega^2 M is singular at omega = {:.9g} rad/s (N = {}): forcing at the "
        "frequency of a mode the damping does not reach (resonance)",
        omega, chain.elements);
    return out;
  }
  out.real.pieces = field_pieces(chain);
  out.imag.pieces = out.real.pieces;
  out.real.nodes = node_displacements(plane, chain.elements, x.real(), end_a, end_b);
  out.imag.nodes = node_displacements(plane, chain.elements, x.imag());
  if (plane == Plane::InPlane) {
    damped_tension(chain, omega, out.real.nodes, out.imag.nodes, out.real.tension,
                   out.imag.tension);
    double worst = 0.0;
    for (int j = 0; j < chain.elements; ++j) {
      const auto k = static_cast<std::size_t>(j);
      const double stiffness =
          std::hypot(chain.axial_stiffness_n[j], omega * chain.axial_damping_n_s[j]);
      worst = std::max(worst, stiffness / chain.element_length_m[j] *
                                  (out.real.nodes[k].norm() + out.real.nodes[k + 1].norm() +
                                   out.imag.nodes[k].norm() + out.imag.nodes[k + 1].norm()));
    }
    out.tension_rounding = std::numeric_limits<double>::epsilon() * worst;
  }
  out.ok = true;
  return out;
}

double damped_frequency_error_amplification(double omega,
                                            const std::vector<FeNaturalFrequency>& naturals) {
  double worst = 0.0;
  for (const FeNaturalFrequency& mode : naturals) {
    if (!(mode.relative_error_estimate >= 0.0)) continue;
    const double wd = mode.omega_rad_s, delta = mode.decay_rate_1_s;
    const double modulus2 = wd * wd + delta * delta;  // |lambda_n|^2, the undamped omega_n^2
    const double distance = std::abs(Complex(modulus2 - omega * omega, 2.0 * delta * omega));
    const double decay_part = mode.decay_rate_error_estimate >= 0.0
                                  ? 2.0 * delta * omega * mode.decay_rate_error_estimate
                                  : 0.0;
    worst = std::max(worst,
                     distance > 0.0
                         ? (2.0 * modulus2 * mode.relative_error_estimate + decay_part) / distance
                         : std::numeric_limits<double>::infinity());
  }
  return worst;
}

namespace {

struct DampedForcing {
  Plane plane;
  Vec2 end_a, end_b;
  const Vector& stations;
  const StaticSolution& statics;
};

// One mesh's response, extrapolated to kappa = 0 when penalised, and the kappa reference field
// (as respond_on_mesh in fe_forced.cpp), for the real and imaginary parts.
struct DampedMeshResponse {
  std::string diagnostic;
  FeResponseField real, imag, real_reference, imag_reference;
  double kappa_factor = 1.0;
  double tension_rounding = 0.0;
};

DampedMeshResponse respond_on_mesh(const DampedForcing& forcing,
                                   const std::vector<FeLevel>& mesh,
                                   std::vector<ComplexBandedLdlt>& pencils,
                                   double omega) {
  DampedMeshResponse out;
  std::vector<FeResponseField> real, imag;
  for (std::size_t k = 0; k < mesh.size(); ++k) {
    const FeLevel& level = mesh[k];
    FeDampedLevelResponse response = respond_damped_on_level(
        forcing.plane, level.chain, level.matrices.at(forcing.plane),
        level.damping.at(forcing.plane), omega, forcing.end_a, forcing.end_b, &pencils[k]);
    if (!response.ok) {
      out.diagnostic = response.diagnostic;
      return out;
    }
    real.push_back(std::move(response.real));
    imag.push_back(std::move(response.imag));
    out.tension_rounding = std::max(out.tension_rounding, response.tension_rounding);
  }
  if (real.size() >= 2) out.tension_rounding *= 3.0;
  auto extrapolated = [](const std::vector<FeResponseField>& fields) {
    return fields.size() >= 2 ? extrapolate_field_in_kappa(fields[0], fields[1]) : fields[0];
  };
  auto reference = [](const std::vector<FeResponseField>& fields) {
    return fields.size() == 3 ? quadratic_field_in_kappa(fields[0], fields[1], fields[2])
                              : fields[0];
  };
  out.real = extrapolated(real);
  out.imag = extrapolated(imag);
  out.real_reference = reference(real);
  out.imag_reference = reference(imag);
  out.kappa_factor = real.size() == 3 ? 2.0 : 1.0;
  return out;
}

// The larger of the two parts' station differences, times sqrt(2): a bound on the difference of
// the complex fields' moduli.
double complex_difference(const FeSampled& a_re,
                          const FeSampled& a_im,
                          const FeSampled& b_re,
                          const FeSampled& b_im,
                          bool tension) {
  return std::sqrt(2.0) * std::max(max_station_difference(a_re, b_re, tension),
                                   max_station_difference(a_im, b_im, tension));
}

// The pencils (K, C, M) of the forced meshes' levels, set once for a run of frequencies:
// [0] the main fine mesh's levels, [1] the main coarse mesh's.
using MeshPencils = std::vector<std::vector<ComplexBandedLdlt>>;

void respond(ForcedResponse& response,
             const DampedForcing& forcing,
             const FePlan& plan,
             const FeLevels& levels,
             const std::vector<FeNaturalFrequency>& naturals,
             MeshPencils& pencils) {
  const double omega = response.omega_rad_s;
  const DampedMeshResponse fine =
      respond_on_mesh(forcing, levels[static_cast<std::size_t>(plan.main_fine)], pencils[0], omega);
  DampedMeshResponse coarse;
  if (plan.has_coarse() && fine.diagnostic.empty())
    coarse = respond_on_mesh(forcing, levels[static_cast<std::size_t>(plan.main_coarse)],
                             pencils[1], omega);
  response.diagnostic = fine.diagnostic.empty() ? coarse.diagnostic : fine.diagnostic;
  if (!response.diagnostic.empty()) return;
  auto sampled = [&](const FeResponseField& field) {
    return sample_field(forcing.plane, field, forcing.stations, forcing.statics);
  };
  const bool in_plane = forcing.plane == Plane::InPlane;
  const FeSampled fine_re = sampled(fine.real), fine_im = sampled(fine.imag);
  FeSampled result_re = fine_re, result_im = fine_im;
  double mesh = 0.0, kappa = 0.0;
  if (plan.has_coarse()) {
    const FeSampled other_re =
        plan.richardson ? sampled(richardson_field(coarse.real, fine.real)) : sampled(coarse.real);
    const FeSampled other_im =
        plan.richardson ? sampled(richardson_field(coarse.imag, fine.imag)) : sampled(coarse.imag);
    if (plan.richardson) {
      result_re = other_re;
      result_im = other_im;
    }
    // The Richardson correction: it bounds the unextrapolated error (the undamped response's
    // sharper N/2 estimate is not used here).
    mesh = complex_difference(fine_re, fine_im, other_re, other_im, in_plane);
  }
  const double rounding =
      plan.richardson && plan.has_coarse()
          ? 4.0 / 3.0 * fine.tension_rounding + 1.0 / 3.0 * coarse.tension_rounding
          : fine.tension_rounding;
  if (plan.inextensible)
    kappa = fine.kappa_factor * complex_difference(fine_re, fine_im, sampled(fine.real_reference),
                                                   sampled(fine.imag_reference), in_plane);
  response.u = result_re.u;
  response.w = result_re.w;
  response.v = result_re.v;
  response.tension_n = result_re.tension;
  response.u_imag = result_im.u;
  response.w_imag = result_im.w;
  response.v_imag = result_im.v;
  response.tension_imag_n = result_im.tension;
  response.max_abs_tension_n = max_modulus(result_re.tension, result_im.tension);
  if (plan.has_coarse() && response.max_abs_tension_n > 0.0)
    response.relative_error_estimate = (mesh + kappa + rounding) / response.max_abs_tension_n +
                                       damped_frequency_error_amplification(omega, naturals);
  const double scale =
      std::max({max_abs(response.u), max_abs(response.w), max_abs(response.v),
                max_abs(response.u_imag), max_abs(response.w_imag), max_abs(response.v_imag)});
  if (!std::isfinite(scale) || !std::isfinite(response.max_abs_tension_n) ||
      !std::isfinite(response.relative_error_estimate)) {
    response = ForcedResponse{};
    response.omega_rad_s = omega;
    response.s_m = forcing.stations;
    response.diagnostic = "non-finite response (resonance of an undamped mode)";
  }
}

// The resonance-amplified band of a damped mode: within three half-power half-widths,
// |omega - omega_d| <= 3 delta (the amplitude above 1/sqrt(10) of the peak), or within 1e-3 of
// omega_d (the undamped response's rule) for a lighter one.
constexpr double kNearResonance = 1e-3;
bool near_damped_natural(double omega, const std::vector<FeNaturalFrequency>& naturals) {
  return std::any_of(naturals.begin(), naturals.end(), [&](const FeNaturalFrequency& mode) {
    return std::abs(omega - mode.omega_rad_s) <=
           std::max(kNearResonance * mode.omega_rad_s, 3.0 * mode.decay_rate_1_s);
  });
}

}  // namespace

ForcedOutcome fe_damped_forced_response(const ForcedRequest& request,
                                        const SolveContext& context,
                                        const FePlan& plan,
                                        FeLevels& levels,
                                        const std::vector<FeNaturalFrequency>& naturals,
                                        FeTimings& timings) {
  const auto start = Clock::now();
  const Vector stations = context.request.stations_m(context.problem.length_m());
  const auto [end_a, end_b] =
      end_displacements(request, context.statics, context.problem.length_m());
  const DampedForcing forcing{forced_plane(request), end_a, end_b, stations, context.statics};
  std::vector<std::size_t> meshes = {static_cast<std::size_t>(plan.main_fine)};
  if (plan.has_coarse()) meshes.push_back(static_cast<std::size_t>(plan.main_coarse));
  assemble_missing(levels, forcing.plane, meshes);
  MeshPencils pencils;
  for (std::size_t m : meshes) {
    pencils.emplace_back(levels[m].size());
    for (std::size_t k = 0; k < levels[m].size(); ++k) {
      FeLevel& level = levels[m][k];
      if (!level.damping.count(forcing.plane))
        level.damping[forcing.plane] = assemble_damping(forcing.plane, level.chain);
      const FeMatrices& matrices = level.matrices.at(forcing.plane);
      pencils.back()[k].set_pencil(matrices.stiffness, level.damping.at(forcing.plane).damping,
                                   matrices.mass);
    }
  }
  // Only a mode the damping does not reach (delta = 0) has a singular resonance.
  std::vector<FeNaturalFrequency> undamped;
  for (const FeNaturalFrequency& mode : naturals)
    if (mode.decay_rate_1_s == 0.0) undamped.push_back(mode);
  ForcedOutcome outcome;
  WorkMeter meter(context, "fe", "forced frequencies",
                  static_cast<long>(request.omegas_rad_s.size()));
  const double limit = fe_forcing_limit(levels, meshes, forcing.plane);
  for (double omega : request.omegas_rad_s) {
    ForcedResponse response;
    response.omega_rad_s = omega;
    response.s_m = stations;
    // Beyond the meshes' resolution, or an estimate above 1: declined (fe_forcing_limit).
    response.diagnostic = fe_forcing_beyond_mesh(omega, limit);
    bool declined = !response.diagnostic.empty();
    if (!declined) response.diagnostic = resonance_diagnostic(omega, forcing.plane, undamped);
    if (response.diagnostic.empty()) respond(response, forcing, plan, levels, naturals, pencils);
    if (fe_decline_untrusted_response(response)) declined = true;
    response.at_resonance = !declined && !response.diagnostic.empty();
    response.near_resonance = response.diagnostic.empty() && near_damped_natural(omega, naturals);
    if (!response.diagnostic.empty()) outcome.summary.warnings.push_back(response.diagnostic);
    outcome.responses.push_back(std::move(response));
    if (meter.stop_after(static_cast<long>(outcome.responses.size()))) break;
  }
  timings.forced_s += std::chrono::duration<double>(Clock::now() - start).count();
  describe_forced(outcome, timings);
  mark_time_limit(meter, outcome.summary);
  return outcome;
}

}  // namespace catena::internal
