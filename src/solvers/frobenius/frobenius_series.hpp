// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// A general Frobenius / Taylor power-series engine for linear ODEs with polynomial coefficients,
///
///     sum_{k=0}^{n} p_k(x) y^{(k)}(x) = 0,      p_k(x) = sum_j p_{k,j} x^j,
///
/// used by the `frobenius` solver (Gale 1976, sec. II.4; docs/reference/references.md) but
/// independent of it.
///
/// About a regular singular (or ordinary) point x = 0, substituting y = sum_m a_m x^{m+r} and
/// collecting the power x^{N + r + d_min} gives, with the shift polynomials
///
///     Q_d(nu) = sum_k p_{k,k+d} nu (nu-1) ... (nu-k+1),     d = j - k,   d_min = min d,
///
/// the indicial equation Q_{d_min}(r) = 0 and the recurrence (generated, never hand-typed)
///
///     Q_{d_min}(N + r) a_N = - sum_{d > d_min} Q_d(N + r - (d - d_min)) a_{N - (d - d_min)}.
///
/// At an ordinary point d_min = -n and the roots are r = 0..n-1; at a regular singular point the
/// roots come from the indicial polynomial. Where two roots differ by an integer the recurrence of
/// the smaller one meets Q_{d_min}(N + r) = 0: when its right side vanishes too the coefficient is
/// free (set to 0, so the solution is distinct from the larger root's), otherwise the solution has
/// a logarithm, which this engine reports instead of computing.
///
/// Everything is templated on the real type (double, long double, Boost.Multiprecision) so that a
/// caller can re-run in extended precision when it detects cancellation. The coefficients (and so
/// the series and their values) may also be complex, Scalar = std::complex<Real> (the damped
/// catenary, lambda complex); exponents, the variable x and every magnitude stay Real.

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace catena::internal {

/// The real type behind a scalar: Real itself, or T for std::complex<T>.
template <class Scalar>
struct RealOf {
  using type = Scalar;
};
template <class T>
struct RealOf<std::complex<T>> {
  using type = T;
};
template <class Scalar>
using RealOfT = typename RealOf<Scalar>::type;

/// A polynomial sum_j c[j] x^j with coefficients of type Real.
template <class Real>
using Polynomial = std::vector<Real>;

/// Linear ODE sum_k p[k](x) y^(k) = 0 (p.size() = order + 1, p.back() not identically zero).
template <class Real>
struct PolynomialOde {
  std::vector<Polynomial<Real>> p;

  int order() const { return static_cast<int>(p.size()) - 1; }

  /// The same ODE in t = x - c (Taylor shift of every coefficient polynomial, exact in Real).
  PolynomialOde shifted(const Real& c) const {
    PolynomialOde out;
    out.p.reserve(p.size());
    for (const auto& poly : p) {
      // Horner-style synthetic division: coefficients of poly(t + c).
      Polynomial<Real> q = poly;
      const std::size_t n = q.size();
      for (std::size_t i = 0; i + 1 < n; ++i)
        for (std::size_t j = n - 1; j > i; --j) q[j - 1] += c * q[j];
      out.p.push_back(q);
    }
    return out;
  }

  /// Converts the coefficient type.
  template <class Other>
  PolynomialOde<Other> cast() const {
    PolynomialOde<Other> out;
    for (const auto& poly : p) {
      Polynomial<Other> q;
      for (const auto& c : poly) q.push_back(static_cast<Other>(c));
      out.p.push_back(q);
    }
    return out;
  }
};

/// Roots of a real polynomial (coefficients low to high, double) by the companion matrix.
inline std::vector<std::complex<double>> polynomial_roots(std::vector<double> c) {
  while (!c.empty() && c.back() == 0.0) c.pop_back();
  const int degree = static_cast<int>(c.size()) - 1;
  std::vector<std::complex<double>> roots;
  if (degree < 1) return roots;
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(degree, degree);
  for (int i = 1; i < degree; ++i) companion(i, i - 1) = 1.0;
  for (int i = 0; i < degree; ++i) companion(i, degree - 1) = -c[i] / c[degree];
  Eigen::EigenSolver<Eigen::MatrixXd> solver(companion, false);
  for (int i = 0; i < degree; ++i) roots.push_back(solver.eigenvalues()(i));
  return roots;
}

/// The shift structure of an ODE about x = 0: d_min and the coefficients p_{k,k+d}.
template <class Real>
class ShiftTable {
 public:
  explicit ShiftTable(const PolynomialOde<Real>& ode) : order_(ode.order()) {
    d_min_ = std::numeric_limits<int>::max();
    int d_max = std::numeric_limits<int>::min();
    for (int k = 0; k <= order_; ++k)
      for (int j = 0; j < static_cast<int>(ode.p[k].size()); ++j)
        if (ode.p[k][j] != Real(0)) {
          d_min_ = std::min(d_min_, j - k);
          d_max = std::max(d_max, j - k);
        }
    if (d_min_ == std::numeric_limits<int>::max())
      throw std::invalid_argument("ODE is identically zero");
    width_ = d_max - d_min_ + 1;
    coefficient_.assign(static_cast<std::size_t>(width_ * (order_ + 1)), Real(0));
    for (int k = 0; k <= order_; ++k)
      for (int j = 0; j < static_cast<int>(ode.p[k].size()); ++j)
        if (ode.p[k][j] != Real(0)) at(j - k - d_min_, k) = ode.p[k][j];
    for (int e = 1; e < width_; ++e) {
      bool zero = true;
      for (int k = 0; k <= order_; ++k) zero = zero && at(e, k) == Real(0);
      if (!zero) active_.push_back(e);
    }
  }

  int d_min() const { return d_min_; }
  /// Number of shifts d = d_min .. d_min + width - 1.
  int width() const { return width_; }
  int order() const { return order_; }
  /// True when x = 0 is a regular singular or ordinary point: the lowest shift involves the
  /// highest derivative (Fuchs' condition, in this form).
  bool is_regular() const { return at(0, order_) != Real(0); }

  /// Q_{d_min + e}(nu) = sum_k p_{k,k+d} nu (nu-1) ... (nu-k+1).
  Real q(int e, const Real& nu) const {
    // Nested form a_0 + nu (a_1 + (nu - 1)(a_2 + (nu - 2)(...))): exact zeros of the falling
    // factorials at small integers are kept (resonances are detected exactly).
    Real sum = at(e, order_);
    for (int k = order_ - 1; k >= 0; --k) sum = at(e, k) + (nu - Real(k)) * sum;
    return sum;
  }

  /// The shifts e >= 1 whose Q_e is not identically zero.
  const std::vector<int>& active_shifts() const { return active_; }

  /// Indicial polynomial Q_{d_min}(r) as coefficients in r (double, for root finding).
  std::vector<double> indicial_polynomial() const {
    std::vector<double> result(order_ + 1, 0.0);
    std::vector<double> falling{1.0};  // r (r-1) ... (r-k+1), low to high
    for (int k = 0; k <= order_; ++k) {
      for (std::size_t i = 0; i < falling.size(); ++i)
        result[i] += static_cast<double>(at(0, k)) * falling[i];
      std::vector<double> next(falling.size() + 1, 0.0);
      for (std::size_t i = 0; i < falling.size(); ++i) {
        next[i + 1] += falling[i];
        next[i] -= static_cast<double>(k) * falling[i];
      }
      falling = next;
    }
    return result;
  }

 private:
  Real& at(int e, int k) { return coefficient_[static_cast<std::size_t>(e * (order_ + 1) + k)]; }
  const Real& at(int e, int k) const {
    return coefficient_[static_cast<std::size_t>(e * (order_ + 1) + k)];
  }
  int order_;
  int d_min_;
  int width_;
  std::vector<Real> coefficient_;
  std::vector<int> active_;
};

/// Real indicial roots about x = 0, ascending; snapped to the nearest multiple of 1/2^20 when
/// within 1e-9 of it (roots of the indicial polynomial of an integer-coefficient ODE are usually
/// rational). Throws std::domain_error for complex roots or an irregular point.
template <class Real>
std::vector<double> indicial_roots(const PolynomialOde<Real>& ode) {
  ShiftTable<Real> table(ode);
  if (!table.is_regular()) throw std::domain_error("x = 0 is an irregular singular point");
  std::vector<double> roots;
  for (const auto& z : polynomial_roots(table.indicial_polynomial())) {
    if (std::abs(z.imag()) > 1e-8 * (1.0 + std::abs(z)))
      throw std::domain_error("complex indicial root");
    double r = z.real();
    const double snapped = std::round(r * 1048576.0) / 1048576.0;
    if (std::abs(r - snapped) < 1e-9) r = snapped;
    roots.push_back(r);
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

/// A series solution y = sum_m a[m] x^(m + r) about x = 0 (the exponent r is real).
template <class Scalar>
struct FrobeniusSeries {
  RealOfT<Scalar> r = RealOfT<Scalar>(0);
  std::vector<Scalar> a;
};

/// Result of evaluating a series (and derivatives) at one point.
template <class Scalar>
struct SeriesValue {
  /// derivative[k] = y^(k)(x).
  std::vector<Scalar> derivative;
  /// Largest |term| of each derivative's sum (for the cancellation ratio max|term| / |sum|).
  std::vector<RealOfT<Scalar>> largest_term;
  /// Estimate of the truncation error of each derivative (last terms, geometric tail).
  std::vector<RealOfT<Scalar>> truncation;
};

/// Whether Q_{d_min}(nu) = `lead` vanishes at nu (a resonant index of the recurrence): |lead| at
/// most 1e-9 of the indicial polynomial's size nearby, max_k |Q_{d_min}(nu + k)| for k = 1..order
/// (the polynomial's scale there, never all zero: it has at most `order` roots), or 1 when that is
/// larger. The scale is relative so that an ordinary point very close to a singular one, where the
/// whole indicial polynomial is small, is not mistaken for a resonance.
template <class Scalar>
bool is_resonant_index(const ShiftTable<Scalar>& table, const Scalar& lead, const Scalar& nu) {
  using std::abs;
  using Real = RealOfT<Scalar>;
  Real scale = abs(table.q(0, nu + Scalar(1)));
  const bool tiny_polynomial = scale < Real(1);
  if (tiny_polynomial)
    for (int k = 2; k <= table.order(); ++k)
      scale = std::max(scale, Real(abs(table.q(0, nu + Scalar(k)))));
  return abs(lead) <= Real(1e-9) * (tiny_polynomial ? std::min(scale, Real(1)) : scale + Real(1));
}

/// Generates coefficients of the solution with indicial root `r` (a[0] = 1 and, at resonant
/// indices N where Q_{d_min}(N + r) = 0, a[N] = `resonant_value(N)`, default 0), up to index
/// `num_terms - 1`. Throws std::domain_error when a resonance carries a logarithm.
template <class Scalar>
FrobeniusSeries<Scalar> frobenius_series(const ShiftTable<Scalar>& table,
                                         const RealOfT<Scalar>& r,
                                         int num_terms,
                                         const std::vector<Scalar>& initial = {Scalar(1)}) {
  using std::abs;
  using Real = RealOfT<Scalar>;
  FrobeniusSeries<Scalar> series;
  series.r = r;
  series.a.assign(static_cast<std::size_t>(num_terms), Scalar(0));
  for (int N = 0; N < num_terms; ++N) {
    Scalar rhs(0);
    Real scale(0);
    for (const int e : table.active_shifts()) {
      if (e > N) break;
      const Scalar term =
          table.q(e, Scalar(Real(N - e) + r)) * series.a[static_cast<std::size_t>(N - e)];
      rhs -= term;
      scale += abs(term);
    }
    const Scalar lead = table.q(0, Scalar(Real(N) + r));
    if (is_resonant_index(table, lead, Scalar(Real(N) + r))) {
      // Resonance: free coefficient if the right side vanishes.
      if (abs(rhs) > Real(1e-8) * (scale + Real(1e-300)) && abs(rhs) > Real(1e-12))
        throw std::domain_error("logarithmic solution at resonant index " + std::to_string(N));
      series.a[static_cast<std::size_t>(N)] = static_cast<std::size_t>(N) < initial.size()
                                                  ? initial[static_cast<std::size_t>(N)]
                                                  : Scalar(0);
    } else {
      series.a[static_cast<std::size_t>(N)] = rhs / lead;
    }
  }
  return series;
}

/// What evaluate_series computes besides the values: the largest term and the truncation estimate
/// of each derivative (the error bounds of the boundary matrix), or the values alone (fields and
/// conjugate-point signs, which use nothing else: about a third of the work).
enum class SeriesErrors { Tracked, Skipped };

/// Evaluates y^(k)(x), k = 0..max_derivative (<= 3), of the series with coefficients `a` and
/// exponent `r`, for x > 0 (or any x when r is a non-negative integer), term by term, with the
/// truncation estimate from the last `tail` terms assuming a geometric tail of ratio `ratio` =
/// |x| / radius (< 1) unless `errors` is Skipped (largest_term and truncation then stay 0).
template <class Scalar>
SeriesValue<Scalar> evaluate_series(const std::vector<Scalar>& a,
                                    const RealOfT<Scalar>& r,
                                    const RealOfT<Scalar>& x,
                                    int max_derivative,
                                    const RealOfT<Scalar>& ratio,
                                    SeriesErrors errors = SeriesErrors::Tracked) {
  using std::abs;
  using std::pow;
  using Real = RealOfT<Scalar>;
  if (max_derivative < 0 || max_derivative > 3)
    throw std::domain_error("evaluate_series: derivatives 0..3 only");
  SeriesValue<Scalar> value;
  const bool tracked = errors == SeriesErrors::Tracked;
  const std::size_t K1 = static_cast<std::size_t>(max_derivative + 1);
  value.derivative.assign(K1, Scalar(0));
  value.largest_term.assign(K1, Real(0));
  value.truncation.assign(K1, Real(0));
  const int n = static_cast<int>(a.size());
  const int K = max_derivative;
  // term_{m,k} = a_m nu (nu-1)...(nu-k+1) x^(nu-k), nu = m + r, computed as a_m ff_k x^m x^(r-k).
  const bool at_origin = x == Real(0);
  std::array<Real, 4> base{Real(1), Real(1), Real(1), Real(1)};
  if (!at_origin) {
    using std::floor;
    for (int k = 0; k <= K; ++k) {
      const Real exponent = r - Real(k);
      Real b(1);
      if (exponent == Real(floor(exponent))) {  // integer power: valid for negative x too
        const int p = static_cast<int>(exponent);
        for (int i = 0; i < (p < 0 ? -p : p); ++i) b = p < 0 ? Real(b / x) : Real(b * x);
      } else {
        b = pow(x, exponent);
      }
      base[static_cast<std::size_t>(k)] = b;
    }
  }
  // Away from the origin x^(r-k) is common to every term of derivative k: the sums run over
  // a_m ff_k(nu) x^m and are scaled by base[k] once at the end (as are the largest and last
  // terms), which halves the long-double multiplications of this loop, the hot spot of the forced
  // response (a Gale C-2 curve of 301 forcing frequencies spends 70% of its time here).
  std::array<Real, 4> last{Real(0), Real(0), Real(0), Real(0)};
  std::array<Real, 4> scale = base;
  if (at_origin) scale.fill(Real(1));
  Real xm(1);
  for (int m = 0; m < n; ++m, xm *= x) {
    const Scalar& c = a[static_cast<std::size_t>(m)];
    if (c == Scalar(0)) continue;
    const Real nu = Real(m) + r;
    Scalar product = at_origin ? c : Scalar(c * xm);  // a_m ff_k(nu) x^m, k = 0 first
    for (int k = 0; k <= K; ++k) {
      if (k > 0) product *= (nu - Real(k - 1));
      if (product == Scalar(0)) continue;
      Scalar term = product;
      if (at_origin) {
        const Real power = nu - Real(k);
        term = power == Real(0)
                   ? product
                   : (power > Real(0) ? Scalar(0) : Scalar(std::numeric_limits<Real>::infinity()));
      }
      const std::size_t kk = static_cast<std::size_t>(k);
      value.derivative[kk] += term;
      if (!tracked) continue;
      const Real magnitude = abs(term);
      if (magnitude > value.largest_term[kk]) value.largest_term[kk] = magnitude;
      if (m >= n - 3 && magnitude > last[kk]) last[kk] = magnitude;
    }
  }
  for (int k = 0; k <= K; ++k) {
    const std::size_t kk = static_cast<std::size_t>(k);
    value.derivative[kk] *= scale[kk];
    value.largest_term[kk] *= abs(scale[kk]);
    last[kk] *= abs(scale[kk]);
  }
  if (!tracked) return value;
  for (int k = 0; k <= K; ++k)
    value.truncation[static_cast<std::size_t>(k)] =
        ratio < Real(1) ? last[static_cast<std::size_t>(k)] * ratio / (Real(1) - ratio)
                        : std::numeric_limits<Real>::infinity();
  return value;
}

/// evaluate_series for a FrobeniusSeries (its coefficients and exponent).
template <class Scalar>
SeriesValue<Scalar> evaluate_series(const FrobeniusSeries<Scalar>& series,
                                    const RealOfT<Scalar>& x,
                                    int max_derivative,
                                    const RealOfT<Scalar>& ratio,
                                    SeriesErrors errors = SeriesErrors::Tracked) {
  return evaluate_series(series.a, series.r, x, max_derivative, ratio, errors);
}

/// Number of terms needed so that |a_m| rho^m stays below `tolerance` * max_m |a_m| rho^m for the
/// last `window` terms, with rho the largest distance at which the series will be evaluated; the
/// coefficients are generated one at a time (the recurrence of frobenius_series) up to
/// `max_terms`. Returns the series and sets `converged`.
template <class Scalar>
FrobeniusSeries<Scalar> adaptive_series(const ShiftTable<Scalar>& table,
                                        const RealOfT<Scalar>& r,
                                        const RealOfT<Scalar>& rho,
                                        double tolerance,
                                        int max_terms,
                                        bool& converged,
                                        const std::vector<Scalar>& initial = {Scalar(1)}) {
  using std::abs;
  using Real = RealOfT<Scalar>;
  FrobeniusSeries<Scalar> series;
  series.r = r;
  series.a.reserve(static_cast<std::size_t>(std::min(max_terms, 256)));
  const int window = 6;
  const int minimum = 12;
  Real largest(0), power(1);
  std::vector<Real> recent(static_cast<std::size_t>(window), Real(0));
  converged = false;
  for (int N = 0; N < max_terms; ++N) {
    Scalar rhs(0);
    Real scale(0);
    for (const int e : table.active_shifts()) {
      if (e > N) break;
      const Scalar term =
          table.q(e, Scalar(Real(N - e) + r)) * series.a[static_cast<std::size_t>(N - e)];
      rhs -= term;
      scale += abs(term);
    }
    const Scalar lead = table.q(0, Scalar(Real(N) + r));
    Scalar value;
    if (is_resonant_index(table, lead, Scalar(Real(N) + r))) {
      if (abs(rhs) > Real(1e-8) * (scale + Real(1e-300)) && abs(rhs) > Real(1e-12))
        throw std::domain_error("logarithmic solution at resonant index " + std::to_string(N));
      value = static_cast<std::size_t>(N) < initial.size() ? initial[static_cast<std::size_t>(N)]
                                                           : Scalar(0);
    } else {
      value = rhs / lead;
    }
    series.a.push_back(value);
    const Real t = abs(value) * power;
    power *= rho;
    largest = std::max(largest, t);
    recent[static_cast<std::size_t>(N % window)] = t;
    if (N + 1 >= minimum) {
      Real tail(0);
      for (const auto& x : recent) tail = std::max(tail, x);
      if (tail <= Real(tolerance) * largest) {
        converged = true;
        break;
      }
    }
  }
  return series;
}

}  // namespace catena::internal
