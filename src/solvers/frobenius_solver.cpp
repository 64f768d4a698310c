// The `frobenius` solver: Gale's power series for the inextensible catenary (DESIGN.md §2.3).
// The series machinery is in solvers/internal/frobenius_series.hpp (general engine) and
// frobenius_catenary.hpp (the catenary's equations and basis); this file finds the frequencies,
// builds modes and forced responses, and reports.
#include "catena/solvers/frobenius_solver.hpp"

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "solvers/internal/frobenius_catenary.hpp"
#include "solvers/internal/knob_reader.hpp"
#include "solvers/internal/mode_tools.hpp"
#include "solvers/internal/solver_entries.hpp"

namespace catena {

using internal::CatenaryBasis;
using internal::CatenarySeriesSettings;
using Quad = boost::multiprecision::cpp_bin_float_quad;

void FrobeniusSolverOptions::validate() const {
  auto fail = [](const std::string& field, double value, const std::string& range) {
    std::ostringstream text;
    text << "FrobeniusSolverOptions." << field << " = " << value << " is outside " << range;
    throw InvalidInput(text.str());
  };
  if (!(tolerance >= 1e-15 && tolerance <= 1e-3)) fail("tolerance", tolerance, "[1e-15, 1e-3]");
  if (max_terms < 8 || max_terms > 5000) fail("max_terms", max_terms, "[8, 5000]");
  if (!(step_ratio >= 0.1 && step_ratio <= 0.8)) fail("step_ratio", step_ratio, "[0.1, 0.8]");
  if (!(scan_fraction >= 0.01 && scan_fraction <= 0.5)) fail("scan_fraction", scan_fraction, "[0.01, 0.5]");
}

std::string frobenius_not_applicable_reason(const Problem& problem, const DimensionlessGroups& groups) {
  if (!problem.cable.is_inextensible())
    return "the frobenius solver models an inextensible cable (EA = inf, Gale 1976); this cable has EA = " +
           std::to_string(problem.cable.axial_stiffness_n) + " N";
  if (!groups.has_apex_parameterization || !(groups.catenary_parameter_m > 0.0))
    return "the frobenius solver needs a catenary with H > 0 (Gale's parameter a = H/W0 is undefined)";
  if (!(problem.cable.weight_n_per_m > 0.0))
    return "the frobenius solver needs a positive weight W0 (Gale's catenary)";
  return {};
}

namespace {

// Unqualified abs/sqrt below must find the floating-point overloads for double and long double
// (and Boost's by ADL for quad), never the C library's int abs.
using std::abs;
using std::sqrt;

/// What one plane's problem needs.
struct PlaneSetup {
  bool inplane = true;
  double sigma1 = 0.0;
  double sigma2 = 0.0;
  double mu = 1.0;
  double eta_max = 0.0;
  CatenarySeriesSettings settings;
};

enum class Precision { Double = 0, LongDouble = 1, Quad = 2 };
const char* precision_name(Precision p) {
  return p == Precision::Double ? "double" : (p == Precision::LongDouble ? "long double" : "quad (113-bit)");
}

/// The boundary matrix (rows: U, DU at sigma1, then sigma2; out of plane U only) and its error
/// estimates, in Real.
template <class Real>
struct BoundaryMatrix {
  std::vector<std::vector<Real>> a;
  std::vector<std::vector<Real>> error;
  std::vector<Real> column_scale;
  /// max_j (largest series term behind column j) / (column norm): digits lost to cancellation.
  double cancellation = 1.0;
  long terms = 0;
  int centres = 0;
  bool converged = true;
};

template <class Real>
BoundaryMatrix<Real> boundary_matrix(const PlaneSetup& setup, const Real& omega) {
  CatenaryBasis<Real> basis(setup.inplane, omega, Real(setup.mu), setup.eta_max, setup.settings);
  const int n = basis.size();
  const int derivatives = setup.inplane ? 1 : 0;
  BoundaryMatrix<Real> m;
  m.a.assign(static_cast<std::size_t>(n), std::vector<Real>(static_cast<std::size_t>(n)));
  m.error = m.a;
  m.terms = basis.total_terms();
  m.centres = basis.num_centres();
  m.converged = basis.converged();
  // Columns are scaled by the norm of all derivatives D^0..D^(n-1) U_j at both ends: positive and
  // smooth in omega (they cannot all vanish), so the scaled det keeps its sign and zeros and stays
  // continuous, while its size becomes comparable across omega and precisions.
  m.column_scale.assign(static_cast<std::size_t>(n), Real(0));
  std::vector<Real> largest(static_cast<std::size_t>(n), Real(0));
  int row = 0;
  for (double sigma : {setup.sigma1, setup.sigma2}) {
    const auto v = basis.evaluate(Real(sigma), n - 1);
    for (int j = 0; j < n; ++j) largest[static_cast<std::size_t>(j)] = std::max(largest[static_cast<std::size_t>(j)], v.largest_term[static_cast<std::size_t>(j)]);
    for (int j = 0; j < n; ++j)
      for (int d = 0; d < n; ++d)
        m.column_scale[static_cast<std::size_t>(j)] += v.value[static_cast<std::size_t>(j)][static_cast<std::size_t>(d)] *
                                                       v.value[static_cast<std::size_t>(j)][static_cast<std::size_t>(d)];
    for (int d = 0; d <= derivatives; ++d, ++row)
      for (int j = 0; j < n; ++j) {
        m.a[static_cast<std::size_t>(row)][static_cast<std::size_t>(j)] = v.value[static_cast<std::size_t>(j)][static_cast<std::size_t>(d)];
        m.error[static_cast<std::size_t>(row)][static_cast<std::size_t>(j)] = v.error[static_cast<std::size_t>(j)][static_cast<std::size_t>(d)];
      }
  }
  for (int j = 0; j < n; ++j) {
    const Real big = sqrt(m.column_scale[static_cast<std::size_t>(j)]);
    m.column_scale[static_cast<std::size_t>(j)] = big > Real(0) ? big : Real(1);
    m.cancellation = std::max(m.cancellation, static_cast<double>(largest[static_cast<std::size_t>(j)] / m.column_scale[static_cast<std::size_t>(j)]));
    for (int i = 0; i < n; ++i) {
      m.a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] /= m.column_scale[static_cast<std::size_t>(j)];
      m.error[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] /= m.column_scale[static_cast<std::size_t>(j)];
    }
  }
  return m;
}

/// Counts of work done, for the summary.
struct WorkCounter {
  long determinant_evaluations = 0;
  double cancellation = 1.0;
  long terms = 0;
  int centres = 0;
  bool truncated = false;
};

template <class Real>
double scaled_determinant(const PlaneSetup& setup, double omega, WorkCounter& work) {
  const auto m = boundary_matrix<Real>(setup, Real(omega));
  ++work.determinant_evaluations;
  work.terms = std::max(work.terms, m.terms);
  work.centres = std::max(work.centres, m.centres);
  work.truncated = work.truncated || !m.converged;
  work.cancellation = std::max(work.cancellation, m.cancellation);
  return static_cast<double>(internal::determinant(m.a));
}

double scaled_determinant_at(Precision p, const PlaneSetup& setup, double omega, WorkCounter& work) {
  switch (p) {
    case Precision::Double: return scaled_determinant<double>(setup, omega, work);
    case Precision::LongDouble: return scaled_determinant<long double>(setup, omega, work);
    default: return scaled_determinant<Quad>(setup, omega, work);
  }
}

/// Root of f in [lo, hi] (f(lo) f(hi) < 0) by Illinois regula falsi with bisection safeguard.
template <class F>
double refine_root(F&& f, double lo, double hi, double flo, double fhi, double relative_tolerance, int& iterations) {
  int side = 0;
  for (iterations = 0; iterations < 200; ++iterations) {
    if (hi - lo <= relative_tolerance * std::abs(hi)) break;
    double x = (lo * fhi - hi * flo) / (fhi - flo);
    if (!(x > lo && x < hi) || iterations % 4 == 3) x = 0.5 * (lo + hi);
    const double fx = f(x);
    if (fx == 0.0) return x;
    if ((fx < 0.0) == (flo < 0.0)) {
      lo = x;
      flo = fx;
      if (side == -1) fhi *= 0.5;
      side = -1;
    } else {
      hi = x;
      fhi = fx;
      if (side == 1) flo *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (lo + hi);
}

/// One frequency with its error estimate and the precision that was needed.
struct FoundRoot {
  double omega = 0.0;  // Gale ratio
  double relative_error = -1.0;
  Precision precision = Precision::Double;
  double precision_difference = 0.0;
  double truncation_estimate = 0.0;
};

/// Frequencies of one plane.
struct PlaneRoots {
  std::vector<FoundRoot> roots;
  std::vector<std::string> notes;
  std::vector<std::string> warnings;
  WorkCounter work;
  int hidden_pairs_found = 0;
  int minima_checked = 0;
  Precision scan_precision = Precision::Double;
};

PlaneRoots find_frequencies(const PlaneSetup& setup, int count, const FrobeniusSolverOptions& options) {
  PlaneRoots result;
  // Asymptotic spacing of the modes (WKB of the string with tension C and mass mu): pi / int sqrt(mu/C).
  double integral = 0.0;
  const int panels = 400;
  for (int i = 0; i <= panels; ++i) {
    const double sigma = setup.sigma1 + (setup.sigma2 - setup.sigma1) * i / panels;
    const double weight = (i == 0 || i == panels) ? 0.5 : 1.0;
    integral += weight * std::sqrt(setup.mu / std::sqrt(1.0 + sigma * sigma));
  }
  integral *= (setup.sigma2 - setup.sigma1) / panels;
  const double spacing = kPi / integral;
  const double step = options.scan_fraction * spacing;
  // Cancellation (largest series term / column norm) at the top of the expected range decides the
  // precision of the scan: double while it leaves 8 digits, then long double, then quad.
  Precision scan_precision = Precision::Double;
  {
    WorkCounter probe;
    (void)scaled_determinant_at(Precision::Double, setup, (count + 1.0) * spacing, probe);
    result.work.determinant_evaluations += probe.determinant_evaluations;
    result.work.cancellation = probe.cancellation;
    if (probe.cancellation * std::numeric_limits<double>::epsilon() > 1e-8 && options.extended_precision)
      scan_precision = probe.cancellation * std::numeric_limits<long double>::epsilon() > 1e-8 ? Precision::Quad
                                                                                             : Precision::LongDouble;
    std::ostringstream text;
    text << "cancellation (largest series term / |sum|) at Omega = " << (count + 1.0) * spacing << ": "
         << probe.cancellation << "; root scan in " << precision_name(scan_precision);
    result.notes.push_back(text.str());
  }
  result.scan_precision = scan_precision;
  auto f = [&](double omega) { return scaled_determinant_at(scan_precision, setup, omega, result.work); };
  // The scan needs only the sign of det away from its roots: series cut at 1e-9 (fewer terms),
  // tightened by the cancellation factor so that the cut stays 1e-4 below the sums.
  PlaneSetup coarse = setup;
  coarse.settings.term_tolerance =
      std::max(setup.settings.term_tolerance, std::min(1e-9, 1e-4 / std::max(1.0, result.work.cancellation)));
  auto f_scan = [&](double omega) { return scaled_determinant_at(scan_precision, coarse, omega, result.work); };

  // The coarse series must reproduce the determinant itself (which can be far smaller than the
  // column norms when the basis is nearly dependent): checked at the top of the range.
  {
    const double top = (count + 1.0) * spacing;
    const double full = f(top), cut = f_scan(top);
    if (std::abs(cut - full) > 1e-2 * std::abs(full)) {
      coarse = setup;
      result.notes.push_back("coarse-series scan rejected (det differs by " +
                             std::to_string(std::abs(cut - full) / std::max(std::abs(full), 1e-300)) +
                             " relative at the top of the range): scan with the full series");
    }
  }

  // Scan state, so that the scan can be resumed when a bracket is lost in refinement.
  std::vector<std::pair<double, double>> brackets;
  double x0 = 0.02 * spacing, f0 = f_scan(x0);
  double x1 = x0 + step, f1 = f_scan(x1);
  const double limit = (3.0 * count + 20.0) * spacing;
  auto scan_more = [&](std::size_t wanted) {
    while (brackets.size() < wanted && x1 < limit) {
      const double x2 = x1 + step, f2 = f_scan(x2);
      if ((f0 < 0.0) != (f1 < 0.0)) brackets.emplace_back(x0, x1);
      // A local minimum of |det| without a sign change on either side may hide two close roots:
      // search it (golden section on the signed value) for a sign change.
      if ((f0 < 0.0) == (f1 < 0.0) && (f1 < 0.0) == (f2 < 0.0) && std::abs(f1) < std::abs(f0) &&
          std::abs(f1) < std::abs(f2)) {
        ++result.minima_checked;
        const double sign = f1 < 0.0 ? -1.0 : 1.0;
        double a = x0, b = x2;
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        double c = b - g * (b - a), d = a + g * (b - a);
        double fc = sign * f_scan(c), fd = sign * f_scan(d);
        std::optional<double> crossing;
        for (int it = 0; it < 60 && !crossing; ++it) {
          if (fc < 0.0) crossing = c;
          else if (fd < 0.0) crossing = d;
          else if (fc < fd) {
            b = d; d = c; fd = fc; c = b - g * (b - a); fc = sign * f_scan(c);
          } else {
            a = c; c = d; fc = fd; d = a + g * (b - a); fd = sign * f_scan(d);
          }
          if (b - a < 1e-14 * b) break;
        }
        if (crossing) {
          ++result.hidden_pairs_found;
          brackets.emplace_back(x0, *crossing);
          brackets.emplace_back(*crossing, x2);
          result.notes.push_back("close pair of roots found inside one scan cell near Omega = " + std::to_string(*crossing));
          x0 = x2;
          f0 = f2;
          x1 = x2 + step;
          f1 = f_scan(x1);
          continue;
        }
      }
      x0 = x1; f0 = f1;
      x1 = x2; f1 = f2;
    }
  };
  scan_more(static_cast<std::size_t>(count));

  const double rtol = std::max(options.tolerance * 0.1, 4e-16);
  for (std::size_t index = 0; index < brackets.size() && static_cast<int>(result.roots.size()) < count; ++index) {
    const double lo = brackets[index].first, hi = brackets[index].second;
    FoundRoot root;
    int iterations = 0;
    // The coarse scan may misplace a root lying within its truncation of a grid point: widen the
    // bracket by a grid step until the accurate determinant changes sign on it.
    double a = lo, b = hi, fa = f(a), fb = f(b);
    for (int widen = 0; widen < 4 && (fa < 0.0) == (fb < 0.0); ++widen) {
      a = std::max(0.5 * a, a - step);
      b += step;
      fa = f(a);
      fb = f(b);
    }
    if ((fa < 0.0) == (fb < 0.0)) {
      result.warnings.push_back("a sign change of the scan near Omega = " + std::to_string(lo) +
                                " is not confirmed by the full series; skipped, scan resumed");
      scan_more(brackets.size() + 1);
      continue;
    }
    double omega = refine_root(f, a, b, fa, fb, rtol, iterations);
    // A-posteriori check of the root: secant-Newton steps with the series cut finer (1e-3 of the
    // term tolerance per level, within the same max_terms: that knob is the user's resolution
    // and is never exceeded) and in higher precision (long double, then
    // quad from the third level when allowed). Errors carried through the matched expansions and
    // rounding lost to cancellation are both caught, which a per-entry tail estimate would miss.
    // The last correction is the reported estimate (conservative: the returned root is the one
    // after it).
    PlaneSetup fine = setup;
    Precision check = std::max(scan_precision, Precision::LongDouble);
    double correction = 0.0;
    bool double_was_enough = true;
    // Slope from the scan-precision determinant over h ~ sqrt(tolerance) omega: accurate to
    // ~1e-6, so each Newton correction is accurate to ~1e-6 of itself (one evaluation per level).
    const double h = std::max(1e-7, std::sqrt(options.tolerance)) * omega;
    // Later levels (the root needed a correction) use the slope at the check precision.
    double slope = (f(omega + h) - f(omega - h)) / (2.0 * h);
    for (int level = 0; level < 4 && slope != 0.0; ++level) {
      if (level == 2 && options.extended_precision && correction > 0.1 * options.tolerance) check = Precision::Quad;
      fine.settings.term_tolerance = std::max(fine.settings.term_tolerance * 1e-3, 1e-40);
      const double ga = scaled_determinant_at(check, fine, omega, result.work);
      if (level > 0) slope = (scaled_determinant_at(check, fine, omega + h, result.work) - ga) / h;
      if (slope == 0.0) break;
      const double corrected = omega - ga / slope;
      correction = std::abs(corrected - omega) / omega;
      omega = corrected;
      if (level == 0 && correction > 0.1 * options.tolerance) double_was_enough = false;
      if (correction <= 0.1 * options.tolerance) break;
    }
    root.omega = omega;
    root.precision = double_was_enough ? scan_precision : check;
    root.precision_difference = correction;
    root.truncation_estimate = correction;
    root.relative_error = std::max(correction, rtol);
    result.roots.push_back(root);
  }
  return result;
}

/// Coefficients of the mode (null vector of the boundary matrix), in the unscaled basis.
template <class Real>
std::vector<Real> null_vector(const PlaneSetup& setup, double omega) {
  const auto m = boundary_matrix<Real>(setup, Real(omega));
  const int n = static_cast<int>(m.a.size());
  Eigen::MatrixXd a(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) a(i, j) = static_cast<double>(m.a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullV);
  const Eigen::VectorXd v = svd.matrixV().col(n - 1);
  std::vector<Real> c(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) c[static_cast<std::size_t>(j)] = Real(v(j)) / m.column_scale[static_cast<std::size_t>(j)];
  return c;
}

/// Number of zeros in (sigma1, sigma2] of det [[U_a, U_b], [DU_a, DU_b]] for the two solutions
/// with U = DU = 0 at sigma1 (conjugate points of the clamped end), on `points` equal steps in
/// sigma. For this self-adjoint (Hamiltonian) system it counts the natural frequencies below omega
/// (Morse index); the solver uses it as an independent check of the in-plane root count.
template <class Real>
int conjugate_point_count(const PlaneSetup& setup, double omega, int points) {
  CatenaryBasis<Real> basis(true, Real(omega), Real(setup.mu), setup.eta_max, setup.settings);
  const auto start = basis.evaluate(Real(setup.sigma1), 3);
  Eigen::MatrixXd a(2, 4);
  Eigen::VectorXd scale(4);
  for (int j = 0; j < 4; ++j) {
    double norm = 0.0;
    for (int d = 0; d < 4; ++d) norm += std::pow(static_cast<double>(start.value[static_cast<std::size_t>(j)][static_cast<std::size_t>(d)]), 2);
    scale(j) = std::sqrt(norm) > 0.0 ? std::sqrt(norm) : 1.0;
    for (int d = 0; d < 2; ++d) a(d, j) = static_cast<double>(start.value[static_cast<std::size_t>(j)][static_cast<std::size_t>(d)]) / scale(j);
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullV);
  std::array<std::array<Real, 4>, 2> c{};
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 4; ++j) c[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)] = Real(svd.matrixV()(j, 2 + k) / scale(j));
  int changes = 0;
  double previous = 0.0;
  for (int i = 1; i <= points; ++i) {
    const double sigma = setup.sigma1 + (setup.sigma2 - setup.sigma1) * i / points;
    const auto v = basis.evaluate(Real(sigma), 1);
    Real u[2] = {Real(0), Real(0)}, du[2] = {Real(0), Real(0)};
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 4; ++j) {
        u[k] += c[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)] * v.value[static_cast<std::size_t>(j)][0];
        du[k] += c[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)] * v.value[static_cast<std::size_t>(j)][1];
      }
    const double det = static_cast<double>(u[0] * du[1] - u[1] * du[0]);
    if (i > 1 && det != 0.0 && previous != 0.0 && (det < 0.0) != (previous < 0.0)) ++changes;
    if (det != 0.0) previous = det;
  }
  return changes;
}

