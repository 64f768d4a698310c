// SPDX-License-Identifier: MIT
// The omega-independent part of the Airy model: end statics, travel time, linear fit of Q(s).
#include "solvers/airy/airy_model.hpp"

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>

namespace catena::internal {
namespace {

// int_0^L sqrt(M/T) ds, the transverse travel time of the fast (string) solution [s].
double transverse_travel_time(const StaticSolution& statics,
                              double normal_mass,
                              double length,
                              int quadrature_panels) {
  auto slowness = [&](double s) { return std::sqrt(normal_mass / statics.tension_n(s)); };
  const double panel = length / quadrature_panels;
  double travel_time = 0.0;
  for (int i = 0; i < quadrature_panels; ++i) {
    travel_time +=
        boost::math::quadrature::gauss<double, 20>::integrate(slowness, i * panel, (i + 1) * panel);
  }
  return travel_time;
}

// alpha^2(s) made linear in s: a2_ref + a2_slope (s - s_ref).
void fit_curvature_squared(const StaticSolution& statics,
                           const DimensionlessGroups& groups,
                           AiryCurvatureFit fit,
                           AiryModel& model) {
  const double W0 = statics.cable().weight_n_per_m;
  switch (fit) {
    case AiryCurvatureFit::Tangent: {
      // d(alpha^2)/ds = -4 alpha^2 W0 V / T^2 (alpha = W0 H / T^2, T' = W0 V / T).
      const double s_a = groups.s_at_chord_angle_m;
      const double alpha = static_curvature(statics, s_a);
      const double T = statics.tension_n(s_a);
      model.s_ref = s_a;
      model.a2_ref = alpha * alpha;
      model.a2_slope = -4.0 * alpha * alpha * W0 * statics.vertical_force_n(s_a) / (T * T);
      break;
    }
    case AiryCurvatureFit::Secant:
      model.s_ref = 0.0;
      model.a2_ref = model.alpha_end[0] * model.alpha_end[0];
      model.a2_slope = (model.alpha_end[1] * model.alpha_end[1] - model.a2_ref) / model.length;
      break;
    case AiryCurvatureFit::Paper: {
      // Eqs. (17)-(18): alpha0 = eps cos(phi_a) / L at mid-span, slope from 4 eps sin(phi_a).
      const double alpha0 = groups.eps * std::cos(groups.chord_angle_rad) / model.length;
      model.s_ref = 0.5 * model.length;
      model.a2_ref = alpha0 * alpha0;
      model.a2_slope =
          -4.0 * groups.eps * std::sin(groups.chord_angle_rad) * alpha0 * alpha0 / model.length;
      break;
    }
  }
}

}  // namespace

double static_curvature(const StaticSolution& statics, double s) {
  const double T = statics.tension_n(s);
  return statics.cable().weight_n_per_m * statics.horizontal_force_n() / (T * T);
}

AiryModel build_airy_model(const Problem& problem,
                           const StaticSolution& statics,
                           const DimensionlessGroups& groups,
                           AiryCurvatureFit fit,
                           int quadrature_panels) {
  const CableProperties& cable = problem.cable;
  AiryModel model;
  model.length = cable.length_m;
  model.mass = cable.mass_kg_per_m;
  model.normal_mass = cable.normal_mass_kg_per_m();
  model.h = model.mass / model.normal_mass;
  model.inverse_ea = cable.is_inextensible() ? 0.0 : 1.0 / cable.axial_stiffness_n;
  const double ends[2] = {0.0, model.length};
  for (int i = 0; i < 2; ++i) {
    model.alpha_end[i] = static_curvature(statics, ends[i]);
    model.c_end[i] = std::sqrt(statics.tension_n(ends[i]) / model.normal_mass);
  }
  model.travel_time =
      transverse_travel_time(statics, model.normal_mass, model.length, quadrature_panels);
  fit_curvature_squared(statics, groups, fit, model);
  model.kappa = std::cbrt(-model.h * model.a2_slope);
  return model;
}

double airy_argument(const AiryModel& model, double omega, double s) {
  const double q = model.mass * omega * omega * model.inverse_ea -
                   model.h * (model.a2_ref + model.a2_slope * (s - model.s_ref));
  return -q / (model.kappa * model.kappa);
}

}  // namespace catena::internal
