// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Series solutions of the inextensible catenary's linear equations (Gale 1976, sec. II.4;
/// docs/reference/references.md) on the general engine of frobenius_series.hpp.
///
/// Units: lengths in a = H/W0, sigma = (s - s_apex)/a, C = sqrt(1 + sigma^2), eta = |xi| = C - 1,
/// q = sigma^2 = eta (2 + eta), Omega = w / sqrt(g/a) (g = W0/m), mu = M/m. D = d/dsigma.
///
/// In-plane (tangential U, normal V, dynamic tension T / H;
/// verification/tools/frobenius_derive_odes.py):
///   eta^2 (1+eta)(2+eta)^2 U'''' + 2 eta (2+eta)(3+10 eta+5 eta^2) U'''
///     + [3(1+eta)(1+16 eta+8 eta^2) + mu W2 eta (1+eta)^2 (2+eta)] U''
///     + [6(1+4 eta+2 eta^2) + mu W2 (1+eta)(1+8 eta+4 eta^2)] U' - W2 U = 0        (Gale 2.42)
///   V = C^2 DU                                                                         (2.36)
///   T = (sigma/C) U - [(3+4 sigma^2) C + mu W2 C^4] DU - 5 sigma C^3 D^2U - C^5 D^3U  (2.37)
/// Out of plane: eta (2+eta) v'' + (1+eta) v' + mu W2 (1+eta) v = 0                     (2.44)
/// (' = d/deta, W2 = Omega^2). The equation in eta is the same on both sides of the apex.
///
/// Basis: the Frobenius solutions F_j(eta) about eta = 0, exponents 0, 1/2, 1, 3/2 (in-plane) or
/// 0, 1/2 (out of plane). Every solution is analytic in sigma; the integer exponents give solutions
/// even in sigma, the half-integer ones odd: U_j(sigma) = F_j(|xi|) or sign(sigma) F_j(|xi|). This
/// is the continuity across xi = 0 (Gale 2.53-2.56: D_j = C_j for the integer, -C_j for the
/// half-integer exponents). Near the apex the odd solutions are evaluated as sigma h(eta),
/// h = eta^(r-1/2) S(eta) / sqrt(2+eta), so that the sigma-derivatives have no cancelling
/// eta^(-1/2) terms. Beyond the disc of the singular expansion, Taylor expansions about ordinary
/// points c_1 < c_2 < ... continue each F_j analytically (values and derivatives at c_{k+1} from
/// the expansion about c_k); c_{k+1} = c_k + rho R_k with R_k the distance from c_k to the nearest
/// singular point (eta = 0, -1, -2) and rho = step_ratio, so any eta is reachable.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "solvers/frobenius/frobenius_series.hpp"

