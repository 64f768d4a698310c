// SPDX-License-Identifier: MIT
// Fields of the frobenius solver: see frobenius_fields.hpp.
#include "solvers/frobenius/frobenius_fields.hpp"

#include <Eigen/SVD>
#include <cmath>

#include "solvers/common/mode_tools.hpp"

namespace catena::internal {

namespace {

// Unqualified sqrt must find the floating-point overloads for double and long double (and
// Boost's by ADL for QuadFloat).
using std::sqrt;

// Mode shapes from the fields at `stations` (units a and H to m and N).
void set_inplane_shape(Mode& mode,
                       const std::vector<FieldValues>& values,
                       bool tension,
                       const CableUnits& units) {
  const Index n = mode.s_m.size();
  mode.u.resize(n);
  mode.w.resize(n);
  if (tension) mode.tension_n.resize(n);
  for (Index k = 0; k < n; ++k) {
    const FieldValues& f = values[static_cast<std::size_t>(k)];
    mode.u(k) = units.length_m * f.u;
    mode.w(k) = units.length_m * f.v;
    if (tension) mode.tension_n(k) = units.tension_n * f.t;
  }
}

// Keeps only the frequency and (in plane, when asked) max |T| of a mode computed on the dense
// internal stations.
void strip_dense_fields(Mode& mode, bool keep_max_tension) {
  drop_shape_fields(mode);
  if (!keep_max_tension) mode.max_abs_tension_n = -1.0;
}

}  // namespace

template <class Real>
std::vector<Real> null_vector(const PlaneSetup& setup, double omega) {
  const auto m = boundary_matrix<Real>(setup, Real(omega));
  const Index n = static_cast<Index>(m.a.size());
  Eigen::MatrixXd a(n, n);
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j)
      a(i, j) = static_cast<double>(m.a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullV);
  const Eigen::VectorXd v = svd.matrixV().col(n - 1);
  std::vector<Real> c(static_cast<std::size_t>(n));
  for (Index j = 0; j < n; ++j)
    c[static_cast<std::size_t>(j)] = Real(v(j)) / m.column_scale[static_cast<std::size_t>(j)];
  return c;
}

template <class Real>
std::vector<FieldValues> fields(const PlaneSetup& setup,
                                double omega,
                                const std::vector<Real>& c,
                                const std::vector<double>& sigmas,
                                bool with_tension) {
  CatenaryBasis<Real> basis(setup.inplane, Real(omega), Real(setup.mu), setup.eta_max,
                            setup.settings);
  const int derivatives = setup.inplane ? (with_tension ? 3 : 1) : 0;
  std::vector<FieldValues> out;
  const Real w2mu = Real(omega) * Real(omega) * Real(setup.mu);
  for (double sigma_d : sigmas) {
    const Real sigma(sigma_d);
    const auto b = basis.evaluate(sigma, derivatives, SeriesErrors::Skipped);  // values only
    Real d[4] = {Real(0), Real(0), Real(0), Real(0)};
    for (std::size_t j = 0; j < static_cast<std::size_t>(basis.size()); ++j)
      for (std::size_t k = 0; k <= static_cast<std::size_t>(derivatives); ++k)
        d[k] += c[j] * b.value[j][k];
    FieldValues f;
    f.u = static_cast<double>(d[0]);
    if (setup.inplane) {
      const Real q = sigma * sigma;
      const Real C = sqrt(Real(1) + q);
      f.v = static_cast<double>(q * d[1] + d[1]);
      if (with_tension)
        f.t = static_cast<double>(sigma / C * d[0] -
                                  ((Real(3) + Real(4) * q) * C + w2mu * C * C * C * C) * d[1] -
                                  Real(5) * sigma * C * C * C * d[2] - C * C * C * C * C * d[3]);
    }
    out.push_back(f);
  }
  return out;
}

#define CATENA_FROBENIUS_FIELDS_INSTANTIATE(Real)                          \
  template std::vector<Real> null_vector<Real>(const PlaneSetup&, double); \
  template std::vector<FieldValues> fields<Real>(                          \
      const PlaneSetup&, double, const std::vector<Real>&, const std::vector<double>&, bool);
CATENA_FROBENIUS_FIELDS_INSTANTIATE(double)
CATENA_FROBENIUS_FIELDS_INSTANTIATE(long double)
CATENA_FROBENIUS_FIELDS_INSTANTIATE(QuadFloat)
#undef CATENA_FROBENIUS_FIELDS_INSTANTIATE

std::vector<FieldValues> mode_fields(Precision p,
                                     const PlaneSetup& setup,
                                     double omega,
                                     const std::vector<double>& sigmas,
                                     bool with_tension) {
  return with_precision(p, [&](auto zero) {
    using Real = decltype(zero);
    return fields<Real>(setup, omega, null_vector<Real>(setup, omega), sigmas, with_tension);
  });
}

int interior_sign_changes(const Vector& v) {
  int changes = 0;
  for (Index k = 2; k + 1 < v.size(); ++k)
    if ((v(k) < 0.0) != (v(k - 1) < 0.0)) ++changes;
  return changes;
}

int add_mode_fields(Mode& mode,
                    const PlaneSetup& setup,
                    double omega,
                    Precision p,
                    const ModeFieldRequest& request,
                    const CableUnits& units) {
  const bool want_fields = request.shapes || request.tension || !setup.inplane;
  if (!want_fields) return -1;
  const bool dense = !request.shapes;
  const FieldStations& stations = dense ? *request.dense : *request.stations;
  const bool with_tension = setup.inplane && request.tension;
  const auto values = mode_fields(p, setup, omega, stations.sigma, with_tension);
  mode.s_m = stations.s_m;
  int sign_changes = -1;
  if (setup.inplane) {
    set_inplane_shape(mode, values, request.tension, units);
    normalise_inplane_mode(mode);
    mode.modal_mass_kg = inplane_modal_mass(mode, units.mass_kg_per_m, units.normal_mass_kg_per_m);
  } else {
    mode.v.resize(stations.s_m.size());
    for (Index k = 0; k < stations.s_m.size(); ++k)
      mode.v(k) = units.length_m * values[static_cast<std::size_t>(k)].u;
    sign_changes = interior_sign_changes(mode.v);
    normalise_outofplane_mode(mode);
    mode.modal_mass_kg = outofplane_modal_mass(mode, units.normal_mass_kg_per_m);
  }
  if (dense) strip_dense_fields(mode, with_tension);
  return sign_changes;
}

}  // namespace catena::internal
