// SPDX-License-Identifier: MIT
// Scene: the published-quantity names, the solver selection and the conversion of the request
// to SI units.
#include "catena/verification/scene.hpp"

#include <gtest/gtest.h>

#include "catena/core/error.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/statics/dimensionless_groups.hpp"

namespace catena {
namespace {

TEST(Scene, PublishedQuantityNamesRoundTrip) {
  for (auto q : {PublishedQuantity::InPlaneFrequency, PublishedQuantity::OutOfPlaneFrequency,
                 PublishedQuantity::ForcedMaxTension}) {
    EXPECT_EQ(parse_published_quantity(to_string(q)), q);
  }
  EXPECT_FALSE(parse_published_quantity("frequency"));
}

TEST(Scene, SolverNamesAreTheRegistryOrTheSceneChoice) {
  Scene scene;
  EXPECT_EQ(scene.solver_names().size(), solver_registry().size());
  scene.solvers["shooting"] = {};
  scene.solvers["fe"] = {};
  EXPECT_EQ(scene.solver_names(), (std::vector<std::string>{"fe", "shooting"}));  // registry order
}

TEST(Scene, ResolveRequestConvertsForcingToSI) {
  const Scene scene = parse_scene_text(
                          "[gale]\nxi1 = -1.0\nxi2 = 1.0\n[request]\ninplane_modes = 1\n"
                          "[request.forced]\nfrequencies = [2.0]\nfrequency_unit = "
                          "\"gale\"\namplitude = 0.5\namplitude_unit = \"a\"\n",
                          "s.toml")
                          .front();
  const StaticSolution statics = solve_statics(scene.problem);
  const DimensionlessGroups groups = compute_dimensionless_groups(scene.problem, statics);
  const SolveRequest request = resolve_request(scene, groups);
  ASSERT_TRUE(request.forced);
  EXPECT_NEAR(request.forced->omegas_rad_s[0], 2.0 * groups.gale_frequency_scale_rad_s, 1e-14);
  EXPECT_NEAR(request.forced->amplitude_m, 0.5 * groups.catenary_parameter_m, 1e-14);
}

}  // namespace
}  // namespace catena
