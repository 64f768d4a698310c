// The fe solver's forced response: see fe_forced.hpp and docs/methods/fe.md.
#include "solvers/internal/fe_forced.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "solvers/internal/fe_banded_ldlt.hpp"
#include "solvers/internal/fe_summary.hpp"
#include "solvers/internal/work_meter.hpp"

namespace catena::internal {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The imposed end displacements (d at the forced end, 0 at the other). Out of plane the amplitude
// is carried in x.
std::pair<Vec2, Vec2> end_displacements(const ForcedRequest& request, const StaticSolution& statics,
                                        double length_m) {
  const double s_end = request.end == CableEnd::A ? 0.0 : length_m;
  Vec2 direction = Vec2(1.0, 0.0);
  switch (request.direction) {
    case ForcingDirection::Tangential: direction = statics.tangent(s_end); break;
    case ForcingDirection::Normal: direction = statics.normal(s_end); break;
    case ForcingDirection::GivenVector: direction = request.unit_vector(); break;
    case ForcingDirection::OutOfPlane: break;
  }
  const Vec2 d = request.amplitude_m * direction;
  return {request.end == CableEnd::A ? d : Vec2::Zero(), request.end == CableEnd::B ? d : Vec2::Zero()};
}

// What one forcing frequency needs besides omega.
struct Forcing {
  Plane plane;
  Vec2 end_a, end_b;
  const Vector& stations;
  const StaticSolution& statics;

  FeLevelResponse on(const FeLevel& level, double omega) const {
    return respond_on_level(plane, level.chain, level.matrices.at(plane), omega, end_a, end_b, stations,
                            statics);
  }
};

double max_abs(const Vector& x) { return x.size() ? x.cwiseAbs().maxCoeff() : 0.0; }

// The response on the finest main mesh, extrapolated in kappa when penalised, with the relative
// error estimate of its peak tension from the coarse mesh (same penalty as the first level): the
// response converges as O(h^2), so |fine - coarse| bounds the fine mesh's error.
void respond(ForcedResponse& response, const Forcing& forcing, const FePlan& plan, const FeLevels& levels) {
  const double omega = response.omega_rad_s;
  const auto& fine = levels[static_cast<std::size_t>(plan.main_fine)];
  std::vector<FeLevelResponse> raw;
  for (const FeLevel& level : fine) {
    raw.push_back(forcing.on(level, omega));
    if (!raw.back().ok) {
      response.diagnostic = raw.back().diagnostic;
      return;
    }
  }
  FeSampled result = raw[0].sampled;
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
  response.max_abs_tension_n = max_abs(result.tension);
  const double scale = std::max({max_abs(response.u), max_abs(response.w), max_abs(response.v)});
  if (plan.has_coarse() && response.max_abs_tension_n > 0.0) {
    const FeLevelResponse coarse = forcing.on(levels[static_cast<std::size_t>(plan.main_coarse)][0], omega);
    if (coarse.ok && coarse.sampled.tension.size()) {
      const double fine_max = raw[0].sampled.tension.cwiseAbs().maxCoeff();
      const double coarse_max = coarse.sampled.tension.cwiseAbs().maxCoeff();
      response.relative_error_estimate = std::abs(fine_max - coarse_max) / std::max(fine_max, 1e-300);
    }
  }
  if (!std::isfinite(scale) || !std::isfinite(response.max_abs_tension_n)) {
    response = ForcedResponse{};
    response.omega_rad_s = omega;
    response.s_m = forcing.stations;
    response.diagnostic = "non-finite response (resonance)";
  }
}

// Within kNearResonance (relative) of a computed natural frequency: the response is
// resonance-amplified (the same 1e-3 as shooting's normalised determinant).
constexpr double kNearResonance = 1e-3;
bool near_natural(double omega, const std::vector<FeNaturalFrequency>& naturals) {
  return std::any_of(naturals.begin(), naturals.end(), [&](const FeNaturalFrequency& mode) {
    return std::abs(omega - mode.omega_rad_s) <= kNearResonance * mode.omega_rad_s;
  });
}

}  // namespace

Plane forced_plane(const ForcedRequest& request) {
  return request.direction == ForcingDirection::OutOfPlane ? Plane::OutOfPlane : Plane::InPlane;
}

// A forcing frequency indistinguishable from a computed natural frequency (within that
// frequency's own error estimate) has no meaningful finite answer.
std::string resonance_diagnostic(double omega, Plane plane, const std::vector<FeNaturalFrequency>& naturals) {
  for (const FeNaturalFrequency& mode : naturals) {
    const double window =
        std::max(1e-9, 3.0 * std::max(0.0, mode.relative_error_estimate)) * mode.omega_rad_s;
    if (std::abs(omega - mode.omega_rad_s) <= window) {
      return fmt::format(
          "forcing at omega = {:.9g} rad/s is within {:.2e} rad/s of {} natural frequency {} "
          "({:.9g} rad/s, relative error estimate {:.1e}): resonance, no finite response",
          omega, std::abs(omega - mode.omega_rad_s), to_string(plane), mode.index, mode.omega_rad_s,
          mode.relative_error_estimate);
    }
  }
  return {};
}

FeLevelResponse respond_on_level(Plane plane,
                                 const FeChain& chain,
                                 const FeMatrices& matrices,
                                 double omega,
                                 const Vec2& end_a,
                                 const Vec2& end_b,
                                 const Vector& stations,
                                 const StaticSolution& statics) {
  FeLevelResponse out;
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
  out.sampled = sample_on_stations(plane, chain, D, plane == Plane::InPlane ? &tau : nullptr, stations, statics);
  if (plane == Plane::OutOfPlane) out.sampled.tension = Vector::Zero(stations.size());
  out.ok = true;
  return out;
}

ForcedOutcome fe_forced_response(const ForcedRequest& request,
                                 const SolveContext& context,
                                 const FePlan& plan,
                                 FeLevels& levels,
                                 const std::vector<FeNaturalFrequency>& naturals,
                                 FeTimings& timings) {
  const auto start = Clock::now();
  const Vector stations = context.request.stations_m(context.problem.length_m());
  const auto [end_a, end_b] = end_displacements(request, context.statics, context.problem.length_m());
  const Forcing forcing{forced_plane(request), end_a, end_b, stations, context.statics};
  std::vector<std::size_t> meshes = {static_cast<std::size_t>(plan.main_fine)};
  if (plan.has_coarse()) meshes.push_back(static_cast<std::size_t>(plan.main_coarse));
  assemble_missing(levels, forcing.plane, meshes);
  ForcedOutcome outcome;
  WorkMeter meter(context, "fe", "forced frequencies", static_cast<long>(request.omegas_rad_s.size()));
  for (double omega : request.omegas_rad_s) {
    ForcedResponse response;
    response.omega_rad_s = omega;
    response.s_m = stations;
    response.diagnostic = resonance_diagnostic(omega, forcing.plane, naturals);
    if (response.diagnostic.empty()) respond(response, forcing, plan, levels);
    // Every diagnostic of fe's forced response is a resonance (its own, or a singular K - omega^2 M).
    response.at_resonance = !response.diagnostic.empty();
    response.near_resonance = response.diagnostic.empty() && near_natural(omega, naturals);
    if (!response.diagnostic.empty()) outcome.summary.warnings.push_back(response.diagnostic);
    outcome.responses.push_back(std::move(response));
    if (meter.stop_after(static_cast<long>(outcome.responses.size()))) break;
  }
  timings.forced_s += seconds_since(start);
  describe_forced(outcome, timings);
  mark_time_limit(meter, outcome.summary);
  return outcome;
}

}  // namespace catena::internal
