// Triantafyllou's Airy-function solution (Grinfogel 1984, eqs. 7-16): the 4x4 boundary
// determinant, its roots and null vectors. Model and notation in airy_solver.hpp.
#include "catena/solvers/airy_solver.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>

#include "catena/core/error.hpp"
#include "catena/solvers/asymptotic_solver.hpp"
#include "solvers/internal/airy_functions.hpp"
#include "solvers/internal/asymptotic_formulas.hpp"
#include "solvers/internal/knob_reader.hpp"
#include "solvers/internal/mode_tools.hpp"
#include "solvers/internal/solver_entries.hpp"

namespace catena {
namespace {

// Everything of the model that does not depend on omega.
struct AiryModel {
  double length = 1.0;
  double mass = 1.0;                 // m [kg/m]
  double normal_mass = 1.0;          // M [kg/m]
  double h = 1.0;                    // m / M
  double inverse_ea = 0.0;           // 1/EA [1/N], 0 when inextensible
  double alpha_end[2] = {0.0, 0.0};  // static curvature at s = 0, L [1/m]
  double c_end[2] = {1.0, 1.0};      // sqrt(T/M) at s = 0, L [m/s]
  double travel_time = 0.0;          // int_0^L ds / c [s]
  // alpha^2(s) ~ a2_ref + a2_slope (s - s_ref), so Q(s) = m w^2/EA - h alpha^2 = Q0 (s - s0).
  double a2_ref = 0.0;
  double a2_slope = 0.0;
  double s_ref = 0.0;
  double kappa = 0.0;  // Q0^(1/3), Q0 = -h a2_slope
};

double curvature(const StaticSolution& statics, double s) {
  const double T = statics.tension_n(s);
  return statics.cable().weight_n_per_m * statics.horizontal_force_n() / (T * T);
}

AiryModel build_model(const Problem& problem,
                      const StaticSolution& statics,
                      const DimensionlessGroups& groups,
                      const AirySolverOptions& options) {
  const CableProperties& cable = problem.cable;
  AiryModel model;
  model.length = cable.length_m;
  model.mass = cable.mass_kg_per_m;
  model.normal_mass = cable.normal_mass_kg_per_m();
  model.h = model.mass / model.normal_mass;
  model.inverse_ea = cable.is_inextensible() ? 0.0 : 1.0 / cable.axial_stiffness_n;
  const double ends[2] = {0.0, model.length};
  for (int i = 0; i < 2; ++i) {
    model.alpha_end[i] = curvature(statics, ends[i]);
    model.c_end[i] = std::sqrt(statics.tension_n(ends[i]) / model.normal_mass);
  }
  const double M = model.normal_mass;
  auto slowness = [&](double s) { return std::sqrt(M / statics.tension_n(s)); };
  const double panel = model.length / options.quadrature_panels;
  for (int i = 0; i < options.quadrature_panels; ++i) {
    model.travel_time +=
        boost::math::quadrature::gauss<double, 20>::integrate(slowness, i * panel, (i + 1) * panel);
  }
  const double W0 = cable.weight_n_per_m;
  switch (options.curvature_fit) {
    case AiryCurvatureFit::Tangent: {
      // d(alpha^2)/ds = -4 alpha^2 W0 V / T^2 (alpha = W0 H / T^2, T' = W0 V / T).
      const double s_a = groups.s_at_chord_angle_m;
      const double alpha = curvature(statics, s_a);
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
      const double alpha0 = groups.eps * std::cos(groups.chord_angle_rad) / model.length;
      model.s_ref = 0.5 * model.length;
      model.a2_ref = alpha0 * alpha0;
      model.a2_slope =
          -4.0 * groups.eps * std::sin(groups.chord_angle_rad) * alpha0 * alpha0 / model.length;
      break;
    }
  }
  model.kappa = std::cbrt(-model.h * model.a2_slope);
  return model;
}

// Argument -z(s) = -Q(s) / kappa^2 of the Airy functions.
double airy_argument(const AiryModel& model, double omega, double s) {
  const double q = model.mass * omega * omega * model.inverse_ea -
                   model.h * (model.a2_ref + model.a2_slope * (s - model.s_ref));
  return -q / (model.kappa * model.kappa);
}

// Exponents factored out of the two Airy columns: Ai entries carry e^{-(zeta - ai_ref)} <= 1,
// Bi entries e^{zeta - bi_ref} <= 1 (zeta is monotone in s, so the ends bound the interior).
struct ColumnExponents {
  double ai_ref = 0.0;
  double bi_ref = 0.0;
};

// Raw (unequilibrated) boundary-system rows at station s: the w row and the u row, columns
// (Ai, Bi, cos, sin). `alpha`, `c`, `phase` are the statics at s and W(s).
void station_rows(const AiryModel& model,
                  double omega,
                  double s,
                  double alpha,
                  double c,
                  double phase,
                  const ColumnExponents& exponents,
                  double w_row[4],
                  double u_row[4],
                  double* slow_ai = nullptr,
                  double* slow_bi = nullptr) {
  const internal::ScaledAiry airy = internal::scaled_airy(airy_argument(model, omega, s));
  const double ai_factor = std::exp(-(airy.zeta - exponents.ai_ref));
  const double bi_factor = std::exp(airy.zeta - exponents.bi_ref);
  const double ai = airy.ai * ai_factor;
  const double bi = airy.bi * bi_factor;
  const double cos_w = std::cos(phase);
  const double sin_w = std::sin(phase);
  const double fast_w = 1.0 / std::sqrt(c);
  const double fast_u = alpha * std::sqrt(c) / omega;
  w_row[0] = -model.h * alpha * ai;
  w_row[1] = -model.h * alpha * bi;
  w_row[2] = fast_w * cos_w;
  w_row[3] = fast_w * sin_w;
  u_row[0] = model.kappa * airy.ai_prime * ai_factor;
  u_row[1] = model.kappa * airy.bi_prime * bi_factor;
  u_row[2] = fast_u * sin_w;
  u_row[3] = -fast_u * cos_w;
  if (slow_ai) *slow_ai = ai;
  if (slow_bi) *slow_bi = bi;
}

ColumnExponents column_exponents(const AiryModel& model, double omega) {
  auto zeta = [&](double s) {
    const double x = airy_argument(model, omega, s);
    return x > 0.0 ? 2.0 / 3.0 * x * std::sqrt(x) : 0.0;
  };
  const double z0 = zeta(0.0);
  const double z1 = zeta(model.length);
  return {std::min(z0, z1), std::max(z0, z1)};
}

struct BoundarySystem {
  Eigen::Matrix4d matrix;        // equilibrated
  Eigen::Vector4d column_scale;  // matrix = row_scale * raw * column_scale
  ColumnExponents exponents;
};

BoundarySystem boundary_system(const AiryModel& model, double omega) {
  BoundarySystem system;
  system.exponents = column_exponents(model, omega);
  const double ends[2] = {0.0, model.length};
  const double phases[2] = {0.0, omega * model.travel_time};
  for (int i = 0; i < 2; ++i) {
    double w_row[4], u_row[4];
    station_rows(model, omega, ends[i], model.alpha_end[i], model.c_end[i], phases[i],
                 system.exponents, w_row, u_row);
    for (int j = 0; j < 4; ++j) {
      system.matrix(2 * i, j) = w_row[j];
      system.matrix(2 * i + 1, j) = u_row[j];
    }
  }
  // Equilibrate columns then rows by their largest entries (positive factors).
  for (int j = 0; j < 4; ++j) {
    const double largest = system.matrix.col(j).cwiseAbs().maxCoeff();
    system.column_scale[j] = largest > 0.0 ? 1.0 / largest : 1.0;
    system.matrix.col(j) *= system.column_scale[j];
  }
  for (int i = 0; i < 4; ++i) {
    const double largest = system.matrix.row(i).cwiseAbs().maxCoeff();
    if (largest > 0.0) system.matrix.row(i) /= largest;
  }
  return system;
}

double determinant_at(const AiryModel& model, const DimensionlessGroups& groups, double kl) {
  const double omega = groups.omega_from_k_l_over_pi(kl / kPi);
  return boundary_system(model, omega).matrix.determinant();
}

struct RootScan {
  std::vector<double> roots;  // kL, ascending
  long evaluations = 0;
  int sign_changes = 0;
  int pairs_from_minima = 0;
  double cutoff_kl = 0.0;
  double limit_kl = 0.0;
};

RootScan scan_roots(const AiryModel& model,
                    const DimensionlessGroups& groups,
                    const StaticSolution& statics,
                    int count,
                    const AirySolverOptions& options) {
  RootScan scan;
  // Rigorous lower bound of the first in-plane frequency of the full model (Rayleigh with
  // A >= T/(1+e) I and Mmat <= M I): the string with the smallest tension.
  const double L = model.length;
  const double V_A = statics.vertical_force_n(0.0);
  const double V_B = statics.vertical_force_n(L);
  const double t_min = (V_A <= 0.0 && V_B >= 0.0)
                           ? statics.horizontal_force_n()
                           : std::min(statics.tension_n(0.0), statics.tension_n(L));
  const double stiffness_min = t_min / (1.0 + t_min * model.inverse_ea);
  scan.cutoff_kl = options.cutoff_fraction * kPi * std::sqrt(stiffness_min / groups.t0_n);
  const double limit_over_pi =
      options.max_k_l_over_pi > 0.0 ? options.max_k_l_over_pi : 2.0 * count + 20.0;
  scan.limit_kl = limit_over_pi * kPi;
  const double step = options.scan_step_k_l_over_pi * kPi;

  auto det = [&](double kl) {
    ++scan.evaluations;
    return determinant_at(model, groups, kl);
  };
  const auto tolerance = boost::math::tools::eps_tolerance<double>(options.tolerance_bits);
  auto refine = [&](double a, double b, double fa, double fb) {
    boost::uintmax_t iterations = 100;
    const auto bracket =
        boost::math::tools::toms748_solve(det, a, b, fa, fb, tolerance, iterations);
    scan.roots.push_back(0.5 * (bracket.first + bracket.second));
  };

  double kl_pp = 0.0, d_pp = 0.0;  // two samples back (valid when have_pp)
  bool have_pp = false;
  double kl_p = scan.cutoff_kl;
  double d_p = det(kl_p);
  for (double kl = kl_p + step;
       kl <= scan.limit_kl + 0.5 * step && static_cast<int>(scan.roots.size()) < count;
       kl += step) {
    const double d = det(kl);
    if (d == 0.0) {
      scan.roots.push_back(kl);
      ++scan.sign_changes;
    } else if (d_p != 0.0 && (d > 0.0) != (d_p > 0.0)) {
      refine(kl_p, kl, d_p, d);
      ++scan.sign_changes;
    } else if (have_pp && d_pp != 0.0 && (d_pp > 0.0) == (d_p > 0.0) &&
               std::abs(d_p) < std::abs(d_pp) && std::abs(d_p) < std::abs(d)) {
      // |det| has a grid minimum without a sign change: look for a hidden pair of roots.
      const double sign = d_p > 0.0 ? 1.0 : -1.0;
      boost::uintmax_t iterations = 80;
      const auto minimum = boost::math::tools::brent_find_minima(
          [&](double x) { return sign * det(x); }, kl_pp, kl, 40, iterations);
      if (minimum.second < 0.0) {
        const double d_min = sign * minimum.second;
        refine(kl_pp, minimum.first, d_pp, d_min);
        refine(minimum.first, kl, d_min, d);
        ++scan.pairs_from_minima;
      }
    }
    kl_pp = kl_p;
    d_pp = d_p;
    have_pp = true;
    kl_p = kl;
    d_p = d;
  }
  std::sort(scan.roots.begin(), scan.roots.end());
  if (static_cast<int>(scan.roots.size()) > count)
    scan.roots.resize(static_cast<std::size_t>(count));
  return scan;
}

// Mode shape and tension from the null vector of the boundary system at omega.
void fill_mode(const AiryModel& model,
               const StaticSolution& statics,
               double omega,
               const Vector& stations,
               const Vector& phases,
               Mode& mode,
               double& residual) {
  const BoundarySystem system = boundary_system(model, omega);
  Eigen::JacobiSVD<Eigen::Matrix4d> svd(system.matrix, Eigen::ComputeFullV);
  const Eigen::Vector4d singular = svd.singularValues();
  residual = singular[3] / singular[0];
  const Eigen::Vector4d coefficients = system.column_scale.cwiseProduct(svd.matrixV().col(3));
  const Index n = stations.size();
  mode.s_m = stations;
  mode.w.resize(n);
  mode.u.resize(n);
  mode.tension_n.resize(n);
  for (Index j = 0; j < n; ++j) {
    const double s = stations[j];
    const double c = std::sqrt(statics.tension_n(s) / model.normal_mass);
    double w_row[4], u_row[4], slow_ai = 0.0, slow_bi = 0.0;
    station_rows(model, omega, s, curvature(statics, s), c, phases[j], system.exponents, w_row,
                 u_row, &slow_ai, &slow_bi);
    mode.w[j] = Eigen::Map<const Eigen::RowVector4d>(w_row).dot(coefficients);
    mode.u[j] = Eigen::Map<const Eigen::RowVector4d>(u_row).dot(coefficients);
    // tau = m omega^2 v with v = C1 Ai + C2 Bi (w_slow = -h alpha v).
    mode.tension_n[j] =
        model.mass * omega * omega * (slow_ai * coefficients[0] + slow_bi * coefficients[1]);
  }
}

}  // namespace

std::string to_string(AiryCurvatureFit fit) {
  switch (fit) {
    case AiryCurvatureFit::Tangent:
      return "tangent";
    case AiryCurvatureFit::Secant:
      return "secant";
    case AiryCurvatureFit::Paper:
      return "paper";
  }
  return "?";
}

std::optional<AiryCurvatureFit> parse_airy_curvature_fit(const std::string& text) {
  if (text == "tangent") return AiryCurvatureFit::Tangent;
  if (text == "secant") return AiryCurvatureFit::Secant;
  if (text == "paper") return AiryCurvatureFit::Paper;
  return std::nullopt;
}

void AirySolverOptions::validate() const {
  auto bad = [](const char* field, double value, const char* constraint) {
    throw InvalidInput(fmt::format("Invalid AirySolverOptions::{} = {}. Violated constraint: {}.",
                                   field, value, constraint));
  };
  if (!(scan_step_k_l_over_pi >= 1e-4 && scan_step_k_l_over_pi <= 0.5)) {
    bad("scan_step_k_l_over_pi", scan_step_k_l_over_pi, "1e-4 <= scan_step_k_l_over_pi <= 0.5");
  }
  if (!(cutoff_fraction > 0.0 && cutoff_fraction < 1.0)) {
    bad("cutoff_fraction", cutoff_fraction, "0 < cutoff_fraction < 1");
  }
  if (!(std::isfinite(max_k_l_over_pi) && max_k_l_over_pi >= 0.0)) {
    bad("max_k_l_over_pi", max_k_l_over_pi, "finite and >= 0");
  }
  if (tolerance_bits < 20 || tolerance_bits > 53) {
    bad("tolerance_bits", tolerance_bits, "20 <= tolerance_bits <= 53");
  }
  if (!(std::isfinite(max_eps) && max_eps > 0.0 && max_eps <= 10.0)) {
    bad("max_eps", max_eps, "0 < max_eps <= 10");
  }
  if (!(eps_warning_threshold > 0.0 && eps_warning_threshold <= max_eps)) {
    bad("eps_warning_threshold", eps_warning_threshold, "0 < eps_warning_threshold <= max_eps");
  }
  if (quadrature_panels < 1 || quadrature_panels > 1000) {
    bad("quadrature_panels", quadrature_panels, "1 <= quadrature_panels <= 1000");
  }
}

std::optional<std::string> airy_not_applicable_reason(const Problem& problem,
                                                      const StaticSolution& statics,
                                                      const DimensionlessGroups& groups,
                                                      const AirySolverOptions& options) {
  // Like eq. (21), the Airy model linearises about a slightly stretched string.
  const double strain = internal::static_strain(problem, groups);
  if (strain > internal::kMaxStaticStrain) {
    return fmt::format("static strain T0/EA = {:.3g} > {:.1g}: the small-strain Airy model does not apply",
                       strain, internal::kMaxStaticStrain);
  }
  if (!(statics.horizontal_force_n() > 0.0) || std::abs(std::cos(groups.chord_angle_rad)) < 1e-9) {
    return fmt::format(
        "vertical chord (H = {:.3g} N): the static curvature vanishes and the Airy solution "
        "degenerates",
        statics.horizontal_force_n());
  }
  if (std::abs(std::sin(groups.chord_angle_rad)) < 1e-6) {
    return fmt::format(
        "horizontal chord (phi_a = {:.3g} deg): Q0 = 0 and the Airy solution degenerates into "
        "Irvine's, which the asymptotic solver gives exactly",
        groups.chord_angle_rad * 180.0 / kPi);
  }
  if (groups.eps > options.max_eps) {
    return fmt::format(
        "eps = W0 L / T0 = {:.4g} > max_eps = {:.4g}: the Airy model is asymptotic "
        "in eps (linearised Q, WKB fast solution)",
        groups.eps, options.max_eps);
  }
  return std::nullopt;
}

double airy_frequency_determinant(const Problem& problem,
                                  const StaticSolution& statics,
                                  const DimensionlessGroups& groups,
                                  double k_l,
                                  const AirySolverOptions& options) {
  options.validate();
  const AiryModel model = build_model(problem, statics, groups, options);
  return determinant_at(model, groups, k_l);
}

SolverOutput solve_airy(const Problem& problem,
                        const StaticSolution& statics,
                        const DimensionlessGroups& groups,
                        const SolveRequest& request,
                        const AirySolverOptions& options) {
  options.validate();
  request.validate();
  SolverOutput output;
  output.solver = "airy";
  output.summary.solver = "airy";
  if (auto reason = airy_not_applicable_reason(problem, statics, groups, options)) {
    output.summary.termination = Termination::NotApplicable;
    output.summary.message = *reason;
    return output;
  }
  SolverSummary& summary = output.summary;
  const double eps = groups.eps;
  // O(eps^2) from the model, plus half the static strain T0/EA it neglects in k (see asymptotic).
  const double static_strain = internal::static_strain(problem, groups);
  const double model_error = eps * eps + 0.5 * static_strain;
  const double root_error = std::ldexp(1.0, 1 - options.tolerance_bits);
  const double error_estimate = std::max(model_error, root_error);
  summary.max_error_estimate = error_estimate;
  summary.resolution = fmt::format(
      "scan step kL/pi = {:.3g}, TOMS 748 to {} bits, Q fit '{}', {} x 20-point Gauss-Legendre",
      options.scan_step_k_l_over_pi, options.tolerance_bits, to_string(options.curvature_fit),
      options.quadrature_panels);
  summary.notes.push_back(fmt::format(
      "Triantafyllou's Airy model is asymptotic in eps (linearised Q, WKB fast solution): model "
      "error O(eps^2) + T0/(2 EA) = {:.3g} reported as relative_error_estimate; roots are solved to {:.1e}",
      model_error, root_error));
  if (eps > options.eps_warning_threshold) {
    summary.warnings.push_back(fmt::format(
        "eps = {:.4g} > {:.3g}: the Airy model's linearisation of Q and WKB fast solution lose "
        "accuracy; expect errors of order eps^2 = {:.2g} or worse",
        eps, options.eps_warning_threshold, model_error));
  }
  if (request.forced) {
    summary.warnings.push_back(
        "forced response is not implemented by the airy solver: not computed");
  }
  const CableProperties& cable = problem.cable;
  const double M = cable.normal_mass_kg_per_m();
  const Vector stations = request.stations_m(cable.length_m);
  const bool need_shape = request.shapes || request.tension;
  summary.operations = 0;  // determinant evaluations
  bool complete = true;

  if (request.inplane_modes > 0) {
    const AiryModel model = build_model(problem, statics, groups, options);
    ModalResult result;
    result.plane = Plane::InPlane;
    const RootScan scan = scan_roots(model, groups, statics, request.inplane_modes, options);
    summary.operations += scan.evaluations;
    result.summary.operations = scan.evaluations;
    Vector phases;
    if (need_shape) {
      // W(s_j) = omega * travel time to s_j; the travel time is omega-independent.
      phases.resize(stations.size());
      double travel = 0.0;
      double previous = 0.0;
      auto slowness = [&](double s) { return std::sqrt(M / statics.tension_n(s)); };
      for (Index j = 0; j < stations.size(); ++j) {
        if (stations[j] > previous) {
          travel += boost::math::quadrature::gauss<double, 20>::integrate(slowness, previous,
                                                                          stations[j]);
        }
        previous = stations[j];
        phases[j] = travel;
      }
    }
    double max_residual = 0.0;
    for (std::size_t i = 0; i < scan.roots.size(); ++i) {
      Mode mode;
      mode.index = static_cast<int>(i) + 1;
      const double omega = groups.omega_from_k_l_over_pi(scan.roots[i] / kPi);
      internal::set_mode_frequency(mode, omega, groups);
      mode.relative_error_estimate = error_estimate;
      if (need_shape) {
        double residual = 0.0;
        fill_mode(model, statics, omega, stations, phases * omega, mode, residual);
        max_residual = std::max(max_residual, residual);
        if (!request.tension) mode.tension_n = Vector();
        internal::normalise_inplane_mode(mode);
        mode.modal_mass_kg = internal::inplane_modal_mass(mode, cable.mass_kg_per_m, M);
        if (!request.shapes) {
          mode.s_m = Vector();
          mode.u = Vector();
          mode.w = Vector();
          mode.tension_n = Vector();
          mode.modal_mass_kg = -1.0;
        }
      }
      result.modes.push_back(std::move(mode));
    }
    result.summary.solver = "airy";
    result.summary.resolution = summary.resolution;
    result.summary.max_error_estimate = error_estimate;
    result.summary.max_residual = need_shape ? max_residual : -1.0;
    summary.max_residual = result.summary.max_residual;
    const int found = static_cast<int>(result.modes.size());
    result.summary.notes.push_back(fmt::format(
        "scan kL/pi in [{:.4g}, {:.4g}] ({} determinants): {} sign changes, {} close pairs found "
        "at |det| minima; roots below kL/pi = {:.4g} (spurious, WKB invalid) skipped; no proof of "
        "count",
        scan.cutoff_kl / kPi, (scan.roots.empty() ? scan.limit_kl : scan.roots.back()) / kPi,
        scan.evaluations, scan.sign_changes, scan.pairs_from_minima, scan.cutoff_kl / kPi));
    // Cross-check the count with eq. (21), whose count is exact (its model differs by O(eps^2),
    // and it has no axial modes, so a difference is a warning, not an error).
    if (found > 0 && !cable.is_inextensible()) {
      const double axial_kl =
          first_axial_k_l(eps, groups.chord_angle_rad, groups.lambda2, groups.mass_ratio);
      if (scan.roots.back() < 0.5 * axial_kl) {
        const auto eq21 =
            grinfogel_eq21_roots(found + 2, eps, groups.chord_angle_rad, groups.lambda2);
        const auto below = std::count_if(eq21.begin(), eq21.end(), [&](double kl) {
          return kl < scan.roots.back() * (1.0 + 1e-9);
        });
        if (below != found &&
            std::abs(eq21[static_cast<std::size_t>(found - 1)] / scan.roots.back() - 1.0) >
                3.0 * model_error) {
          result.summary.warnings.push_back(fmt::format(
              "eq. (21) has {} roots below the top Airy root kL/pi = {:.6g} but the scan found {}: "
              "check with a finer scan_step_k_l_over_pi",
              below, scan.roots.back() / kPi, found));
        }
      }
    }
    if (found > 0 && scan.roots.front() < 1.1 * scan.cutoff_kl) {
      result.summary.warnings.push_back(
          fmt::format("the first root kL/pi = {:.4g} lies within 10% of the spurious-root cutoff "
                      "{:.4g}: it may "
                      "be the model's spurious low root (eps = {:.3g} is large)",
                      scan.roots.front() / kPi, scan.cutoff_kl / kPi, eps));
    }
    if (found < request.inplane_modes) {
      complete = false;
      result.summary.termination = Termination::NoConvergence;
      result.summary.message =
          fmt::format("No convergence: {} of {} in-plane roots below kL/pi = {:.4g}", found,
                      request.inplane_modes, scan.limit_kl / kPi);
    } else {
      result.summary.termination = Termination::Converged;
      result.summary.message = fmt::format(
          "Converged: {} of {} in-plane roots of the Airy determinant to {} bits{}", found,
          request.inplane_modes, options.tolerance_bits,
          need_shape ? fmt::format(", max sigma_min/sigma_max {:.1e}", max_residual) : "");
    }
    result.summary.warnings.insert(result.summary.warnings.begin(), summary.warnings.begin(),
                                   summary.warnings.end());
    output.inplane = std::move(result);
  }

  if (request.outofplane_modes > 0) {
    ModalResult result = internal::wkb_outofplane_modes(statics, groups, request, M, error_estimate,
                                                        options.quadrature_panels, "airy");
    result.summary.message =
        fmt::format("Converged: {} out-of-plane WKB string modes (the Airy model is in-plane only)",
                    result.modes.size());
    result.summary.max_error_estimate = error_estimate;
    output.outofplane = std::move(result);
  }

  summary.termination = complete ? Termination::Converged : Termination::NoConvergence;
  summary.message = fmt::format(
      "{}: {} in-plane Airy-determinant roots and {} out-of-plane (WKB) modes",
      complete ? "Converged" : "No convergence", output.inplane ? output.inplane->modes.size() : 0,
      output.outofplane ? output.outofplane->modes.size() : 0);
  return output;
}

namespace internal {

AirySolverOptions read_airy_options(const SolverKnobs& knobs) {
  KnobReader reader("airy", knobs);
  AirySolverOptions options;
  const std::string fit = reader.get_string("curvature_fit", to_string(options.curvature_fit));
  const auto parsed = parse_airy_curvature_fit(fit);
  if (!parsed) {
    throw InvalidInput(fmt::format("{} = \"{}\": must be \"tangent\", \"secant\" or \"paper\"",
                                   reader.key("curvature_fit"), fit));
  }
  options.curvature_fit = *parsed;
  options.scan_step_k_l_over_pi = reader.get_double("scan_step", options.scan_step_k_l_over_pi);
  if (!(options.scan_step_k_l_over_pi >= 1e-4 && options.scan_step_k_l_over_pi <= 0.5)) {
    throw InvalidInput(fmt::format("{} = {}: must be in [1e-4, 0.5] (kL/pi)",
                                   reader.key("scan_step"), options.scan_step_k_l_over_pi));
  }
  options.cutoff_fraction = reader.get_double("cutoff_fraction", options.cutoff_fraction);
  options.max_k_l_over_pi = reader.get_double("max_k_l_over_pi", options.max_k_l_over_pi);
  options.tolerance_bits =
      static_cast<int>(reader.get_integer("tolerance_bits", options.tolerance_bits));
  options.eps_warning_threshold =
      reader.get_double("eps_warning_threshold", options.eps_warning_threshold);
  options.max_eps = reader.get_double("max_eps", options.max_eps);
  options.quadrature_panels =
      static_cast<int>(reader.get_integer("quadrature_panels", options.quadrature_panels));
  reader.reject_unknown();
  try {
    options.validate();
  } catch (const InvalidInput& error) {
    throw InvalidInput(fmt::format("[solvers.airy]: {}", error.what()));
  }
  return options;
}

SolverEntry make_airy_entry() {
  SolverEntry entry;
  entry.name = "airy";
  entry.description =
      "Triantafyllou's Airy-function solution (Grinfogel 1984, eqs. 12-16): roots of the 4x4 "
      "boundary determinant with exponentially scaled Ai, Bi; the paper's 'exact' reference";
  entry.knobs = {
      {"curvature_fit", "linearisation of Q(s): \"tangent\" (default), \"secant\", \"paper\""},
      {"scan_step", "scan step in kL/pi, default 0.05, in [1e-4, 0.5]"},
      {"cutoff_fraction", "spurious-root cutoff as a fraction of the string bound, default 0.75"},
      {"max_k_l_over_pi", "scan limit in kL/pi (0: 2 modes + 20)"},
      {"tolerance_bits", "root tolerance in bits, default 50, in [20, 53]"},
      {"eps_warning_threshold", "eps above which a validity warning is given; default 0.3"},
      {"max_eps", "eps above which the solver declines; default 1.0"},
      {"quadrature_panels", "panels of 20-point Gauss-Legendre for the travel time; default 4"},
  };
  entry.not_applicable_reason = [](const SolveContext& context) -> std::optional<std::string> {
    // Structural reasons only: the eps limit is a knob (max_eps, at most 10), which this hook
    // cannot see; run() applies it and returns NotApplicable itself.
    AirySolverOptions permissive;
    permissive.max_eps = 10.0;
    return airy_not_applicable_reason(context.problem, context.statics, context.groups, permissive);
  };
  entry.validate_knobs = [](const SolverKnobs& knobs) { read_airy_options(knobs); };
  entry.run = [](const SolveContext& context, const SolverKnobs& knobs) {
    return solve_airy(context.problem, context.statics, context.groups, context.request,
                      read_airy_options(knobs));
  };
  return entry;
}

}  // namespace internal
}  // namespace catena