namespace catena::internal {

/// Series resolution settings.
struct CatenarySeriesSettings {
  /// Relative size of the last terms (against the largest) at which a series is cut.
  double term_tolerance = 1e-16;
  /// Cap on the number of terms per expansion.
  int max_terms = 400;
  /// Distance between expansion centres as a fraction of the radius of convergence, (0, 0.9].
  double step_ratio = 0.5;
  /// Largest phase Omega * integral sqrt(mu/C) dsigma a solution may turn through between an
  /// expansion's centre and the ends of its reach; 0: no limit. At high Omega a solution is a wave
  /// of wave number Omega sqrt(mu/C) (WKB) and the terms of a series reaching a phase P grow to
  /// about e^P before they cancel to O(1): the limit keeps that cancellation below e^P, by placing
  /// more centres (frobenius_forced.hpp sets it; the natural frequencies keep the radius rule).
  double max_phase_per_expansion = 0.0;
  /// Cap on the number of expansion centres when max_phase_per_expansion is set (the basis then
  /// stops short of eta_max and reports it by covers()).
  int max_centres = 0;
};

/// The WKB phase rate d(phase)/d(eta) = Omega sqrt(mu (1+eta) / (eta (2+eta))) of the waves of
/// both planes (from the leading terms of Gale 2.42 and 2.44 at large Omega).
inline double wave_phase_rate(double omega, double mu, double eta) {
  return omega * std::sqrt(mu * (1.0 + eta) / (eta * (2.0 + eta)));
}

/// The eta at which the phase from the apex, Omega sqrt(mu) sigma to leading order near the apex
/// (and an upper bound beyond it, since C >= 1), reaches `phase`.
inline double eta_at_apex_phase(double omega, double mu, double phase) {
  const double sigma = phase / (omega * std::sqrt(mu));
  return sigma * sigma / (std::sqrt(1.0 + sigma * sigma) + 1.0);
}

/// The ODE in eta of one plane (coefficients of y, y', ...), with the tangential inertia w2 =
/// Omega^2 and the normal inertia mw = mu Omega^2 as separate parameters: in a viscous medium
/// (Gale's eqs. 2.33a,b, 2.34 with motion ~ e^(lambda t)) w2 = -(lambda^2 + eta1 lambda) and
/// mw = -(mu lambda^2 + eta2 lambda), complex (verification/tools/frobenius_derive_damped_odes.py).
template <class Real>
PolynomialOde<Real> catenary_ode_inertia(bool inplane, const Real& w2, const Real& mw) {
  PolynomialOde<Real> ode;
  if (inplane) {
    ode.p = {
        {-w2},
        {Real(6) + mw, Real(24) + Real(9) * mw, Real(12) + Real(12) * mw, Real(4) * mw},
        {Real(3), Real(51) + Real(2) * mw, Real(72) + Real(5) * mw, Real(24) + Real(4) * mw, mw},
        {Real(0), Real(12), Real(46), Real(40), Real(10)},
        {Real(0), Real(0), Real(4), Real(8), Real(5), Real(1)}};
  } else {
    ode.p = {{mw, mw}, {Real(1), Real(1)}, {Real(0), Real(2), Real(1)}};
  }
  return ode;
}

/// The undamped ODE in eta of one plane at Omega^2 = w2.
template <class Real>
PolynomialOde<Real> catenary_ode(bool inplane, const Real& w2, const Real& mu) {
  const Real mw = mu * w2;
  return catenary_ode_inertia<Real>(inplane, w2, mw);
}

/// Solves the small dense system A x = b (Gaussian elimination, partial pivoting).
template <class Real>
std::vector<Real> solve_dense(std::vector<std::vector<Real>> A, std::vector<Real> b) {
  using std::abs;
  const std::size_t n = A.size();
  b.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    for (std::size_t i = k + 1; i < n; ++i)
      if (abs(A[i][k]) > abs(A[p][k])) p = i;
    std::swap(A[k], A[p]);
    std::swap(b[k], b[p]);
    for (std::size_t i = k + 1; i < n; ++i) {
      const Real f = A[i][k] / A[k][k];
      for (std::size_t j = k; j < n; ++j) A[i][j] -= f * A[k][j];
      b[i] -= f * b[k];
    }
  }
  std::vector<Real> x(n);
  for (std::size_t k = n; k-- > 0;) {
    Real sum = b[k];
    for (std::size_t j = k + 1; j < n; ++j) sum -= A[k][j] * x[j];
    x[k] = sum / A[k][k];
  }
  return x;
}

/// Determinant of a small dense matrix (Gaussian elimination, partial pivoting).
template <class Real>
Real determinant(std::vector<std::vector<Real>> A) {
  using std::abs;
  const std::size_t n = A.size();
  Real det(1);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    for (std::size_t i = k + 1; i < n; ++i)
      if (abs(A[i][k]) > abs(A[p][k])) p = i;
    if (A[p][k] == Real(0)) return Real(0);
    if (p != k) {
      std::swap(A[k], A[p]);
      det = -det;
    }
    det *= A[k][k];
    for (std::size_t i = k + 1; i < n; ++i) {
      const Real f = A[i][k] / A[k][k];
      for (std::size_t j = k; j < n; ++j) A[i][j] -= f * A[k][j];
    }
  }
  return det;
}

/// Singular points: roots of the leading coefficient. Multiple roots come out of the companion
/// matrix only to ~sqrt(eps): snapped to nearby dyadic rationals (the coefficients are small
/// integers).
inline std::vector<std::complex<double>> leading_roots(const PolynomialOde<double>& ode) {
  std::vector<std::complex<double>> result;
  for (auto z : polynomial_roots(ode.p.back())) {
    const double re = std::round(z.real() * 1024.0) / 1024.0;
    if (std::abs(z - std::complex<double>(re, 0.0)) < 1e-6) z = re;
    result.push_back(z);
  }
  return result;
}

