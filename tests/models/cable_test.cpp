// SPDX-License-Identifier: MIT
// API-level bad input (docs/contributing/architecture.md, "Errors"): every validate() constraint of
// the cable, supports, request and statics options throws InvalidInput naming the field; statics
// reports unreachable chords.
#include "catena/models/cable.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "catena/core/error.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using testing::expect_invalid;

Problem good() {
  Problem p;
  p.cable = {100.0, 10.0, 1e6, 2.0, 1.0};
  p.supports.b_m = Vec2(80.0, 20.0);
  return p;
}

TEST(CableProperties, RejectsEachInvalidField) {
  const double nan = std::nan("");
  auto with = [](auto change) {
    Problem p = good();
    change(p);
    return [p] { p.validate(); };
  };
  expect_invalid(with([](Problem& p) { p.cable.length_m = 0.0; }), "length_m");
  expect_invalid(with([&](Problem& p) { p.cable.length_m = nan; }), "length_m");
  expect_invalid(with([](Problem& p) { p.cable.weight_n_per_m = -1.0; }), "weight_n_per_m");
  expect_invalid(with([](Problem& p) { p.cable.mass_kg_per_m = kInfinity; }), "mass_kg_per_m");
  expect_invalid(with([](Problem& p) { p.cable.axial_stiffness_n = 0.0; }), "axial_stiffness_n");
  expect_invalid(with([&](Problem& p) { p.cable.axial_stiffness_n = nan; }), "axial_stiffness_n");
  expect_invalid(with([](Problem& p) { p.cable.added_mass_kg_per_m = -0.1; }),
                 "added_mass_kg_per_m");
  expect_invalid(with([&](Problem& p) { p.supports.b_m.x() = nan; }), "finite");
  expect_invalid(with([](Problem& p) { p.supports.b_m = p.supports.a_m; }), "coincide");
  expect_invalid(with([](Problem& p) { p.supports.b_m.x() = -5.0; }), "left of");
}

// Damping (docs/explanation/physics.md, "Damping"): every coefficient finite and >= 0, axial
// damping only where there is axial strain; each error names the field.
TEST(CableProperties, RejectsBadDampingNamingTheField) {
  const double nan = std::nan("");
  auto with = [](auto change) {
    Problem p = good();
    change(p);
    return [p] { p.validate(); };
  };
  expect_invalid(with([](Problem& p) { p.cable.damping.tangential_n_s_per_m2 = -1.0; }),
                 "damping_tangential");
  expect_invalid(with([&](Problem& p) { p.cable.damping.normal_n_s_per_m2 = nan; }),
                 "damping_normal");
  expect_invalid(with([](Problem& p) { p.cable.damping.axial_n_s = kInfinity; }), "axial_damping");
  expect_invalid(with([](Problem& p) {
                   p.cable.axial_stiffness_n = kInfinity;
                   p.cable.damping.axial_n_s = 1.0;
                 }),
                 "inextensible");
  expect_invalid(with([](Problem& p) {
                   p.line = line_of_cable(p.cable);
                   p.line.segments[0].damping.axial_n_s = -2.0;
                 }),
                 "segments[0].axial_damping");
  Problem damped = good();
  EXPECT_FALSE(damped.is_damped());
  damped.cable.damping.normal_n_s_per_m2 = 3.0;
  EXPECT_NO_THROW(damped.validate());
  EXPECT_TRUE(damped.is_damped());
  EXPECT_EQ(line_of_cable(damped.cable).segments[0].damping.normal_n_s_per_m2, 3.0);
}