/// U, V = C^2 DU and T (Gale 2.36, 2.37, in units of a and H) of the combination c at sigma.
struct FieldValues {
  double u = 0.0, v = 0.0, t = 0.0;
};

template <class Real>
std::vector<FieldValues> fields(const PlaneSetup& setup, double omega, const std::vector<Real>& c,
                                const std::vector<double>& sigmas, bool with_tension) {
  CatenaryBasis<Real> basis(setup.inplane, Real(omega), Real(setup.mu), setup.eta_max, setup.settings);
  const int derivatives = setup.inplane ? (with_tension ? 3 : 1) : 0;
  std::vector<FieldValues> out;
  const Real w2mu = Real(omega) * Real(omega) * Real(setup.mu);
  for (double sigma_d : sigmas) {
    const Real sigma(sigma_d);
    const auto b = basis.evaluate(sigma, derivatives);
    Real d[4] = {Real(0), Real(0), Real(0), Real(0)};
    for (int j = 0; j < basis.size(); ++j)
      for (int k = 0; k <= derivatives; ++k) d[k] += c[static_cast<std::size_t>(j)] * b.value[static_cast<std::size_t>(j)][static_cast<std::size_t>(k)];
    FieldValues f;
    f.u = static_cast<double>(d[0]);
    if (setup.inplane) {
      const Real q = sigma * sigma;
      const Real C = sqrt(Real(1) + q);
      f.v = static_cast<double>(q * d[1] + d[1]);
      if (with_tension)
        f.t = static_cast<double>(sigma / C * d[0] - ((Real(3) + Real(4) * q) * C + w2mu * C * C * C * C) * d[1] -
                                  Real(5) * sigma * C * C * C * d[2] - C * C * C * C * C * d[3]);
    }
    out.push_back(f);
  }
  return out;
}

