// SPDX-License-Identifier: MIT
// The damped boundary problem of the frobenius solver: see frobenius_damped_boundary.hpp.
#include "solvers/frobenius/frobenius_damped_boundary.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "solvers/common/mode_tools.hpp"

namespace catena::internal {

namespace {

using Basis = CatenaryBasis<DampedReal, DampedComplex>;

Basis damped_basis(const DampedSetup& setup, const DampedComplex& lambda, double term_scale) {
  const DampedInertia in = damped_inertia(setup, lambda);
  CatenarySeriesSettings settings = setup.plane.settings;
  // Terms below long double's epsilon of the largest change nothing: the finest cut. A coarser
  // cut (term_scale > 1, the argument count's phase) stops at 1e-9.
  settings.term_tolerance = std::clamp(settings.term_tolerance * term_scale, 1e-19,
                                       std::max(settings.term_tolerance, 1e-9));
  // The undamped parameters Omega^2 -> -mu1, mu Omega^2 -> -mu2.
  const auto ode = catenary_ode_inertia<DampedComplex>(setup.plane.inplane, -in.mu1, -in.mu2);
  return Basis(setup.plane.inplane, ode, static_cast<double>(std::abs(lambda)), setup.plane.mu,
               setup.plane.eta_max, settings);
}

}  // namespace

DampedInertia damped_inertia(const DampedSetup& setup, const DampedComplex& lambda) {
  const DampedReal mu = setup.plane.mu;
  return {lambda * lambda + DampedReal(setup.eta1) * lambda,
          mu * lambda * lambda + DampedReal(setup.eta2) * lambda};
}

DampedMatrix damped_boundary_matrix(const DampedSetup& setup,
                                    const DampedComplex& lambda,
                                    double term_scale) {
  const Basis basis = damped_basis(setup, lambda, term_scale);
  const std::size_t n = static_cast<std::size_t>(basis.size());
  const std::size_t derivatives = setup.plane.inplane ? 1 : 0;
  DampedMatrix m;
  m.a.assign(n, std::vector<DampedComplex>(n));
  m.error.assign(n, std::vector<DampedReal>(n));
  m.terms = basis.total_terms();
  m.centres = basis.num_centres();
  m.converged = basis.converged();
  m.column_scale.assign(n, DampedReal(0));
  std::vector<DampedReal> largest(n, DampedReal(0));
  std::size_t row = 0;
  for (double sigma : {setup.plane.sigma1, setup.plane.sigma2}) {
    const auto v = basis.evaluate(DampedReal(sigma), static_cast<int>(n) - 1);
    for (std::size_t j = 0; j < n; ++j) {
      largest[j] = std::max(largest[j], v.largest_term[j]);
      for (std::size_t d = 0; d < n; ++d) m.column_scale[j] += std::norm(v.value[j][d]);
    }
    for (std::size_t d = 0; d <= derivatives; ++d, ++row)
      for (std::size_t j = 0; j < n; ++j) {
        m.a[row][j] = v.value[j][d];
        m.error[row][j] = v.error[j][d];
      }
  }
  for (std::size_t j = 0; j < n; ++j) {
    const DampedReal big = std::sqrt(m.column_scale[j]);
    m.column_scale[j] = big > DampedReal(0) ? big : DampedReal(1);
    m.cancellation = std::max(m.cancellation, static_cast<double>(largest[j] / m.column_scale[j]));
    for (std::size_t i = 0; i < n; ++i) {
      m.a[i][j] /= m.column_scale[j];
      m.error[i][j] /= m.column_scale[j];
    }
  }
  return m;
}

DampedComplex damped_determinant(const std::vector<std::vector<DampedComplex>>& a) {
  return determinant(a);
}

std::vector<DampedComplex> damped_null_vector(const DampedSetup& setup,
                                              const DampedComplex& lambda) {
  const DampedMatrix m = damped_boundary_matrix(setup, lambda);
  const Index n = static_cast<Index>(m.a.size());
  Eigen::MatrixXcd a(n, n);
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j) {
      const DampedComplex& x = m.a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      a(i, j) = {static_cast<double>(x.real()), static_cast<double>(x.imag())};
    }
  Eigen::JacobiSVD<Eigen::MatrixXcd> svd(a, Eigen::ComputeFullV);
  const Eigen::VectorXcd v = svd.matrixV().col(n - 1);
  std::vector<DampedComplex> c(static_cast<std::size_t>(n));
  for (Index j = 0; j < n; ++j)
    c[static_cast<std::size_t>(j)] =
        DampedComplex(v(j).real(), v(j).imag()) / m.column_scale[static_cast<std::size_t>(j)];
  return c;
}