/// D^k U_j (k = 0..3) of each basis function at one sigma, with absolute error estimates.
template <class Scalar>
struct BasisValues {
  using Real = RealOfT<Scalar>;
  int size = 0;
  std::array<std::array<Scalar, 4>, 4> value{};  // [j][k]
  std::array<std::array<Real, 4>, 4> error{};    // truncation + rounding estimate
  /// Largest single term of the series sums behind basis function j (for max term / |sum|).
  std::array<Real, 4> largest_term{};
};

/// The series basis of one plane at one frequency, valid for 0 <= eta <= eta_max. Scalar is Real
/// (undamped) or std::complex<Real> (damped: complex coefficients, real sigma and eta).
template <class Real, class Scalar = Real>
class CatenaryBasis {
 public:
  CatenaryBasis(bool inplane,
                const Real& omega,
                const Real& mu,
                double eta_max,
                const CatenarySeriesSettings& settings)
      : CatenaryBasis(inplane,
                      catenary_ode<Scalar>(inplane, Scalar(omega * omega), Scalar(mu)),
                      static_cast<double>(omega),
                      static_cast<double>(mu),
                      eta_max,
                      settings) {}

  /// The basis of the ODE `ode` (catenary_ode_inertia); omega and mu set the wave phase rate
  /// that CatenarySeriesSettings::max_phase_per_expansion limits (|lambda| for a damped ODE).
  CatenaryBasis(bool inplane,
                const PolynomialOde<Scalar>& ode,
                double omega,
                double mu,
                double eta_max,
                const CatenarySeriesSettings& settings)
      : inplane_(inplane), n_(inplane ? 4 : 2), omega_(omega), mu_(mu) {
    // Indicial roots (0, 1/2, 1, 3/2 in plane; 0, 1/2 out of plane) and singular points (roots of
    // the leading coefficient: 0, -1, -2 in plane; 0, -2 out of plane), both from the polynomials.
    // Neither depends on the frequency: computed once per plane.
    static const std::vector<double> roots_in =
        indicial_roots(catenary_ode<double>(true, 1.0, 1.0));
    static const std::vector<double> roots_out =
        indicial_roots(catenary_ode<double>(false, 1.0, 1.0));
    static const std::vector<std::complex<double>> singular_in =
        leading_roots(catenary_ode<double>(true, 1.0, 1.0));
    static const std::vector<std::complex<double>> singular_out =
        leading_roots(catenary_ode<double>(false, 1.0, 1.0));
    roots_ = inplane ? roots_in : roots_out;
    singular_ = inplane ? singular_in : singular_out;
    add_apex_expansion(ode, settings);
    // Ordinary centres until eta_max is covered (or the cap on centres is reached).
    covers_ = true;
    while (centres_.back() + reach_.back() < eta_max) {
      if (settings.max_centres > 0 && num_centres() >= settings.max_centres) {
        covers_ = false;
        break;
      }
      add_ordinary_expansion(ode, settings);
    }
  }

  int size() const { return n_; }
  bool converged() const { return converged_; }
  long total_terms() const { return total_terms_; }
  int num_centres() const { return static_cast<int>(centres_.size()); }
  /// False when max_centres stopped the expansions short of eta_max.
  bool covers() const { return covers_; }
  double exponent(int j) const { return roots_[static_cast<std::size_t>(j)]; }

  /// D^k U_j(sigma), k = 0..max_derivative (<= 3); with `errors` Skipped the error and
  /// largest_term entries stay 0 (for callers that use the values alone).
  BasisValues<Scalar> evaluate(const Real& sigma,
                               int max_derivative,
                               SeriesErrors errors = SeriesErrors::Tracked) const {
    using std::sqrt;
    BasisValues<Scalar> out;
    out.size = n_;
    const Real q = sigma * sigma;
    const Real eta = q / (sqrt(Real(1) + q) + Real(1));
    const int k = centre_index(static_cast<double>(eta));
    for (std::size_t j = 0; j < static_cast<std::size_t>(n_); ++j) {
      const bool odd = roots_[j] != std::floor(roots_[j]);
      if (k == 0 && odd)
        odd_near_apex(j, sigma, eta, max_derivative, errors, out);
      else
        from_series_in_eta(j, k, odd, sigma, eta, max_derivative, errors, out);
    }
    return out;
  }