std::vector<FieldValues> fields_at(Precision p, const PlaneSetup& setup, double omega, const std::vector<double>& sigmas,
                                   bool with_tension) {
  switch (p) {
    case Precision::Double: return fields<double>(setup, omega, null_vector<double>(setup, omega), sigmas, with_tension);
    case Precision::LongDouble:
      return fields<long double>(setup, omega, null_vector<long double>(setup, omega), sigmas, with_tension);
    default: return fields<Quad>(setup, omega, null_vector<Quad>(setup, omega), sigmas, with_tension);
  }
}

/// Forced response: combination with the fixed end at rest and the driven end displaced.
template <class Real>
std::optional<std::vector<Real>> forced_coefficients(const PlaneSetup& setup, double omega, bool driven_at_b,
                                                     double u_end, double v_end, double& conditioning) {
  const auto m = boundary_matrix<Real>(setup, Real(omega));
  const std::size_t n = m.a.size();
  std::vector<Real> rhs(n, Real(0));
  const double sigma_end = driven_at_b ? setup.sigma2 : setup.sigma1;
  const std::size_t row = driven_at_b ? n / 2 : 0;
  rhs[row] = Real(u_end);
  if (setup.inplane) rhs[row + 1] = Real(v_end) / Real(1.0 + sigma_end * sigma_end);  // DU = V / C^2
  conditioning = std::abs(static_cast<double>(internal::determinant(m.a)));
  if (conditioning < 1e-13) return std::nullopt;
  std::vector<Real> c = internal::solve_dense(m.a, rhs);
  for (std::size_t j = 0; j < n; ++j) c[j] /= m.column_scale[j];
  return c;
}

}  // namespace