std::vector<DampedFieldValues> damped_fields(const DampedSetup& setup,
                                             const DampedComplex& lambda,
                                             const std::vector<DampedComplex>& c,
                                             const std::vector<double>& sigmas,
                                             bool with_tension) {
  const Basis basis = damped_basis(setup, lambda, 1.0);
  const bool inplane = setup.plane.inplane;
  const int derivatives = inplane ? (with_tension ? 3 : 1) : 0;
  const DampedComplex mu2 = damped_inertia(setup, lambda).mu2;
  std::vector<DampedFieldValues> out;
  for (double sigma_d : sigmas) {
    const DampedReal sigma(sigma_d);
    const auto b = basis.evaluate(sigma, derivatives, SeriesErrors::Skipped);
    DampedComplex d[4] = {};
    for (std::size_t j = 0; j < static_cast<std::size_t>(basis.size()); ++j)
      for (std::size_t k = 0; k <= static_cast<std::size_t>(derivatives); ++k)
        d[k] += c[j] * b.value[j][k];
    DampedFieldValues f;
    f.u = d[0];
    if (inplane) {
      const DampedReal q = sigma * sigma;
      const DampedReal C = std::sqrt(DampedReal(1) + q);
      const DampedReal C4 = C * C * C * C;
      f.v = (DampedReal(1) + q) * d[1];
      if (with_tension)
        f.t = sigma / C * d[0] - ((DampedReal(3) + DampedReal(4) * q) * C - mu2 * C4) * d[1] -
              DampedReal(5) * sigma * C * C * C * d[2] - C4 * C * d[3];
    }
    out.push_back(f);
  }
  return out;
}

void add_damped_mode_fields(Mode& mode,
                            const DampedSetup& setup,
                            const DampedComplex& lambda,
                            const ModeFieldRequest& request,
                            const CableUnits& units) {
  const bool inplane = setup.plane.inplane;
  if (!request.shapes && !(request.tension && inplane)) return;
  const FieldStations& stations = request.shapes ? *request.stations : *request.dense;
  const bool with_tension = inplane && request.tension;
  const auto values =
      damped_fields(setup, lambda, damped_null_vector(setup, lambda), stations.sigma, with_tension);
  const Index n = stations.s_m.size();
  mode.s_m = stations.s_m;
  auto fill = [&](Vector& re, Vector& im, auto get, double unit) {
    re.resize(n);
    im.resize(n);
    for (Index k = 0; k < n; ++k) {
      const DampedComplex x = get(values[static_cast<std::size_t>(k)]) * DampedReal(unit);
      re(k) = static_cast<double>(x.real());
      im(k) = static_cast<double>(x.imag());
    }
  };
  std::string by = "v";
  if (inplane) {
    fill(
        mode.u, mode.u_imag, [](const DampedFieldValues& f) { return f.u; }, units.length_m);
    fill(
        mode.w, mode.w_imag, [](const DampedFieldValues& f) { return f.v; }, units.length_m);
    if (with_tension)
      fill(
          mode.tension_n, mode.tension_imag_n, [](const DampedFieldValues& f) { return f.t; },
          units.tension_n);
    const double w_max = (mode.w.cwiseAbs2() + mode.w_imag.cwiseAbs2()).maxCoeff();
    const double u_max = (mode.u.cwiseAbs2() + mode.u_imag.cwiseAbs2()).maxCoeff();
    by = std::sqrt(w_max) <= 1e-6 * std::sqrt(u_max) ? "u" : "w";
  } else {
    fill(
        mode.v, mode.v_imag, [](const DampedFieldValues& f) { return f.u; }, units.length_m);
  }
  normalise_complex_mode(mode, by);
  if (!request.shapes) {
    const double keep = mode.max_abs_tension_n;
    drop_shape_fields(mode);
    mode.u_imag = mode.w_imag = mode.v_imag = mode.tension_imag_n = Vector();
    mode.max_abs_tension_n = with_tension ? keep : -1.0;
  }
}

}  // namespace catena::internal