 private:
  // Centre 0: the singular point (the apex), where the Frobenius series are built.
  void add_apex_expansion(const PolynomialOde<Scalar>& ode,
                          const CatenarySeriesSettings& settings) {
    const double r0 = radius(0.0);
    double rho = settings.step_ratio;
    if (settings.max_phase_per_expansion > 0.0)
      rho = std::min(rho, eta_at_apex_phase(omega_, mu_, settings.max_phase_per_expansion) / r0);
    centres_.push_back(0.0);
    reach_.push_back(rho * r0);
    const ShiftTable<Scalar> table0(ode);
    for (int j = 0; j < n_; ++j) {
      bool ok = false;
      singular_series_.push_back(adaptive_series(table0, Real(roots_[static_cast<std::size_t>(j)]),
                                                 Real(rho * r0), settings.term_tolerance,
                                                 settings.max_terms, ok));
      converged_ = converged_ && ok;
      total_terms_ += static_cast<long>(singular_series_.back().a.size());
    }
    ratio_.push_back(rho);
    lower_.push_back(0.0);
  }

  // The next centre c is placed so that the matching point x_m (the right end of the previous
  // disc, at rho of its radius) lies at rho of the new radius on its left: c - rho R(c) = x_m
  // (Gale matches at a point where both series converge). Bisection on c.
  double next_centre(double x_m, double rho) const {
    double lo = x_m, hi = x_m + 1.0;
    while (hi - rho * radius(hi) < x_m) hi = x_m + 2.0 * (hi - x_m);
    for (int it = 0; it < 200 && hi - lo > 1e-14 * hi; ++it) {
      const double mid = 0.5 * (lo + hi);
      (mid - rho * radius(mid) < x_m ? lo : hi) = mid;
    }
    return hi;
  }

  // A Taylor expansion about the next ordinary centre, continuing every basis function: the
  // unit solutions there are combined to match the previous expansion's derivatives at x_m.
  void add_ordinary_expansion(const PolynomialOde<Scalar>& ode,
                              const CatenarySeriesSettings& settings) {
    double rho = settings.step_ratio;
    const double x_m = centres_.back() + reach_.back();
    double c = next_centre(x_m, rho);
    double step = rho * radius(c);
    // The wave limit: the phase rate falls with eta, so its value at x_m bounds it on the disc.
    const double wave_step =
        settings.max_phase_per_expansion > 0.0
            ? settings.max_phase_per_expansion / wave_phase_rate(omega_, mu_, x_m)
            : step;
    if (wave_step < step) {
      c = x_m + wave_step;
      step = wave_step;
      rho = step / radius(c);
    }
    const ShiftTable<Scalar> table(ode.shifted(Scalar(c)));
    std::vector<FrobeniusSeries<Scalar>> unit;
    std::size_t longest = 0;
    for (int m = 0; m < n_; ++m) {
      bool ok = false;
      unit.push_back(adaptive_series(table, Real(m), Real(step), settings.term_tolerance,
                                     settings.max_terms, ok));
      converged_ = converged_ && ok;
      longest = std::max(longest, unit.back().a.size() + static_cast<std::size_t>(m));
    }
    const std::size_t n = static_cast<std::size_t>(n_);
    // Matching at x_m: B[d][m] = b_m^(d)(x_m - c); solve B coef_j = F_j^(d)(x_m).
    const Real t_m = Real(x_m) - Real(c);
    std::vector<std::vector<Scalar>> B(n, std::vector<Scalar>(n));
    for (std::size_t m = 0; m < n; ++m) {
      const auto v = evaluate_series(unit[m], t_m, n_ - 1, Real(rho));
      for (std::size_t d = 0; d < n; ++d) B[d][m] = v.derivative[d];
    }
    std::vector<FrobeniusSeries<Scalar>> combined(n);
    for (std::size_t j = 0; j < n; ++j) {
      const auto d = raw_derivatives(static_cast<int>(centres_.size()) - 1, static_cast<int>(j),
                                     Real(x_m), n_ - 1);
      const std::vector<Scalar> coef = solve_dense(B, d.derivative);
      auto& s = combined[j];
      s.r = Real(0);
      s.a.assign(longest, Scalar(0));
      for (std::size_t m = 0; m < n; ++m)
        for (std::size_t i = 0; i < unit[m].a.size(); ++i) s.a[i + m] += coef[m] * unit[m].a[i];
      total_terms_ += static_cast<long>(longest);
    }
    centres_.push_back(c);
    lower_.push_back(x_m);
    reach_.push_back(step);
    ratio_.push_back(rho);
    ordinary_series_.push_back(combined);
  }

