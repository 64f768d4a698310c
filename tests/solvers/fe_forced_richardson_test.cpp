// Richardson in h of the fe forced response (src/solvers/internal/fe_forced_richardson.cpp): cubic
// interpolation is exact for cubics (inside and past the ends), and a field with an O(h^2) error
// on the nodes and midpoints is extrapolated to O(h^4) on coinciding points; on a mesh of pieces
// the interpolation stays within each piece, so a kink at a piece boundary does not spoil it.
#include "solvers/internal/fe_forced_richardson.hpp"

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
  field.pieces = {{0, static_cast<std::size_t>(elements), 0.0, h}};
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
  const internal::FeResponseField coarse = synthetic(elements, length), fine = synthetic(2 * elements, length);
  const internal::FeResponseField extrapolated = internal::richardson_field(coarse, fine);
  const Vector stations = Vector::LinSpaced(37, 0.0, length);  // most stations between nodes
  const StaticSolution unused;  // out of plane the statics are not needed: x is sampled as v
  const internal::FeSampled raw = internal::sample_field(Plane::OutOfPlane, fine, stations, unused);
  const internal::FeSampled result = internal::sample_field(Plane::OutOfPlane, extrapolated, stations, unused);
  const std::vector<double> tension(extrapolated.tension.data(),
                                    extrapolated.tension.data() + extrapolated.tension.size());
  const double h = length / elements;
  Errors e;
  for (Index p = 0; p < stations.size(); ++p) {
    const double s = stations[p], exact = std::sin(2.0 * s);
    e.raw = std::max(e.raw, std::abs(raw.v[p] - exact));
    e.displacement = std::max(e.displacement, std::abs(result.v[p] - exact));
    e.tension = std::max(e.tension, std::abs(internal::cubic_interpolate(tension, 0.5 * h, h, s) - exact));
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

// Two pieces of different element lengths, [0, 1] with 8 elements and [1, 3] with 5, and a field
// that is a different cubic on each with a kink at s = 1: sampled exactly everywhere, because no
// stencil crosses the kink (one that did would be off by about 0.1 next to it).
TEST(FeForcedRichardson, InterpolatesWithinEachPieceOfAPiecewiseMesh) {
  auto f = [](double s) { return s <= 1.0 ? s * s * s : 1.0 - 2.0 * (s - 1.0) + cubic(s - 1.0) - cubic(0.0); };
  internal::FeResponseField field;
  field.pieces = {{0, 8, 0.0, 1.0 / 8.0}, {8, 5, 1.0, 2.0 / 5.0}};
  for (int i = 0; i <= 8; ++i) field.nodes.emplace_back(f(i / 8.0), 0.0);
  for (int i = 1; i <= 5; ++i) field.nodes.emplace_back(f(1.0 + 0.4 * i), 0.0);
  const Vector stations = Vector::LinSpaced(61, 0.0, 3.0);
  const StaticSolution unused;
  const internal::FeSampled sampled = internal::sample_field(Plane::OutOfPlane, field, stations, unused);
  for (Index p = 0; p < stations.size(); ++p)
    EXPECT_NEAR(sampled.v[p], f(stations[p]), 1e-13) << "s = " << stations[p];
}

TEST(FeForcedRichardson, RefusesMeshesThatAreNotOneHalvingApart) {
  EXPECT_THROW(internal::richardson_field(synthetic(100, 1.0), synthetic(150, 1.0)), std::logic_error);
}

}  // namespace
}  // namespace catena
