// Forced response of the frobenius solver: see frobenius_forced.hpp.
#include "solvers/internal/frobenius_forced.hpp"

#include <cmath>
#include <optional>

#include <fmt/format.h>

namespace catena::internal {

namespace {

// Coefficients (in the unscaled basis) of the solution with the fixed end at rest and the driven
// end displaced by `end`; nullopt at a natural frequency (`conditioning`, |scaled det|, < 1e-13).
template <class Real>
std::optional<std::vector<Real>> forced_coefficients(const PlaneSetup& setup, double omega, bool driven_at_b,
                                                     const EndDisplacement& end, double& conditioning) {
  const auto m = boundary_matrix<Real>(setup, Real(omega));
  const std::size_t n = m.a.size();
  std::vector<Real> rhs(n, Real(0));
  const double sigma_end = driven_at_b ? setup.sigma2 : setup.sigma1;
  const std::size_t row = driven_at_b ? n / 2 : 0;
  rhs[row] = Real(end.u);
  if (setup.inplane) rhs[row + 1] = Real(end.v) / Real(1.0 + sigma_end * sigma_end);  // DU = V / C^2
  conditioning = std::abs(static_cast<double>(determinant(m.a)));
  if (conditioning < 1e-13) return std::nullopt;
  std::vector<Real> c = solve_dense(m.a, rhs);
  for (std::size_t j = 0; j < n; ++j) c[j] /= m.column_scale[j];
  return c;
}

// The response at one frequency [rad/s], in long double (the system is small; the extra digits
// are cheap and keep the fields accurate near resonance).
ForcedResponse response_at(const PlaneSetup& setup, bool driven_at_b, const EndDisplacement& end, double omega_rad_s,
                           const FieldStations& stations, const CableUnits& units) {
  ForcedResponse response;
  response.omega_rad_s = omega_rad_s;
  response.s_m = stations.s_m;
  const double omega = omega_rad_s / units.frequency_rad_s;
  double conditioning = 0.0;
  const auto c = forced_coefficients<long double>(setup, omega, driven_at_b, end, conditioning);
  if (!c) {
    response.diagnostic = fmt::format(
        "forcing at Omega = {:g} is at a natural frequency (scaled boundary determinant {:g} < 1e-13): resonance, "
        "no finite response",
        omega, conditioning);
    return response;
  }
  const auto values = fields<long double>(setup, omega, *c, stations.sigma, setup.inplane);
  const Index n = stations.s_m.size();
  if (setup.inplane) {
    response.u.resize(n);
    response.w.resize(n);
    response.tension_n.resize(n);
    for (Index k = 0; k < n; ++k) {
      const FieldValues& f = values[static_cast<std::size_t>(k)];
      response.u(k) = units.length_m * f.u;
      response.w(k) = units.length_m * f.v;
      response.tension_n(k) = units.tension_n * f.t;
    }
    response.max_abs_tension_n = response.tension_n.cwiseAbs().maxCoeff();
  } else {
    response.v.resize(n);
    for (Index k = 0; k < n; ++k) response.v(k) = units.length_m * values[static_cast<std::size_t>(k)].u;
  }
  return response;
}

}  // namespace

EndDisplacement forced_end_displacement(const ForcedRequest& forced, double sigma_end, double length_m) {
  const double a = length_m;
  EndDisplacement end;
  switch (forced.direction) {
    case ForcingDirection::Tangential: end.u = forced.amplitude_m / a; break;
    case ForcingDirection::Normal: end.v = forced.amplitude_m / a; break;
    case ForcingDirection::OutOfPlane: end.u = forced.amplitude_m / a; break;
    case ForcingDirection::GivenVector: {
      // Resolved on the end's unit tangent t = (1, sigma)/C and normal n = (-sigma, 1)/C.
      const double C_end = std::sqrt(1.0 + sigma_end * sigma_end);
      const Vec2 d = forced.vector.normalized() * forced.amplitude_m / a;
      const Vec2 t(1.0 / C_end, sigma_end / C_end), n(-sigma_end / C_end, 1.0 / C_end);
      end.u = d.dot(t);
      end.v = d.dot(n);
      break;
    }
  }
  return end;
}

std::vector<ForcedResponse> frobenius_forced_responses(const PlaneSetup& base, const ForcedRequest& forced,
                                                       const FieldStations& stations, const CableUnits& units,
                                                       WorkMeter* meter) {
  const bool at_b = forced.end == CableEnd::B;
  PlaneSetup setup = base;
  setup.inplane = forced.direction != ForcingDirection::OutOfPlane;
  const EndDisplacement end = forced_end_displacement(forced, at_b ? base.sigma2 : base.sigma1, units.length_m);
  std::vector<ForcedResponse> responses;
  for (double omega_rad_s : forced.omegas_rad_s) {
    responses.push_back(response_at(setup, at_b, end, omega_rad_s, stations, units));
    if (meter && meter->stop_after(static_cast<long>(responses.size()))) break;
  }
  return responses;
}

}  // namespace catena::internal