  // An odd (half-integer exponent) basis function near the apex: U = sigma h(eta),
  // h = g(eta) (2+eta)^(-1/2), g = eta^(r-1/2) S(eta) (integer powers), so that the
  // sigma-derivatives have no cancelling eta^(-1/2) terms.
  void odd_near_apex(std::size_t j,
                     const Real& sigma,
                     const Real& eta,
                     int max_derivative,
                     SeriesErrors errors,
                     BasisValues<Scalar>& out) const {
    using std::abs;
    using std::sqrt;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const FrobeniusSeries<Scalar>& s =
        singular_series_[j];  // g: its coefficients, exponent r - 1/2
    const auto gv =
        evaluate_series(s.a, Real(s.r - Real(0.5)), eta, max_derivative, Real(ratio_[0]), errors);
    for (const auto& x : gv.largest_term) out.largest_term[j] = std::max(out.largest_term[j], x);
    // Derivatives in eta of h by Leibniz's rule with w = (2+eta)^(-1/2).
    std::array<Real, 4> w{}, he{};
    std::array<Scalar, 4> h{};
    const Real root = sqrt(Real(2) + eta);
    w[0] = Real(1) / root;
    for (std::size_t i = 1; i < 4; ++i)
      w[i] = w[i - 1] * (Real(0.5) - Real(static_cast<int>(i))) / (Real(2) + eta);
    static const int binom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
    for (std::size_t d = 0; d <= static_cast<std::size_t>(max_derivative); ++d)
      for (std::size_t i = 0; i <= d; ++i) {
        h[d] += Real(binom[d][i]) * gv.derivative[i] * w[d - i];
        he[d] += Real(binom[d][i]) * (gv.truncation[i] + eps * gv.largest_term[i]) * abs(w[d - i]);
      }
    sigma_derivatives_of_odd(j, sigma, eta, h, he, max_derivative, out);
  }

  // D^k (sigma h(eta)) from the eta-derivatives h, with their error bounds he.
  void sigma_derivatives_of_odd(std::size_t j,
                                const Real& sigma,
                                const Real& eta,
                                const std::array<Scalar, 4>& h,
                                const std::array<Real, 4>& he,
                                int max_derivative,
                                BasisValues<Scalar>& out) const {
    using std::abs;
    const Real q = sigma * sigma;
    const Real C = Real(1) + eta;
    auto& f = out.value[j];
    auto& fe = out.error[j];
    const Real qc = q / C, iC2 = Real(1) / (C * C), iC3 = iC2 / C;
    f[0] = sigma * h[0];
    fe[0] = abs(sigma) * he[0];
    if (max_derivative >= 1) {
      f[1] = h[0] + qc * h[1];
      fe[1] = he[0] + qc * he[1];
    }
    const Scalar e1p = (Real(2) + iC2) * h[1] + qc * h[2];
    const Real e1pe = (Real(2) + iC2) * he[1] + qc * he[2];
    if (max_derivative >= 2) {
      f[2] = sigma / C * e1p;
      fe[2] = abs(sigma) / C * e1pe;
    }
    if (max_derivative >= 3) {
      const Scalar e1pp = Real(-2) * iC3 * h[1] + (Real(3) + Real(2) * iC2) * h[2] + qc * h[3];
      const Real e1ppe = Real(2) * iC3 * he[1] + (Real(3) + Real(2) * iC2) * he[2] + qc * he[3];
      f[3] = iC3 * e1p + q * iC2 * e1pp;
      fe[3] = iC3 * e1pe + q * iC2 * e1ppe;
    }
  }