namespace {

SolverOutput solve_frobenius_impl(const Problem& problem, const StaticSolution& statics, const DimensionlessGroups& groups,
                                  const SolveRequest& request, const FrobeniusSolverOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SolverOutput output;
  output.solver = "frobenius";
  output.summary.solver = "frobenius";
  const std::string reason = frobenius_not_applicable_reason(problem, groups);
  if (!reason.empty()) {
    output.summary.termination = Termination::NotApplicable;
    output.summary.message = reason;
    return output;
  }
  const double a = groups.catenary_parameter_m;
  const double H = statics.horizontal_force_n();
  const double m_mass = problem.cable.mass_kg_per_m;
  const double M_mass = problem.cable.normal_mass_kg_per_m();
  const double scale = groups.gale_frequency_scale_rad_s;
  PlaneSetup base;
  base.sigma1 = groups.sigma1;
  base.sigma2 = groups.sigma2;
  base.mu = M_mass / m_mass;
  base.eta_max = std::max(std::abs(groups.xi1), std::abs(groups.xi2)) * (1.0 + 1e-12) + 1e-12;
  base.settings.term_tolerance = std::max(options.tolerance * 1e-3, 1e-34);
  base.settings.max_terms = options.max_terms;
  base.settings.step_ratio = options.step_ratio;

  const Vector stations = request.stations_m(problem.cable.length_m);
  std::vector<double> station_sigmas;
  for (Index i = 0; i < stations.size(); ++i) station_sigmas.push_back(statics.vertical_force_n(stations(i)) / H);
  // Dense internal stations for max |T| when tension is asked without shapes.
  std::vector<double> dense_sigmas;
  Vector dense_s(401);
  for (int i = 0; i <= 400; ++i) {
    dense_s(i) = problem.cable.length_m * i / 400.0;
    dense_sigmas.push_back(statics.vertical_force_n(dense_s(i)) / H);
  }

  bool all_converged = true;
  double worst_error = 0.0;
  long total_evaluations = 0, max_terms_used = 0;
  int max_centres = 0;
  Precision highest = Precision::Double;
  std::vector<std::string> messages;

  for (int plane_index = 0; plane_index < 2; ++plane_index) {
    const bool inplane = plane_index == 0;
    const int count = inplane ? request.inplane_modes : request.outofplane_modes;
    if (count <= 0) continue;
    PlaneSetup setup = base;
    setup.inplane = inplane;
    const auto plane_start = std::chrono::steady_clock::now();
    PlaneRoots found = find_frequencies(setup, count, options);
    int proved_count = -1;
    if (inplane) {
      // Conjugate-point count just above the highest root must equal the number of roots found;
      // when it does not, the scan is repeated on a 4x finer grid (twice at most).
      FrobeniusSolverOptions retry = options;
      for (int attempt = 0; attempt < 3 && !found.roots.empty(); ++attempt) {
        // Just above the highest root (1 % of the last gap): the last conjugate point then lies
        // far enough inside the cable to be resolved.
        const std::size_t n = found.roots.size();
        const double gap = n > 1 ? found.roots[n - 1].omega - found.roots[n - 2].omega : found.roots[0].omega;
        const double top = found.roots.back().omega + 0.01 * gap;
        // Only signs along the cable are needed: ~100 steps per mode, in the scan's precision.
        const int grid = 100 * static_cast<int>(found.roots.size()) + 200;
        const int counted = found.scan_precision == Precision::Double ? conjugate_point_count<double>(setup, top, grid)
                            : found.scan_precision == Precision::LongDouble
                                ? conjugate_point_count<long double>(setup, top, grid)
                                : conjugate_point_count<Quad>(setup, top, grid);
        if (counted == static_cast<int>(found.roots.size())) {
          proved_count = counted;
          found.notes.push_back("mode count checked by conjugate points (Morse index) on " + std::to_string(grid) +
                                " steps: " + std::to_string(counted) + " frequencies below the highest returned");
          break;
        }
        const std::string text = "conjugate-point count " + std::to_string(counted) + " differs from the " +
                                 std::to_string(found.roots.size()) + " roots found with scan_fraction " +
                                 std::to_string(retry.scan_fraction);
        if (attempt == 2 || retry.scan_fraction / 4.0 < 0.001) {
          found.warnings.push_back(text + ": a root may be missing");
          break;
        }
        retry.scan_fraction /= 4.0;
        const long evaluations = found.work.determinant_evaluations;
        found = find_frequencies(setup, count, retry);
        found.work.determinant_evaluations += evaluations;
        found.notes.push_back(text + "; rescanned with scan_fraction " + std::to_string(retry.scan_fraction));
      }
    }
    ModalResult modal;
    modal.plane = inplane ? Plane::InPlane : Plane::OutOfPlane;
    modal.summary.solver = "frobenius";
    double plane_worst = 0.0;
    Precision plane_precision = Precision::Double;
    int sturm_ok = 0;
    for (std::size_t i = 0; i < found.roots.size(); ++i) {
      const FoundRoot& root = found.roots[i];
      Mode mode;
      mode.index = static_cast<int>(i) + 1;
      internal::set_mode_frequency(mode, root.omega * scale, groups);
      mode.relative_error_estimate = root.relative_error;
      plane_worst = std::max(plane_worst, root.relative_error);
      plane_precision = std::max(plane_precision, root.precision);
      const bool want_fields = request.shapes || request.tension || !inplane;
      if (want_fields) {
        const bool dense = !request.shapes;
        const auto& sig = dense ? dense_sigmas : station_sigmas;
        const auto values = fields_at(root.precision, setup, root.omega, sig, inplane && request.tension);
        const Vector& s = dense ? dense_s : stations;
        mode.s_m = s;
        if (inplane) {
          mode.u.resize(s.size());
          mode.w.resize(s.size());
          if (request.tension) mode.tension_n.resize(s.size());
          for (Index k = 0; k < s.size(); ++k) {
            mode.u(k) = a * values[static_cast<std::size_t>(k)].u;
            mode.w(k) = a * values[static_cast<std::size_t>(k)].v;
            if (request.tension) mode.tension_n(k) = H * values[static_cast<std::size_t>(k)].t;
          }
          internal::normalise_inplane_mode(mode);
          mode.modal_mass_kg = internal::inplane_modal_mass(mode, m_mass, M_mass);
        } else {
          mode.v.resize(s.size());
          for (Index k = 0; k < s.size(); ++k) mode.v(k) = a * values[static_cast<std::size_t>(k)].u;
          // Sturm: the n-th out-of-plane mode has n - 1 interior nodes (checked on the stations).
          int changes = 0;
          for (Index k = 2; k + 1 < s.size(); ++k)
            if ((mode.v(k) < 0.0) != (mode.v(k - 1) < 0.0)) ++changes;
          if (changes == mode.index - 1) ++sturm_ok;
          internal::normalise_outofplane_mode(mode);
          mode.modal_mass_kg = internal::outofplane_modal_mass(mode, M_mass);
        }
        if (dense) {
          const double max_tension = mode.max_abs_tension_n;
          mode.s_m = Vector();
          mode.u = Vector();
          mode.w = Vector();
          mode.v = Vector();
          mode.tension_n = Vector();
          mode.modal_mass_kg = -1.0;
          mode.max_abs_tension_n = inplane && request.tension ? max_tension : -1.0;
        }
      }
      modal.modes.push_back(mode);
    }
    if (inplane) modal.proved_count_below_top = proved_count;
    if (!inplane && sturm_ok == static_cast<int>(found.roots.size()) && !found.roots.empty()) {
      modal.proved_count_below_top = static_cast<int>(found.roots.size());
      found.notes.push_back("mode count checked by Sturm oscillation: mode n has n - 1 interior nodes for n = 1.." +
                            std::to_string(found.roots.size()));
    }
    const bool plane_converged = static_cast<int>(found.roots.size()) == count && !found.work.truncated &&
                                 plane_worst <= std::max(options.tolerance, 1e-14) * 10.0;
    auto& summary = modal.summary;
    summary.termination = plane_converged ? Termination::Converged
                                          : (found.roots.empty() ? Termination::NumericalFailure : Termination::NoConvergence);
    std::ostringstream message;
    message << (plane_converged ? "Converged: " : "Not converged: ") << found.roots.size() << " of " << count << " "
            << (inplane ? "in-plane" : "out-of-plane") << " modes, max relative error estimate " << plane_worst
            << (plane_converged ? " <= " : " vs ") << options.tolerance * 10.0;
    if (found.work.truncated) message << "; some series hit max_terms = " << options.max_terms;
    summary.message = message.str();
    std::ostringstream resolution;
    resolution << "tolerance " << options.tolerance << ", up to " << found.work.terms << " series terms over "
               << found.work.centres << " expansion centres, highest precision " << precision_name(plane_precision);
    summary.resolution = resolution.str();
    summary.iterations = found.work.terms;
    summary.operations = found.work.determinant_evaluations;
    summary.max_error_estimate = plane_worst;
    summary.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - plane_start).count();
    summary.notes = found.notes;
    summary.notes.push_back("root scan: " + std::to_string(found.minima_checked) +
                            " local minima of |det| searched for hidden close pairs, " +
                            std::to_string(found.hidden_pairs_found) + " found");
    summary.warnings = found.warnings;
    if (plane_precision != Precision::Double)
      summary.warnings.push_back(std::string("the double-precision roots needed corrections above tolerance/10 from the "
                                             "finer-series re-evaluation in ") +
                                 precision_name(plane_precision) +
                                 " (truncation carried through the matched expansions and/or rounding); the returned roots include them");
    all_converged = all_converged && plane_converged;
    worst_error = std::max(worst_error, plane_worst);
    total_evaluations += found.work.determinant_evaluations;
    max_terms_used = std::max(max_terms_used, found.work.terms);
    max_centres = std::max(max_centres, found.work.centres);
    highest = std::max(highest, plane_precision);
    messages.push_back(summary.message);
    (inplane ? output.inplane : output.outofplane) = modal;
  }

