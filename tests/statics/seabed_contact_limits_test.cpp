// SPDX-License-Identifier: MIT
// Two limits of the seabed statics that were internal errors (issue 32, item 9): a seabed friction
// so large that the tensioned stretch before the touchdown is below the line's resolution
// (against the closed form of the infinite-friction limit), and a touchdown that falls at a point
// weight (refused as bad input naming the point, not a numerical failure).
#include <gtest/gtest.h>

#include <cmath>

#include "catena/io/scene_reader.hpp"
#include "catena/statics/seabed_statics.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

// A uniform elastic line, 300 m, 500 N/m, EA = 1e9 N, from an anchor on the seabed at z = -100 m
// to a fairlead at (250, 0): about half of it rests on the seabed.
constexpr double kLength = 300.0, kWeight = 500.0, kEA = 1e9, kReach = 250.0, kHeight = 100.0;

Problem line_on_seabed(double friction) {
  Problem p;
  p.cable = {kLength, kWeight, kEA, 50.0, 0.0};
  p.supports.a_m = Vec2(0.0, -kHeight);
  p.supports.b_m = Vec2(kReach, 0.0);
  p.seabed = Seabed{-kHeight, friction, 3e6, 0.0};
  return p;
}

// Spans of the suspended part (length Ls, vertical force 0 at the touchdown, H) of an elastic
// catenary (Irvine 1981, eqs. 2.21-2.22 with V_A = 0).
double span_x(double H, double Ls) {
  return H * Ls / kEA + H / kWeight * std::asinh(kWeight * Ls / H);
}
double span_z(double H, double Ls) {
  const double v = kWeight * Ls / H;
  return kWeight * Ls * Ls / (2.0 * kEA) + H / kWeight * (std::sqrt(1.0 + v * v) - 1.0);
}

template <class F>
double bisect(double lo, double hi, F f) {  // f(lo) < 0 < f(hi)
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// With infinite friction the grounded part carries no tension, so it does not stretch: the
// suspended length Ls and H close span_z = height and (L - Ls) + span_x = reach.
double infinite_friction_H() {
  const auto H_for = [](double Ls) {  // span_z falls as H grows
    return bisect(1e-3, 1e9, [&](double H) { return kHeight - span_z(H, Ls); });
  };
  const double Ls = bisect(
      kHeight, kLength, [&](double Ls) { return (kLength - Ls) + span_x(H_for(Ls), Ls) - kReach; });
  return H_for(Ls);
}

TEST(SeabedContactLimits, HugeFrictionConvergesToTheInfiniteFrictionLimit) {
  const double expected = infinite_friction_H();
  for (const double friction : {1e12, 1e200}) {  // both failed to close before (exit 3)
    const StaticSolution s = solve_seabed_statics(line_on_seabed(friction));
    ASSERT_TRUE(s.converged) << friction << ": " << s.message;
    // The finite friction's grounded stretch, H^2 / (2 friction w EA), is below 1e-15 m here.
    EXPECT_LT(testing::relative_error(s.horizontal_force_n(), expected), 1e-9) << friction;
  }
}

TEST(SeabedContactLimits, ATouchdownAtAPointWeightIsRefusedNamingThePoint) {
  // The docs' example deck (docs/examples/moordyn-v2-semitaut.txt), lines 2+3 as imported: a
  // chain and a wire joined by a 20 t clump, which the line's weight lays on the touchdown.
  const char* const scene = R"(name = "clump"
[line]
a = [0.0, -300.0]
b = [780.433213029789, -20.0]
[[line.segments]]
length = 300.0
weight = 1195.30074451493
EA = 1200000000.0
mass = 140.0
[[line.segments]]
length = 560.0
weight = 328.319108025375
EA = 600000000.0
mass = 40.0
[[line.points]]
s = 300.0
mass = 20000.0
weight = 176029.3675
[seabed]
z = -300.0
friction = 0.0
stiffness = 450000.0
)";
  const Problem problem = parse_scene_text(scene, "clump.toml").front().problem;
  testing::expect_invalid([&] { solve_seabed_statics(problem); },
                          "line.points[0]: the touchdown falls at this point weight");
}

}  // namespace
}  // namespace catena
