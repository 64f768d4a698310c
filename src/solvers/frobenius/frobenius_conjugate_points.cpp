// SPDX-License-Identifier: MIT
// Conjugate-point count of the frobenius solver: see frobenius_conjugate_points.hpp.
#include "solvers/frobenius/frobenius_conjugate_points.hpp"

#include <fmt/format.h>

#include <Eigen/SVD>
#include <array>
#include <cmath>
#include <string>

#include "catena/core/types.hpp"

namespace catena::internal {

namespace {

// Coefficients (in the basis) of the two solutions with U = DU = 0 at sigma1: the null space of
// the 2x4 matrix of U, DU there, columns scaled by the norm of all four derivatives.
template <class Real>
std::array<std::array<Real, 4>, 2> clamped_start(const CatenaryBasis<Real>& basis, double sigma1) {
  const auto start = basis.evaluate(Real(sigma1), 3);
  Eigen::MatrixXd a(2, 4);
  Eigen::VectorXd scale(4);
  for (std::size_t j = 0; j < 4; ++j) {
    double norm = 0.0;
    for (std::size_t d = 0; d < 4; ++d) norm += std::pow(static_cast<double>(start.value[j][d]), 2);
    const Index col = static_cast<Index>(j);
    scale(col) = std::sqrt(norm) > 0.0 ? std::sqrt(norm) : 1.0;
    for (std::size_t d = 0; d < 2; ++d)
      a(static_cast<Index>(d), col) = static_cast<double>(start.value[j][d]) / scale(col);
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullV);
  std::array<std::array<Real, 4>, 2> c{};
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t j = 0; j < 4; ++j) {
      const Index col = static_cast<Index>(j);
      c[k][j] = Real(svd.matrixV()(col, 2 + static_cast<Index>(k)) / scale(col));
    }
  return c;
}

template <class Real>
int count_conjugate_points(const PlaneSetup& setup, double omega, int points) {
  CatenaryBasis<Real> basis(true, Real(omega), Real(setup.mu), setup.eta_max, setup.settings);
  const auto c = clamped_start(basis, setup.sigma1);
  int changes = 0;
  double previous = 0.0;
  for (int i = 1; i <= points; ++i) {
    const double sigma = setup.sigma1 + (setup.sigma2 - setup.sigma1) * i / points;
    const auto v = basis.evaluate(Real(sigma), 1, SeriesErrors::Skipped);  // signs only
    Real u[2] = {Real(0), Real(0)}, du[2] = {Real(0), Real(0)};
    for (std::size_t k = 0; k < 2; ++k)
      for (std::size_t j = 0; j < 4; ++j) {
        u[k] += c[k][j] * v.value[j][0];
        du[k] += c[k][j] * v.value[j][1];
      }
    const double det = static_cast<double>(u[0] * du[1] - u[1] * du[0]);
    if (i > 1 && det != 0.0 && previous != 0.0 && (det < 0.0) != (previous < 0.0)) ++changes;
    if (det != 0.0) previous = det;
  }
  return changes;
}

}  // namespace

int conjugate_point_count(Precision p, const PlaneSetup& setup, double omega, int points) {
  return with_precision(
      p, [&](auto zero) { return count_conjugate_points<decltype(zero)>(setup, omega, points); });
}

int confirm_inplane_count(const PlaneSetup& setup,
                          int count,
                          const RootSettings& settings,
                          PlaneRoots& found) {
  RootSettings retry = settings;
  for (int attempt = 0; attempt < 3 && !found.roots.empty(); ++attempt) {
    // Just above the highest root (1 % of the last gap): the last conjugate point then lies far
    // enough inside the cable to be resolved.
    const std::size_t n = found.roots.size();
    const double gap =
        n > 1 ? found.roots[n - 1].omega - found.roots[n - 2].omega : found.roots[0].omega;
    const double top = found.roots.back().omega + 0.01 * gap;
    // Only signs along the cable are needed: ~100 steps per mode, in the scan's precision.
    const int grid = 100 * static_cast<int>(n) + 200;
    const int counted = conjugate_point_count(found.scan_precision, setup, top, grid);
    if (counted == static_cast<int>(n)) {
      found.notes.push_back(
          fmt::format("mode count checked by conjugate points (Morse index) on {} steps: {} "
                      "frequencies below the highest returned",
                      grid, counted));
      return counted;
    }
    const std::string text = fmt::format(
        "conjugate-point count {} differs from the {} roots found with scan_fraction {:g}", counted,
        n, retry.scan_fraction);
    if (attempt == 2 || retry.scan_fraction / 4.0 < 0.001) {
      found.warnings.push_back(text + ": a root may be missing");
      return -1;
    }
    retry.scan_fraction /= 4.0;
    const long evaluations = found.work.determinant_evaluations;
    found = find_frequencies(setup, count, retry);
    found.work.determinant_evaluations += evaluations;
    found.notes.push_back(
        fmt::format("{}; rescanned with scan_fraction {:g}", text, retry.scan_fraction));
  }
  return -1;
}

}  // namespace catena::internal