  if (request.forced) {
    const ForcedRequest& forced = *request.forced;
    const bool at_b = forced.end == CableEnd::B;
    const double sigma_end = at_b ? base.sigma2 : base.sigma1;
    const double C_end = std::sqrt(1.0 + sigma_end * sigma_end);
    PlaneSetup setup = base;
    setup.inplane = forced.direction != ForcingDirection::OutOfPlane;
    double u_end = 0.0, v_end = 0.0;
    switch (forced.direction) {
      case ForcingDirection::Tangential: u_end = forced.amplitude_m / a; break;
      case ForcingDirection::Normal: v_end = forced.amplitude_m / a; break;
      case ForcingDirection::OutOfPlane: u_end = forced.amplitude_m / a; break;
      case ForcingDirection::GivenVector: {
        const Vec2 d = forced.vector.normalized() * forced.amplitude_m / a;
        const Vec2 t(1.0 / C_end, sigma_end / C_end), n(-sigma_end / C_end, 1.0 / C_end);
        u_end = d.dot(t);
        v_end = d.dot(n);
        break;
      }
    }
    for (double omega_rad_s : forced.omegas_rad_s) {
      ForcedResponse response;
      response.omega_rad_s = omega_rad_s;
      response.s_m = stations;
      const double omega = omega_rad_s / scale;
      double conditioning = 0.0;
      const auto c = forced_coefficients<long double>(setup, omega, at_b, u_end, v_end, conditioning);
      if (!c) {
        std::ostringstream text;
        text << "forcing at Omega = " << omega << " is at a natural frequency (scaled boundary determinant "
             << conditioning << " < 1e-13): resonance, no finite response";
        response.diagnostic = text.str();
        output.forced.push_back(response);
        continue;
      }
      const auto values = fields<long double>(setup, omega, *c, station_sigmas, setup.inplane);
      const Index n = stations.size();
      if (setup.inplane) {
        response.u.resize(n);
        response.w.resize(n);
        response.tension_n.resize(n);
        for (Index k = 0; k < n; ++k) {
          response.u(k) = a * values[static_cast<std::size_t>(k)].u;
          response.w(k) = a * values[static_cast<std::size_t>(k)].v;
          response.tension_n(k) = H * values[static_cast<std::size_t>(k)].t;
        }
        response.max_abs_tension_n = response.tension_n.cwiseAbs().maxCoeff();
      } else {
        response.v.resize(n);
        for (Index k = 0; k < n; ++k) response.v(k) = a * values[static_cast<std::size_t>(k)].u;
      }
      output.forced.push_back(response);
    }
  }

