// SPDX-License-Identifier: MIT
#include "catena/statics/problem_builders.hpp"

#include <fmt/format.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>

#include "catena/core/error.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {
namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw InvalidInput(message);
}

}  // namespace

Problem make_taut_inclined_problem(double eps, double phi_deg, double lambda2, double mass_ratio) {
  require(std::isfinite(eps) && eps > 0.0 && eps <= 10.0,
          fmt::format("Invalid taut_inclined eps = {}: must be in (0, 10] (eps = W0 L / T0)", eps));
  require(std::isfinite(phi_deg) && phi_deg >= 0.0 && phi_deg < 90.0,
          fmt::format("Invalid taut_inclined phi_deg = {}: must be in [0, 90) degrees (a vertical "
                      "cable has lambda2 = 0; give it in the [cable] form)",
                      phi_deg));
  require(std::isfinite(lambda2) && lambda2 > 0.0,
          fmt::format("Invalid taut_inclined lambda2 = {}: must be finite and > 0", lambda2));
  require(std::isfinite(mass_ratio) && mass_ratio > 0.0 && mass_ratio <= 1.0,
          fmt::format("Invalid taut_inclined mass_ratio = {}: must be in (0, 1] (h = m / M)",
                      mass_ratio));
  const double phi = phi_deg * kPi / 180.0;
  const double cos_phi = std::cos(phi);
  const double sin_phi = std::sin(phi);

  Problem problem;
  problem.form = ProblemForm::TautInclined;
  problem.cable.length_m = 1.0;
  problem.cable.weight_n_per_m = eps;
  problem.cable.axial_stiffness_n = lambda2 / (eps * eps * cos_phi * cos_phi);
  problem.cable.mass_kg_per_m = mass_ratio;
  problem.cable.added_mass_kg_per_m = 1.0 - mass_ratio;
  // T0 = 1 at s_a, where V(s_a) = sin(phi) and H = cos(phi). The chord angle falls monotonically
  // as s_a grows (from above phi at s_a = 0 to below it at s_a = L): bracket [0, 1].
  const double H = cos_phi;
  auto chord_angle_excess = [&](double s_a) {
    const Vec2 r = catenary_end_offset(problem.cable, H, sin_phi - eps * s_a);
    return std::atan2(r.y(), r.x()) - phi;
  };
  // Groups far outside physical ranges (lambda2 = 5e-324, EA ~ 1e-308) leave no sign change, or a
  // non-finite angle: bad input naming the groups, not an escaping root-finder exception.
  const double at_a = chord_angle_excess(0.0), at_b = chord_angle_excess(1.0);
  require(
      std::isfinite(at_a) && std::isfinite(at_b) && at_a * at_b <= 0.0,
      fmt::format(
          "Invalid taut_inclined eps = {}, phi_deg = {}, lambda2 = {}: no static state of "
          "such a cable has T0 = 1 N at the chord angle (the groups overflow or are out of range)",
          eps, phi_deg, lambda2));
  boost::uintmax_t iterations = 200;
  const auto bracket =
      boost::math::tools::toms748_solve(chord_angle_excess, 0.0, 1.0, at_a, at_b,
                                        boost::math::tools::eps_tolerance<double>(53), iterations);
  const double s_a = 0.5 * (bracket.first + bracket.second);
  const double V_A = sin_phi - eps * s_a;
  problem.supports.a_m = Vec2::Zero();
  problem.supports.b_m = catenary_end_offset(problem.cable, H, V_A);
  problem.prescribed_forces = EndForces{H, V_A};
  return problem;
}

Problem make_gale_xi_problem(double xi1, double xi2) {
  require(std::isfinite(xi1) && std::isfinite(xi2),
          fmt::format("Invalid gale xi1 = {}, xi2 = {}: must be finite", xi1, xi2));
  require(xi1 < xi2, fmt::format("Invalid gale xi1 = {}, xi2 = {}: must have xi1 < xi2", xi1, xi2));
  require(std::max(std::abs(xi1), std::abs(xi2)) <= 1e4,
          fmt::format("Invalid gale xi1 = {}, xi2 = {}: |xi| must be <= 1e4", xi1, xi2));
  // a = H/W0 = 1 m, W0 = 1 N/m, m = 1 kg/m: sqrt(g/a) = 1 rad/s. On the catenary
  // z = a cosh(x/a), the point of parameter sigma = sinh(x/a) sits at (a asinh(sigma), a
  // sqrt(1+sigma^2)).
  const double a = 1.0;
  const double sigma1 = gale_sigma_from_xi(xi1);
  const double sigma2 = gale_sigma_from_xi(xi2);
  Problem problem;
  problem.form = ProblemForm::GaleXi;
  problem.cable.length_m = a * (sigma2 - sigma1);
  problem.cable.weight_n_per_m = 1.0;
  problem.cable.axial_stiffness_n = kInfinity;
  problem.cable.mass_kg_per_m = 1.0;
  problem.cable.added_mass_kg_per_m = 0.0;
  const Vec2 point1(a * std::asinh(sigma1), a * (1.0 + std::abs(xi1)));
  const Vec2 point2(a * std::asinh(sigma2), a * (1.0 + std::abs(xi2)));
  problem.supports.a_m = Vec2::Zero();
  problem.supports.b_m = point2 - point1;
  // H = W0 a = 1 N, V_A = H sigma1.
  problem.prescribed_forces = EndForces{1.0, sigma1};
  return problem;
}

