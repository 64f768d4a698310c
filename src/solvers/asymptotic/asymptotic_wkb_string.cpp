// SPDX-License-Identifier: MIT
// The asymptotic solver's WKB out-of-plane string modes (see asymptotic_wkb_string.hpp).
#include "solvers/asymptotic/asymptotic_wkb_string.hpp"

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>

#include "catena/solvers/asymptotic_solver.hpp"  // wkb_outofplane_omegas
#include "solvers/common/mode_tools.hpp"

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
  const std::vector<double> omegas =
      wkb_outofplane_omegas(statics, request.outofplane_modes, quadrature_panels);
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

}  // namespace catena::internal
