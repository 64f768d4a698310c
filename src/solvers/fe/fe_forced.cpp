// SPDX-License-Identifier: MIT
// The fe solver's forced response: see fe_forced.hpp and docs/explanation/methods/fe.md.
#include "solvers/fe/fe_forced.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "solvers/common/work_meter.hpp"
#include "solvers/fe/fe_banded_ldlt.hpp"
#include "solvers/fe/fe_extrapolation.hpp"
#include "solvers/fe/fe_forced_richardson.hpp"
#include "solvers/fe/fe_structured_residual.hpp"
#include "solvers/fe/fe_summary.hpp"

namespace catena::internal {

// The imposed end displacements (d at the forced end, 0 at the other). Out of plane the amplitude
// is carried in x.
std::pair<Vec2, Vec2> end_displacements(const ForcedRequest& request,
                                        const StaticSolution& statics,
                                        double length_m) {
  const double s_end = request.end == CableEnd::A ? 0.0 : length_m;
  Vec2 direction = Vec2(1.0, 0.0);
  switch (request.direction) {
    case ForcingDirection::Tangential:
      direction = statics.tangent(s_end);
      break;
    case ForcingDirection::Normal:
      direction = statics.normal(s_end);
      break;
    case ForcingDirection::GivenVector:
      direction = request.unit_vector();
      break;
    case ForcingDirection::OutOfPlane:
      break;
  }
  const Vec2 d = request.amplitude_m * direction;
  return {request.end == CableEnd::A ? d : Vec2::Zero(),
          request.end == CableEnd::B ? d : Vec2::Zero()};
}

// The chain's pieces of equal elements, where the response is smooth (fe_forced_richardson.hpp).
std::vector<FeFieldPiece> field_pieces(const FeChain& chain) {
  std::vector<FeFieldPiece> pieces;
  const std::vector<int>& first = chain.piece_first_element;
  for (std::size_t k = 0; k < first.size(); ++k) {
    const int end = k + 1 < first.size() ? first[k + 1] : chain.elements;
    pieces.push_back(
        {first[k], end - first[k], chain.node_s_m[first[k]], chain.element_length_m[first[k]]});
  }
  return pieces;
}

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// What one forcing frequency needs besides omega.
struct Forcing {
  Plane plane;
  Vec2 end_a, end_b;
  const Vector& stations;
  const StaticSolution& statics;

