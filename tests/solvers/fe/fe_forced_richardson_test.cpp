// SPDX-License-Identifier: MIT
// Richardson in h of the fe forced response (src/solvers/fe/fe_forced_richardson.cpp): cubic
// interpolation is exact for cubics (inside and past the ends), and a field with an O(h^2) error
// on the nodes and midpoints is extrapolated to O(h^4) on coinciding points.
#include "solvers/fe/fe_forced_richardson.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace catena {
namespace {

double cubic(double x) { return 0.3 - 1.2 * x + 0.7 * x * x - 0.05 * x * x * x; }

TEST(FeForcedRichardson, CubicInterpolationIsExactForCubicsInsideAndPastTheEnds) {
  std::vector<double> values;
  for (int k = 0; k < 9; ++k) values.push_back(cubic(0.25 + 0.5 * k));
  for (double x : {0.0, 0.25, 0.4, 1.1, 2.3, 4.25, 4.5}) {
    EXPECT_NEAR(internal::cubic_interpolate(values, 0.25, 0.5, x), cubic(x), 1e-13) << "x = " << x;
  }
  // Two points: linear.
  EXPECT_NEAR(internal::cubic_interpolate({1.0, 3.0}, 0.0, 1.0, 0.25), 1.5, 1e-15);
}

// A synthetic mesh field: exact value f plus the error h^2 g of a second-order scheme, on nodes
// (displacement) and midpoints (tension).
internal::FeResponseField synthetic(int elements, double length) {
  internal::FeResponseField field;
  const double h = length / elements;
  field.pieces = {{0, elements, 0.0, h}};
  auto f = [](double s) { return std::sin(2.0 * s); };
  auto g = [](double s) { return 5.0 * std::cos(3.0 * s); };
  for (int i = 0; i <= elements; ++i) {
    const double s = i * h;
    field.nodes.emplace_back(f(s) + h * h * g(s), 0.5 * f(s));
  }
  field.tension.resize(elements);
  for (int j = 0; j < elements; ++j) {
    const double s = (j + 0.5) * h;
    field.tension[j] = f(s) + h * h * g(s);
  }
  return field;
}

struct Errors {
  double raw = 0.0, displacement = 0.0, tension = 0.0;
};

// Max errors on 37 stations of the fine field and of the extrapolated one (coarse mesh `elements`).
Errors errors_on_stations(int elements, double length) {
  const internal::FeResponseField coarse = synthetic(elements, length),
                                  fine = synthetic(2 * elements, length);
  const internal::FeResponseField extrapolated = internal::richardson_field(coarse, fine);
  const Vector stations = Vector::LinSpaced(37, 0.0, length);  // most stations between nodes
  const StaticSolution unused;  // out of plane the statics are not needed: x is sampled as v
  const internal::FeSampled raw = internal::sample_field(Plane::OutOfPlane, fine, stations, unused);
  const internal::FeSampled result =
      internal::sample_field(Plane::OutOfPlane, extrapolated, stations, unused);
  const std::vector<double> tension(extrapolated.tension.data(),
                                    extrapolated.tension.data() + extrapolated.tension.size());
  const double h = length / elements;
  Errors e;
  for (Index p = 0; p < stations.size(); ++p) {
    const double s = stations[p], exact = std::sin(2.0 * s);
    e.raw = std::max(e.raw, std::abs(raw.v[p] - exact));
    e.displacement = std::max(e.displacement, std::abs(result.v[p] - exact));
    e.tension =
        std::max(e.tension, std::abs(internal::cubic_interpolate(tension, 0.5 * h, h, s) - exact));
  }
  return e;
}

TEST(FeForcedRichardson, TheSecondOrderErrorCancelsOnCoincidingPoints) {
  const Errors coarse = errors_on_stations(100, 2.0), fine = errors_on_stations(200, 2.0);
  EXPECT_GT(coarse.raw, 1e-4);  // the fine mesh's h^2 error, 5 (2/200)^2 = 5e-4
  // What is left is the cubic interpolation's O(h^4): about 16x less per halving (observed order
  // between 3.6 and 4.4), and far below the h^2 error.
  EXPECT_LT(coarse.displacement, 1e-3 * coarse.raw);
  EXPECT_LT(coarse.tension, 1e-2 * coarse.raw);
  EXPECT_NEAR(std::log2(coarse.displacement / fine.displacement), 4.0, 0.4);
  EXPECT_NEAR(std::log2(coarse.tension / fine.tension), 4.0, 0.4);
}

TEST(FeForcedRichardson, RefusesMeshesThatAreNotOneHalvingApart) {
  EXPECT_THROW(internal::richardson_field(synthetic(100, 1.0), synthetic(150, 1.0)),
               std::logic_error);
}

// Two pieces of a line, [0, 0.8] with n elements and [0.8, 2] with 3n, and a field whose slope
// jumps at 0.8 (as a line's response does at a joint or point): the extrapolation and the sampling
// stay within each piece, so the cancellation holds up to the break; across it, interpolation would
// leave an O(h) error near s = 0.8.
double kinked(double s) {
  return s < 0.8 ? std::sin(2.0 * s) : std::sin(1.6) + 3.0 * (s - 0.8) * (s - 0.5);
}
double kinked_error(double s) { return s < 0.8 ? 5.0 * std::cos(3.0 * s) : -2.0 * s; }

internal::FeResponseField two_pieces(int n) {
  internal::FeResponseField field;
  field.pieces = {{0, n, 0.0, 0.8 / n}, {n, 3 * n, 0.8, 1.2 / (3 * n)}};
  for (const internal::FeFieldPiece& piece : field.pieces) {
    const double h = piece.element_length_m;
    for (int k = piece.first_element == 0 ? 0 : 1; k <= piece.elements; ++k) {
      const double s = piece.start_m + k * h;
      field.nodes.emplace_back(kinked(s) + h * h * kinked_error(s), 0.0);
    }
  }
  field.tension.resize(4 * n);
  for (const internal::FeFieldPiece& piece : field.pieces) {
    const double h = piece.element_length_m;
    for (int k = 0; k < piece.elements; ++k) {
      const double s = piece.start_m + (k + 0.5) * h;
      field.tension[piece.first_element + k] = kinked(s) + h * h * kinked_error(s);
    }
  }
  return field;
}

double two_piece_error(int n) {
  const internal::FeResponseField extrapolated =
      internal::richardson_field(two_pieces(n), two_pieces(2 * n));
  const Vector stations = Vector::LinSpaced(41, 0.0, 2.0);  // 0.8 is a station
  const StaticSolution unused;
  const internal::FeSampled result =
      internal::sample_field(Plane::OutOfPlane, extrapolated, stations, unused);
  double error = 0.0;
  for (Index p = 0; p < stations.size(); ++p)
    error = std::max(error, std::abs(result.v[p] - kinked(stations[p])));
  return error;
}

TEST(FeForcedRichardson, PiecesOfUnequalElementsExtrapolateWithinEachPiece) {
  const double coarse = two_piece_error(20), fine = two_piece_error(40);
  EXPECT_LT(coarse, 1e-6);
  EXPECT_GT(coarse / fine, 10.0) << coarse << " then " << fine;  // O(h^4): 16 per halving
}

}  // namespace
}  // namespace catena
