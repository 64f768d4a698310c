// The small-strain limit, the WKB out-of-plane string modes and the door to eq. (21) shared by
// the asymptotic and airy solvers (see taut_cable_theory.hpp).
#include "solvers/internal/taut_cable_theory.hpp"

#include "catena/core/error.hpp"
#include <fmt/format.h>

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>

#include "catena/solvers/asymptotic_solver.hpp"  // eq. (21) roots, WKB frequencies (for now)
#include "solvers/internal/mode_tools.hpp"

namespace catena::internal {

Vector wkb_outofplane_shape(const StaticSolution& statics,
                            const Vector& stations_m,
                            double omega_rad_s) {
  const CableProperties& cable = statics.cable();
  const double M = cable.normal_mass_kg_per_m();
  auto stiffness = [&](double s) { return statics.tension_n(s) / (1.0 + statics.strain(s)); };
  auto slowness = [&](double s) { return std::sqrt(M / stiffness(s)); };
  Vector v(stations_m.size());
  double travel_time = 0.0;
  double previous = 0.0;
  for (Index j = 0; j < stations_m.size(); ++j) {
    const double s = stations_m[j];
    if (s > previous) {
      travel_time += boost::math::quadrature::gauss<double, 20>::integrate(slowness, previous, s);
    }
    previous = s;
    v[j] = std::pow(stiffness(s) * M, -0.25) * std::sin(omega_rad_s * travel_time);
  }
  return v;
}

double static_strain(const Problem& problem, const DimensionlessGroups& groups) {
  return problem.cable.is_inextensible() ? 0.0 : groups.t0_n / problem.cable.axial_stiffness_n;
}

ModalResult wkb_outofplane_modes(const StaticSolution& statics,
                                 const DimensionlessGroups& groups,
                                 const SolveRequest& request,
                                 double normal_mass_kg_per_m,
                                 double error_estimate,
                                 int quadrature_panels,
                                 const std::string& solver) {
  ModalResult result;
  result.plane = Plane::OutOfPlane;
  const Vector stations = request.stations_m(statics.cable().length_m);
  const bool need_shape = request.shapes || request.tension;
  const std::vector<double> omegas = wkb_outofplane_omegas(statics, request.outofplane_modes, quadrature_panels);
  for (std::size_t i = 0; i < omegas.size(); ++i) {
    Mode mode;
    mode.index = static_cast<int>(i) + 1;
    set_mode_frequency(mode, omegas[i], groups);
    mode.relative_error_estimate = error_estimate;
    if (need_shape) {
      // WKB shape: v = (T/(1+e))^(-1/4) sin(omega tau(s)), tau the transverse travel time.
      mode.s_m = stations;
      mode.v = wkb_outofplane_shape(statics, stations, omegas[i]);
      normalise_outofplane_mode(mode);
      mode.modal_mass_kg = outofplane_modal_mass(mode, normal_mass_kg_per_m);
      if (request.tension) {
        // Out-of-plane motion stretches the cable only to second order.
        mode.tension_n = Vector::Zero(stations.size());
        mode.max_abs_tension_n = 0.0;
      }
      if (!request.shapes) drop_shape_fields(mode);
    }
    result.modes.push_back(std::move(mode));
  }
  result.proved_count_below_top = static_cast<int>(result.modes.size());
  result.summary.solver = solver;
  result.summary.termination = Termination::Converged;
  result.summary.max_error_estimate = error_estimate;
  return result;
}

std::vector<double> eq21_root_k_ls(int count, double eps, double phi_rad, double lambda2) {
  return grinfogel_eq21_roots(count, eps, phi_rad, lambda2);
}

double first_axial_mode_k_l(double eps, double phi_rad, double lambda2, double mass_ratio) {
  return first_axial_k_l(eps, phi_rad, lambda2, mass_ratio);
}

void require_warning_below_max_eps(const std::string& solver, double eps_warning_threshold, double max_eps) {
  if (eps_warning_threshold > max_eps) {
    throw InvalidInput(fmt::format("[solvers.{}].eps_warning_threshold = {}: must be <= max_eps = {}",
                                   solver, eps_warning_threshold, max_eps));
  }
}

}  // namespace catena::internal
