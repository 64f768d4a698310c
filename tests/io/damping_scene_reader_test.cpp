// SPDX-License-Identifier: MIT
// The damping keys of a scene (docs/reference/scene-format.md, "Damping"): what the reader builds
// from each form's keys, the nondimensional forms' definitions, and every bad value refused with
// the table, the key and the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {
namespace {

const std::string kCable = R"(
[cable]
length = 1000.0
weight = 1000.0
EA = 5.0e8
mass = 120.0
added_mass = 80.0
a = [0.0, 0.0]
b = [900.0, 300.0]
)";

Problem read_one(const std::string& text) {
  const auto scenes = parse_scene_text(text, "d.toml");
  EXPECT_EQ(scenes.size(), 1u);
  return scenes.at(0).problem;
}

TEST(DampingScene, CableSegmentAndSeabedKeysSetTheirCoefficients) {
  const Problem cable = read_one(kCable +
                                 "damping_tangential = 12.0\ndamping_normal = 200.0\n"
                                 "axial_damping = 1e7\n");
  EXPECT_EQ(cable.cable.damping.tangential_n_s_per_m2, 12.0);
  EXPECT_EQ(cable.cable.damping.normal_n_s_per_m2, 200.0);
  EXPECT_EQ(cable.cable.damping.axial_n_s, 1e7);
  EXPECT_TRUE(cable.is_damped());
  EXPECT_FALSE(read_one(kCable).is_damped()) << "all coefficients default to 0";

  const Problem line = read_one(R"(
[line]
a = [0.0, -100.0]
b = [400.0, 0.0]
[[line.segments]]
length = 300.0
weight = 500.0
EA = 1e8
mass = 60.0
damping_normal = 5.0
[[line.segments]]
length = 200.0
weight = 200.0
EA = 1e8
mass = 30.0
axial_damping = 2e5
[seabed]
z = -100.0
damping = 7.5
)");
  ASSERT_EQ(line.line.segments.size(), 2u);
  EXPECT_EQ(line.line.segments[0].damping.normal_n_s_per_m2, 5.0);
  EXPECT_EQ(line.line.segments[1].damping.axial_n_s, 2e5);
  ASSERT_TRUE(line.seabed);
  EXPECT_EQ(line.seabed->damping_n_s_per_m2, 7.5);
}

TEST(DampingScene, OneSegmentLineKeepsItsDampingAsTheUniformCable) {
  const Problem p = read_one(R"(
[line]
a = [0.0, 0.0]
b = [900.0, 300.0]
[[line.segments]]
length = 1000.0
weight = 1000.0
EA = 5e8
mass = 120.0
damping_tangential = 3.0
)");
  ASSERT_TRUE(p.is_uniform());
  EXPECT_EQ(p.cable.damping.tangential_n_s_per_m2, 3.0);
}

// Gale's eqs. 2.28e,f: eta = f / rho sqrt(a / g); in his form rho = a = g = 1, so c = eta, and the
// definition holds in the problem's own scales: c / (m sqrt(g/a)) = eta.
TEST(DampingScene, GaleEtasAreHisNondimensionalDragCoefficients) {
  const Problem p = read_one("[gale]\nxi1 = -0.34\nxi2 = 0.34\neta1 = 0.05\neta2 = 0.2\n");
  const StaticSolution statics = solve_statics(p);
  const DimensionlessGroups g = compute_dimensionless_groups(p, statics);
  const double rho_sqrt_g_over_a = p.cable.mass_kg_per_m * g.gale_frequency_scale_rad_s;
  EXPECT_NEAR(p.cable.damping.tangential_n_s_per_m2 / rho_sqrt_g_over_a, 0.05, 1e-15);
  EXPECT_NEAR(p.cable.damping.normal_n_s_per_m2 / rho_sqrt_g_over_a, 0.2, 1e-15);
  EXPECT_EQ(p.cable.damping.axial_n_s, 0.0);
}

// [taut_inclined]: c_t = eta_t sqrt(T0 M) / L, c_n = eta_n sqrt(T0 M) / L, c_a = eta_a L sqrt(T0
// M), with T0 the tension at s_a from the solved statics.
TEST(DampingScene, TautInclinedEtasAreScaledByTheCablesImpedance) {
  const Problem p = read_one(
      "[taut_inclined]\neps = 0.1\nphi_deg = 30.0\nlambda2 = 10.0\nmass_ratio = 0.5\n"
      "eta_tangential = 0.01\neta_normal = 0.02\neta_axial = 0.03\n");
  const StaticSolution statics = solve_statics(p);
  const DimensionlessGroups g = compute_dimensionless_groups(p, statics);
  const double L = p.cable.length_m;
  const double impedance = std::sqrt(g.t0_n * p.cable.normal_mass_kg_per_m());
  EXPECT_NEAR(p.cable.damping.tangential_n_s_per_m2 * L / impedance, 0.01, 1e-12);
  EXPECT_NEAR(p.cable.damping.normal_n_s_per_m2 * L / impedance, 0.02, 1e-12);
  EXPECT_NEAR(p.cable.damping.axial_n_s / (L * impedance), 0.03, 1e-12);
}

TEST(DampingScene, BadDampingIsRefusedNamingTheTableKeyAndReason) {
  struct Bad {
    std::string text;
    std::vector<std::string> words;
  };
  const std::vector<Bad> cases = {
      {kCable + "damping_normal = -1.0\n", {"[cable].damping_normal", ">= 0"}},
      {kCable + "damping_tangential = nan\n", {"[cable].damping_tangential", "finite"}},
      {kCable + "axial_damping = inf\n", {"[cable].axial_damping", "finite"}},
      {"[cable]\nlength = 10.0\nweight = 1.0\nEA = \"inf\"\nmass = 1.0\na = [0.0, 0.0]\n"
       "b = [8.0, 1.0]\naxial_damping = 1.0\n",
       {"[cable]", "axial_damping", "inextensible"}},
      {"[gale]\nxi1 = -0.3\nxi2 = 0.3\neta1 = -0.1\n", {"[gale].eta1", ">= 0"}},
      {"[taut_inclined]\neps = 0.1\nphi_deg = 30.0\nlambda2 = 10.0\neta_axial = -1\n",
       {"[taut_inclined].eta_axial", ">= 0"}},
      {kCable + "[seabed]\nz = 0.0\ndamping = -3.0\n", {"[seabed].damping", ">= 0"}},
  };
  for (const Bad& bad : cases) {
    try {
      parse_scene_text(bad.text, "bad.toml");
      ADD_FAILURE() << bad.text << ": no error";
    } catch (const Error& error) {
      for (const auto& word : bad.words) {
        EXPECT_NE(std::string(error.what()).find(word), std::string::npos)
            << "message lacks '" << word << "': " << error.what();
      }
    }
  }
}

}  // namespace
}  // namespace catena