  // Basis function j from expansion k as a series in eta, U_j = F_j(|xi|) (even) or
  // sign(sigma) F_j(|xi|) (odd), converted to sigma-derivatives (D eta = sigma / C).
  void from_series_in_eta(std::size_t j,
                          int k,
                          bool odd,
                          const Real& sigma,
                          const Real& eta,
                          int max_derivative,
                          SeriesErrors errors,
                          BasisValues<Scalar>& out) const {
    using std::abs;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const SeriesValue<Scalar> v =
        raw_derivatives(k, static_cast<int>(j), eta, max_derivative, errors);
    std::array<Scalar, 4> F{};
    std::array<Real, 4> Fe{};
    for (const auto& x : v.largest_term) out.largest_term[j] = std::max(out.largest_term[j], x);
    for (std::size_t d = 0; d <= static_cast<std::size_t>(max_derivative); ++d) {
      F[d] = v.derivative[d];
      Fe[d] = v.truncation[d] + eps * v.largest_term[d];
    }
    const Real q = sigma * sigma;
    const Real C = Real(1) + eta;
    const Real sign = (odd && sigma < Real(0)) ? Real(-1) : Real(1);
    const Real iC = Real(1) / C, iC2 = iC * iC, iC3 = iC2 * iC;
    auto& f = out.value[j];
    auto& fe = out.error[j];
    f[0] = sign * F[0];
    fe[0] = Fe[0];
    if (max_derivative >= 1) {
      f[1] = sign * sigma * iC * F[1];
      fe[1] = abs(sigma) * iC * Fe[1];
    }
    if (max_derivative >= 2) {
      f[2] = sign * (q * iC2 * F[2] + iC3 * F[1]);
      fe[2] = q * iC2 * Fe[2] + iC3 * Fe[1];
    }
    if (max_derivative >= 3) {
      f[3] =
          sign * sigma * (q * iC3 * F[3] + Real(3) * iC2 * iC2 * F[2] - Real(3) * iC2 * iC3 * F[1]);
      fe[3] = abs(sigma) *
              (q * iC3 * Fe[3] + Real(3) * iC2 * iC2 * Fe[2] + Real(3) * iC2 * iC3 * Fe[1]);
    }
  }

  double radius(double c) const {
    double r = 1e300;
    for (const auto& s : singular_)
      if (std::abs(c - s) > 1e-9) r = std::min(r, std::abs(c - s));
    return r;
  }

  int centre_index(double eta) const {
    int k = 0;
    while (k + 1 < static_cast<int>(centres_.size()) &&
           eta >= lower_[static_cast<std::size_t>(k + 1)])
      ++k;
    return k;
  }

  /// F_j^(m)(eta), m = 0..max_derivative, from expansion k (eta > 0).
  SeriesValue<Scalar> raw_derivatives(int k,
                                      int j,
                                      const Real& eta,
                                      int max_derivative,
                                      SeriesErrors errors = SeriesErrors::Tracked) const {
    if (k == 0)
      return evaluate_series(singular_series_[static_cast<std::size_t>(j)], eta, max_derivative,
                             Real(ratio_[0]), errors);
    return evaluate_series(
        ordinary_series_[static_cast<std::size_t>(k - 1)][static_cast<std::size_t>(j)],
        Real(eta - Real(centres_[static_cast<std::size_t>(k)])), max_derivative,
        Real(ratio_[static_cast<std::size_t>(k)]), errors);
  }

  bool inplane_;
  int n_;
  double omega_;
  double mu_;
  bool covers_ = true;
  std::vector<double> roots_;
  std::vector<std::complex<double>> singular_;
  std::vector<double> centres_;
  std::vector<double> reach_;
  std::vector<double> lower_;
  std::vector<double> ratio_;
  std::vector<FrobeniusSeries<Scalar>> singular_series_;
  std::vector<std::vector<FrobeniusSeries<Scalar>>> ordinary_series_;
  bool converged_ = true;
  long total_terms_ = 0;
};

}  // namespace catena::internal