// Huge values made the statics overflow ("closure error -nan m", no field named) and
// b = (1e308, 0) was called coincident with a (the squared chord overflowed).
TEST(CableProperties, RejectsMagnitudesThatOverflowTheStaticsNamingTheField) {
  auto with = [](auto change) {
    Problem p = good();
    change(p);
    return [p] { p.validate(); };
  };
  expect_invalid(with([](Problem& p) { p.cable.length_m = 1e300; }),
                 "length_m = 1e+300: must be in [1e-15, 1e+15]");
  expect_invalid(with([](Problem& p) { p.cable.weight_n_per_m = 1e16; }), "weight_n_per_m");
  expect_invalid(with([](Problem& p) { p.cable.weight_n_per_m = 1e-16; }), "weight_n_per_m");
  expect_invalid(with([](Problem& p) { p.cable.axial_stiffness_n = 1e300; }),
                 "axial_stiffness_n = 1e+300: must be in [1e-15, 1e+30]");
  expect_invalid(with([](Problem& p) { p.cable.axial_stiffness_n = 1e-16; }), "axial_stiffness_n");
  EXPECT_NO_THROW(with([](Problem& p) { p.cable.axial_stiffness_n = 1e30; })());
  expect_invalid(with([](Problem& p) { p.cable.mass_kg_per_m = 1e300; }), "mass_kg_per_m");
  expect_invalid(with([](Problem& p) { p.cable.added_mass_kg_per_m = 1e300; }),
                 "added_mass_kg_per_m");
  expect_invalid(with([](Problem& p) { p.supports.b_m = Vec2(1e308, 0.0); }), "within +-1e+15");
  expect_invalid(with([](Problem& p) { p.supports.a_m = Vec2(-1e16, 0.0); }), "within +-1e+15");
  // At the bounds, and EA = inf, ma = 0: accepted; far apart large supports are not "coincident".
  EXPECT_NO_THROW(with([](Problem& p) {
    p.cable = {1e15, 1e-15, kInfinity, 1e15, 0.0};
    p.supports.a_m = Vec2(-1e15, -1e15);
    p.supports.b_m = Vec2(1e15, 1e15);
  })());
}

// k = 1e24 N/m per m made shooting store 24 GB (issue 32): a seabed stiffness is bounded by
// k L^2 / W <= 1e16 against the line's length and total weight (here L = 100 m, W = 1000 N: at
// most 1e15 N/m per m), beyond which double precision cannot carry the line's own stiffness beside
// the foundation's. The message names the field and the largest value for this line.
TEST(CableProperties, RejectsASeabedStiffnessBeyondDoublePrecisionNamingTheField) {
  Problem p = good();
  p.supports.b_m = Vec2(80.0, 0.0);
  p.seabed = Seabed{0.0, 0.0, 1e15, 1e15};
  EXPECT_NO_THROW(p.validate());
  p.seabed->stiffness_n_per_m2 = 1.01e15;
  expect_invalid([p] { p.validate(); }, "Invalid seabed.stiffness = 1.01e+15: k L^2 / W");
  p.seabed->stiffness_n_per_m2 = 1e24;
  expect_invalid([p] { p.validate(); }, "at most 1e+15 N/m per m for this line");
  p.seabed->stiffness_n_per_m2 = 0.0;
  p.seabed->tangential_stiffness_n_per_m2 = 1e20;
  expect_invalid([p] { p.validate(); }, "seabed.tangential_stiffness");
}

TEST(Statics, ReportsUnreachableAndImpossibleGeometries) {
  Problem p = good();
  p.cable.axial_stiffness_n = kInfinity;
  p.supports.b_m = Vec2(120.0, 0.0);
  expect_invalid([&] { solve_statics(p); }, "farther apart than the cable can reach");
  p.supports.b_m = Vec2(0.0, 50.0);  // vertical, inextensible
  expect_invalid([&] { solve_statics(p); }, "vertical chord");
  p.cable.axial_stiffness_n = 1e6;  // vertical, slack: would fold
  expect_invalid([&] { solve_statics(p); }, "slack");
  p = good();
  p.prescribed_forces = EndForces{-1.0, 0.0};
  expect_invalid([&] { solve_statics(p); }, "prescribed_forces");
  p.prescribed_forces = EndForces{100.0, 0.0};  // does not put the end at b
  expect_invalid([&] { solve_statics(p); }, "away from support b");
  StaticsOptions options;
  options.max_iterations = 0;
  expect_invalid([&] { solve_statics(good(), options); }, "max_iterations");
}

}  // namespace
}  // namespace catena
