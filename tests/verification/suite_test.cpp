// SPDX-License-Identifier: MIT
// run_scenes: results in the order of the scenes whatever the thread count, progress reported
// once per scene, invalid options rejected before any thread starts.
#include "catena/verification/suite.hpp"

#include <gtest/gtest.h>

#include "catena/core/error.hpp"
#include "catena/io/scene_reader.hpp"

namespace catena {
namespace {

std::vector<Scene> scenes(int count) {
  std::vector<Scene> out;
  for (int i = 0; i < count; ++i) {
    out.push_back(
        parse_scene_text("name = \"s" + std::to_string(i) +
                             "\"\n[cable]\nlength = 1.0\nweight = 1.0\nEA = 1e6\nmass = 1.0\n"
                             "a = [0.0, 0.0]\nb = [" +
                             std::to_string(0.5 + 0.05 * i) + ", 0.1]\n",
                         "suite.toml")
            .front());
  }
  return out;
}

TEST(Suite, ResultsKeepTheOrderOfTheScenesAndProgressCountsEachOnce) {
  SceneRunOptions options;
  options.checks = false;
  options.only_solvers = {"asymptotic"};
  const std::vector<Scene> input = scenes(7);
  std::vector<std::size_t> done;
  const auto results =
      run_scenes(input, 3, options, [&](std::size_t n, std::size_t total, const std::string&) {
        EXPECT_EQ(total, input.size());
        done.push_back(n);
      });
  ASSERT_EQ(results.size(), input.size());
  for (std::size_t i = 0; i < input.size(); ++i) {
    EXPECT_EQ(results[i].scene.name, input[i].name);
    ASSERT_TRUE(results[i].statics);
    EXPECT_NEAR(results[i].statics->position_m(1.0).x(), input[i].problem.supports.b_m.x(), 1e-9);
  }
  ASSERT_EQ(done.size(), input.size());
  for (std::size_t i = 0; i < done.size(); ++i) EXPECT_EQ(done[i], i + 1);
}

TEST(Suite, InvalidOptionsThrowBeforeAnyWork) {
  EXPECT_THROW(run_scenes(scenes(2), 2, SceneRunOptions{}), InvalidInput);
}

}  // namespace
}  // namespace catena