  FeLevelResponse on(const FeLevel& level, double omega) const {
    return respond_on_level(plane, level.chain, level.matrices.at(plane), omega, end_a, end_b);
  }
};

double max_abs(const Vector& x) { return x.size() ? x.cwiseAbs().maxCoeff() : 0.0; }

// One mesh's response, extrapolated to kappa = 0 when penalised (2 a - b over its first two
// levels), and the field whose distance from it is the kappa term of the estimate: the quadratic
// through the three penalties (twice that distance is the estimate, as for the frequencies,
// fe_extrapolation.hpp), or the field at the first penalty on a plan of two.
struct MeshResponse {
  std::string diagnostic;  // empty when every level gave a response
  FeResponseField field;
  FeResponseField kappa_reference;
  double kappa_factor = 1.0;
  /// The tensions' rounding (FeLevelResponse::tension_rounding), the largest of the levels, times
  /// what the extrapolation in kappa can amplify it by (|2| + |-1| = 3) [N].
  double tension_rounding = 0.0;
};

MeshResponse respond_on_mesh(const Forcing& forcing,
                             const std::vector<FeLevel>& mesh,
                             double omega) {
  MeshResponse out;
  std::vector<FeResponseField> fields;
  for (const FeLevel& level : mesh) {
    FeLevelResponse response = forcing.on(level, omega);
    if (!response.ok) {
      out.diagnostic = response.diagnostic;
      return out;
    }
    fields.push_back(std::move(response.field));
    out.tension_rounding = std::max(out.tension_rounding, response.tension_rounding);
  }
  if (fields.size() >= 2) out.tension_rounding *= 3.0;
  out.field = fields.size() >= 2 ? extrapolate_field_in_kappa(fields[0], fields[1]) : fields[0];
  out.kappa_reference =
      fields.size() == 3 ? quadratic_field_in_kappa(fields[0], fields[1], fields[2]) : fields[0];
  out.kappa_factor = fields.size() == 3 ? 2.0 : 1.0;
  return out;
}

// The error estimate's pieces, absolute over the stations (in the peak tension's unit).
struct ForcedErrorParts {
  double mesh = 0.0;   // the Richardson correction |R - fine| (without Richardson: |fine - coarse|)
  double kappa = 0.0;  // the kappa term on the fine mesh (inextensible, MeshResponse)
  double rounding = 0.0;  // the tensions' rounding, through the extrapolations (MeshResponse)
};

// The relative error estimate of the peak tension: the mesh term plus the kappa term plus the
// propagated frequency error. The Richardson correction |R - fine| is the fine mesh's O(h^2) error
// and bounds the O(h^4) error of R while the response is smooth in h^2. Near a natural frequency
// that expansion holds only while the meshes' frequency shift is small against the distance to
// resonance, and the response of any model whose omega_n is off by delta_n is off by about
// 2 delta_n omega_n^2 / |omega_n^2 - omega^2|: that term, with fe's own frequency estimates, is
// added, so the estimate never falls below the frequency error's amplification.
double forced_estimate(const ForcedErrorParts& parts,
                       double peak,
                       double omega,
                       const std::vector<FeNaturalFrequency>& naturals) {
  return (parts.mesh + parts.kappa + parts.rounding) / peak +
         frequency_error_amplification(omega, naturals);
}

// The mesh term of the estimate in plane (absolute, over the stations): |R(N, 2N) - R(N/2, N)|
// where the estimate mesh N/2 answered and the peak tensions of the three unextrapolated responses
// converge at order 2 (within 0.25, as for the frequencies: fe_extrapolation.hpp); otherwise
// `correction`, the Richardson correction |R - fine|, which bounds the unextrapolated error.
double mesh_term(const Forcing& forcing,
                 const FePlan& plan,
                 const FeLevels& levels,
                 double omega,
                 const MeshResponse& coarse,
                 const FeSampled& fine,
                 const FeSampled& result,
                 double correction) {
  if (!plan.richardson || !plan.has_estimate_mesh() || forcing.plane != Plane::InPlane)
    return correction;
  const MeshResponse half =
      respond_on_mesh(forcing, levels[static_cast<std::size_t>(plan.estimate_coarse)], omega);
  if (!half.diagnostic.empty()) return correction;
  auto sampled = [&](const FeResponseField& field) {
    return sample_field(forcing.plane, field, forcing.stations, forcing.statics);
  };
  const double order =
      observed_order(max_abs(sampled(half.field).tension), max_abs(sampled(coarse.field).tension),
                     max_abs(fine.tension));
  if (!(std::abs(order - 2.0) <= 0.25)) return correction;
  return max_station_difference(result, sampled(richardson_field(half.field, coarse.field)), true);
}

// The response at one forcing frequency: the meshes combined (Richardson in h on coinciding
// points, fe_forced_richardson.hpp) and sampled on the stations, with the relative error estimate
// of its peak tension (forced_estimate).
void respond(ForcedResponse& response,
             const Forcing& forcing,
             const FePlan& plan,
             const FeLevels& levels,
             const std::vector<FeNaturalFrequency>& naturals) {
  const double omega = response.omega_rad_s;
  const MeshResponse fine =
      respond_on_mesh(forcing, levels[static_cast<std::size_t>(plan.main_fine)], omega);
  MeshResponse coarse;
  if (plan.has_coarse() && fine.diagnostic.empty())
    coarse = respond_on_mesh(forcing, levels[static_cast<std::size_t>(plan.main_coarse)], omega);
  response.diagnostic = fine.diagnostic.empty() ? coarse.diagnostic : fine.diagnostic;
  if (!response.diagnostic.empty()) return;
  const FeSampled fine_sampled =
      sample_field(forcing.plane, fine.field, forcing.stations, forcing.statics);
  FeSampled result = fine_sampled;
  ForcedErrorParts parts;
  const bool in_plane = forcing.plane == Plane::InPlane;
  if (plan.has_coarse()) {
    const FeSampled other =
        plan.richardson
            ? sample_field(forcing.plane, richardson_field(coarse.field, fine.field),
                           forcing.stations, forcing.statics)
            : sample_field(forcing.plane, coarse.field, forcing.stations, forcing.statics);
    if (plan.richardson) result = other;
    parts.mesh = mesh_term(forcing, plan, levels, omega, coarse, fine_sampled, result,
                           max_station_difference(fine_sampled, other, in_plane));
  }
  // Richardson's 4/3 fine - 1/3 coarse amplifies independent rounding by up to 5/3.
  parts.rounding = plan.richardson && plan.has_coarse()
                       ? 4.0 / 3.0 * fine.tension_rounding + 1.0 / 3.0 * coarse.tension_rounding
                       : fine.tension_rounding;
  if (plan.inextensible) {
    const FeSampled kappa_reference =
        sample_field(forcing.plane, fine.kappa_reference, forcing.stations, forcing.statics);
    parts.kappa =
        fine.kappa_factor * max_station_difference(fine_sampled, kappa_reference, in_plane);
  }
  response.u = result.u;
  response.w = result.w;
  response.v = result.v;
  response.tension_n = result.tension;
  response.max_abs_tension_n = max_abs(result.tension);
  if (plan.has_coarse() && response.max_abs_tension_n > 0.0)
    response.relative_error_estimate =
        forced_estimate(parts, response.max_abs_tension_n, omega, naturals);
  const double scale = std::max({max_abs(response.u), max_abs(response.w), max_abs(response.v)});
  if (!std::isfinite(scale) || !std::isfinite(response.max_abs_tension_n) ||
      !std::isfinite(response.relative_error_estimate)) {
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
std::string resonance_diagnostic(double omega,
                                 Plane plane,
                                 const std::vector<FeNaturalFrequency>& naturals) {
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

double fe_forcing_limit(const FeLevels& levels,
                        const std::vector<std::size_t>& meshes,
                        Plane plane) {
  double limit = std::numeric_limits<double>::infinity();
  for (std::size_t m : meshes) {
    const FeMatrices& matrices = levels[m].front().matrices.at(plane);
    const SparseMatrix& K = matrices.stiffness;
    double top2 = 0.0;  // Gershgorin: lambda_max(M^-1 K) <= max_i sum_j |K_ij| / M_ii
    for (int i = 0; i < K.outerSize(); ++i) {
      double row = 0.0;  // K is symmetric: its column sums are its row sums
      for (SparseMatrix::InnerIterator it(K, i); it; ++it) row += std::abs(it.value());
      const double mass = matrices.mass.coeff(i, i);
      if (mass > 0.0) top2 = std::max(top2, row / mass);
    }
    limit = std::min(limit, 0.5 * std::sqrt(top2));
  }
  return limit;
}

std::string fe_forcing_beyond_mesh(double omega, double limit) {
  if (omega <= limit) return "";
  return fmt::format(
      "forcing at omega = {:.6g} rad/s is above what fe's meshes resolve (at most {:.6g} rad/s, "
      "half the coarsest mesh's top frequency): not computed",
      omega, limit);
}

bool fe_decline_untrusted_response(ForcedResponse& response) {
  if (!response.diagnostic.empty() || response.relative_error_estimate <= 1.0) return false;
  response.diagnostic = fmt::format(
      "relative error estimate {:.3g} > 1 at omega = {:.6g} rad/s: no digit of the response can "
      "be trusted",
      response.relative_error_estimate, response.omega_rad_s);
  return true;
}

double frequency_error_amplification(double omega,
                                     const std::vector<FeNaturalFrequency>& naturals) {
  double worst = 0.0;
  for (const FeNaturalFrequency& mode : naturals) {
    if (!(mode.relative_error_estimate >= 0.0)) continue;
    const double wn2 = mode.omega_rad_s * mode.omega_rad_s;
    const double distance = std::abs(wn2 - omega * omega);
    worst = std::max(worst, distance > 0.0 ? 2.0 * mode.relative_error_estimate * wn2 / distance
                                           : std::numeric_limits<double>::infinity());
  }
  return worst;
}

namespace {

// FeLevelResponse::tension_rounding.
double tension_rounding(const FeChain& chain, const std::vector<Vec2>& D) {
  double worst = 0.0;
  for (int j = 0; j < chain.elements; ++j) {
    const auto k = static_cast<std::size_t>(j);
    worst = std::max(worst, chain.axial_stiffness_n[j] / chain.element_length_m[j] *
                                (D[k].norm() + D[k + 1].norm()));
  }
  return std::numeric_limits<double>::epsilon() * worst;
}

}  // namespace

FeLevelResponse respond_on_level(Plane plane,
                                 const FeChain& chain,
                                 const FeMatrices& matrices,
                                 double omega,
                                 const Vec2& end_a,
                                 const Vec2& end_b) {
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
    if (plane == Plane::InPlane) {
      // One refinement step against the unrounded chain (fe_structured_residual.hpp).
      Vector correction = inplane_structured_residual(chain, matrices, omega, x, end_a, end_b);
      ldlt.solve_in_place(correction.data());
      x += correction;
    }
    singular = !x.allFinite();
  }
  if (singular) {
    out.diagnostic = fmt::format(
        "K - omega^2 M is singular at omega = {:.9g} rad/s (N = {}): forcing at a natural "
        "frequency of the discrete model (resonance)",
        omega, chain.elements);
    return out;
  }
  out.field.pieces = field_pieces(chain);
  out.field.nodes = node_displacements(plane, chain.elements, x, end_a, end_b);
  if (plane == Plane::InPlane) {
    out.field.tension = element_tension(chain, out.field.nodes);
    out.tension_rounding = tension_rounding(chain, out.field.nodes);
  }
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
  const auto [end_a, end_b] =
      end_displacements(request, context.statics, context.problem.length_m());
  const Forcing forcing{forced_plane(request), end_a, end_b, stations, context.statics};
  std::vector<std::size_t> meshes = {static_cast<std::size_t>(plan.main_fine)};
  if (plan.has_coarse()) meshes.push_back(static_cast<std::size_t>(plan.main_coarse));
  if (plan.has_estimate_mesh()) meshes.push_back(static_cast<std::size_t>(plan.estimate_coarse));
  assemble_missing(levels, forcing.plane, meshes);
  ForcedOutcome outcome;
  WorkMeter meter(context, "fe", "forced frequencies",
                  static_cast<long>(request.omegas_rad_s.size()));
  const double limit = fe_forcing_limit(levels, meshes, forcing.plane);
  for (double omega : request.omegas_rad_s) {
    ForcedResponse response;
    response.omega_rad_s = omega;
    response.s_m = stations;
    response.diagnostic = fe_forcing_beyond_mesh(omega, limit);
    bool declined = !response.diagnostic.empty();
    if (!declined) response.diagnostic = resonance_diagnostic(omega, forcing.plane, naturals);
    if (response.diagnostic.empty()) respond(response, forcing, plan, levels, naturals);
    if (fe_decline_untrusted_response(response)) declined = true;
    // Any other diagnostic of fe's forced response is a resonance (its own, or a singular
    // K - omega^2 M below the mesh's limit).
    response.at_resonance = !declined && !response.diagnostic.empty();
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