double gale_a_over_b(double sag_parameter) {
  require(std::isfinite(sag_parameter) && sag_parameter >= 0.0 && sag_parameter < 1.0,
          fmt::format("Invalid gale sag_param = {}: must be in [0, 1) (b / sqrt(l^2 - h^2))",
                      sag_parameter));
  if (sag_parameter == 0.0) return 0.0;
  // u / sinh(u) falls monotonically from 1 (u = 0) to 0 (u -> inf).
  auto excess = [&](double u) {
    const double ratio = u < 1e-4 ? 1.0 - u * u / 6.0 : u / std::sinh(u);
    return ratio - sag_parameter;
  };
  double high = 1.0;
  while (excess(high) > 0.0) high *= 2.0;
  boost::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(
      excess, 0.0, high, boost::math::tools::eps_tolerance<double>(53), iterations);
  const double u = 0.5 * (bracket.first + bracket.second);
  return 1.0 / (2.0 * u);
}

Problem make_gale_sag_problem(double height_over_span, double sag_parameter) {
  require(std::isfinite(height_over_span) && height_over_span >= 0.0 && height_over_span <= 100.0,
          fmt::format("Invalid gale h_over_b = {}: must be in [0, 100]", height_over_span));
  require(std::isfinite(sag_parameter) && sag_parameter > 0.0 && sag_parameter < 1.0,
          fmt::format("Invalid gale sag_param = {}: must be in (0, 1)", sag_parameter));
  // With a = 1: span b = 1/(a/b), half-span u = b/(2a); the catenary z = cosh(x) through two
  // points b apart and h higher has its chord midpoint at x_m = asinh(h / (2 sinh u)).
  const double a_over_b = gale_a_over_b(sag_parameter);
  const double b = 1.0 / a_over_b;
  const double u = 0.5 * b;
  const double h = height_over_span * b;
  const double x_mid = std::asinh(h / (2.0 * std::sinh(u)));
  const double xi1 = gale_xi_from_sigma(std::sinh(x_mid - u));
  const double xi2 = gale_xi_from_sigma(std::sinh(x_mid + u));
  // A sag parameter near 0 (or a steep h/b) puts the supports far up the catenary: name the inputs,
  // not the derived xi.
  const double reach = std::max(std::abs(xi1), std::abs(xi2));
  const bool finite = std::isfinite(xi1) && std::isfinite(xi2);
  require(
      finite && reach <= 1e4,
      fmt::format(
          "Invalid gale sag_param = {} with h_over_b = {}: the supports would lie at |xi| = {} "
          "on the catenary, beyond the supported |xi| <= 1e4 (too deep a sag)",
          sag_parameter, height_over_span, finite ? fmt::format("{:.3g}", reach) : "beyond 1e308"));
  Problem problem = make_gale_xi_problem(xi1, xi2);
  problem.form = ProblemForm::GaleSag;
  return problem;
}

void set_taut_inclined_damping(Problem& problem, const SectionDamping& eta) {
  const double t0_n = 1.0;  // the builder's tension at s_a
  const double length = problem.cable.length_m;
  const double impedance = std::sqrt(t0_n * problem.cable.normal_mass_kg_per_m());
  problem.cable.damping.tangential_n_s_per_m2 = eta.tangential_n_s_per_m2 * impedance / length;
  problem.cable.damping.normal_n_s_per_m2 = eta.normal_n_s_per_m2 * impedance / length;
  problem.cable.damping.axial_n_s = eta.axial_n_s * impedance * length;
  problem.validate();
}

void set_gale_damping(Problem& problem, double eta1, double eta2) {
  // rho sqrt(g / a) with rho = m, g = W0 / m, a = H / W0 from the builder's values.
  const CableProperties& c = problem.cable;
  const double horizontal =
      problem.prescribed_forces ? problem.prescribed_forces->horizontal_n : c.weight_n_per_m;
  const double g = c.weight_n_per_m / c.mass_kg_per_m;
  const double a = horizontal / c.weight_n_per_m;
  const double scale = c.mass_kg_per_m * std::sqrt(g / a);
  problem.cable.damping.tangential_n_s_per_m2 = eta1 * scale;
  problem.cable.damping.normal_n_s_per_m2 = eta2 * scale;
  problem.validate();
}

}  // namespace catena