  auto& summary = output.summary;
  summary.termination = all_converged ? Termination::Converged : Termination::NoConvergence;
  std::ostringstream message;
  message << (all_converged ? "Converged" : "Not converged");
  for (const auto& text : messages) message << "; " << text;
  if (request.forced) message << "; forced response at " << request.forced->omegas_rad_s.size() << " frequencies";
  summary.message = message.str();
  std::ostringstream resolution;
  resolution << "tolerance " << options.tolerance << ", up to " << max_terms_used << " terms, " << max_centres
             << " expansion centres, precision " << precision_name(highest);
  summary.resolution = resolution.str();
  summary.iterations = max_terms_used;
  summary.operations = total_evaluations;
  summary.max_error_estimate = worst_error;
  summary.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return output;
}

}  // namespace

SolverOutput solve_frobenius(const Problem& problem, const StaticSolution& statics, const DimensionlessGroups& groups,
                             const SolveRequest& request, const FrobeniusSolverOptions& options) {
  options.validate();
  request.validate();
  try {
    return solve_frobenius_impl(problem, statics, groups, request, options);
  } catch (const InvalidInput&) {
    throw;
  } catch (const std::exception& error) {
    // Numerical trouble (e.g. a logarithmic Frobenius solution the engine does not build) is a
    // result, not an exception.
    SolverOutput output;
    output.solver = "frobenius";
    output.summary.solver = "frobenius";
    output.summary.termination = Termination::NumericalFailure;
    output.summary.message = std::string("series solution failed: ") + error.what();
    return output;
  }
}

namespace internal {

SolverEntry make_frobenius_entry() {
  SolverEntry entry;
  entry.name = "frobenius";
  entry.description =
      "Gale's power series for the inextensible catenary (seed 003), chained expansions to any sag, "
      "adaptive terms, extended precision when needed";
  entry.knobs = {
      {"tolerance", "target relative accuracy of each frequency [-], in [1e-15, 1e-3], default 1e-12"},
      {"max_terms", "cap on the terms of one expansion, in [8, 5000], default 600"},
      {"step_ratio", "expansion-centre spacing as a fraction of the radius of convergence, [0.1, 0.8], default 0.5"},
      {"scan_fraction", "root-scan grid as a fraction of the mode spacing, [0.01, 0.5], default 0.2"},
      {"extended_precision", "allow long double / quad when double loses digits (bool), default true"}};
  auto read = [](const SolverKnobs& knobs) {
    KnobReader reader("frobenius", knobs);
    FrobeniusSolverOptions options;
    options.tolerance = reader.get_double("tolerance", options.tolerance);
    options.max_terms = static_cast<int>(reader.get_integer("max_terms", options.max_terms));
    options.step_ratio = reader.get_double("step_ratio", options.step_ratio);
    options.scan_fraction = reader.get_double("scan_fraction", options.scan_fraction);
    options.extended_precision = reader.get_bool("extended_precision", options.extended_precision);
    reader.reject_unknown();
    try {
      options.validate();
    } catch (const InvalidInput& error) {
      throw InvalidInput(std::string("[solvers.frobenius]: ") + error.what());
    }
    return options;
  };
  entry.not_applicable_reason = [](const SolveContext& context) -> std::optional<std::string> {
    const std::string reason = frobenius_not_applicable_reason(context.problem, context.groups);
    if (reason.empty()) return std::nullopt;
    return reason;
  };
  entry.validate_knobs = [read](const SolverKnobs& knobs) { (void)read(knobs); };
  entry.run = [read](const SolveContext& context, const SolverKnobs& knobs) {
    return solve_frobenius(context.problem, context.statics, context.groups, context.request, read(knobs));
  };
  return entry;
}

}  // namespace internal
}  // namespace catena
