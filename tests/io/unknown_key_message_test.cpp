// SPDX-License-Identifier: MIT
// An unknown key names the keys known at its level, for every table: the list was empty for
// [checks] and left out the keys read only when present (top level: checks, sweep; [request]:
// points, forced, motion).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/scene_reader.hpp"

namespace catena {
namespace {

std::string taut_string_scene() {
  std::ifstream in(std::string(CATENA_SOURCE_DIR) +
                   "/verification/scenes/analytic/taut-string.toml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The message of parsing `text`, which must be refused.
std::string refusal(const std::string& text) {
  try {
    parse_scene_text(text, "s.toml");
  } catch (const Error& error) {
    return error.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

void expect_lists(const std::string& message,
                  const std::string& where,
                  const std::vector<std::string>& keys) {
  EXPECT_NE(message.find(where + ": unknown key (known here: "), std::string::npos) << message;
  const std::string known = message.substr(message.find("known here:"));
  for (const auto& key : keys)
    EXPECT_NE(known.find(key), std::string::npos) << key << ": " << message;
}

TEST(UnknownKeyMessage, ListsTheKnownKeysOfEveryLevel) {
  const std::string scene = taut_string_scene();
  ASSERT_NE(scene.find("[request]\n"), std::string::npos);
  ASSERT_EQ(scene.find("[checks]"), std::string::npos);
  expect_lists(
      refusal("bogus = 1\n" + scene), "s.toml: bogus",
      {"name", "description", "tags", "request", "solvers", "checks", "published", "sweep"});
  expect_lists(refusal(scene + "\n[checks]\nbogus = 1\n"), "[checks].bogus",
               {"frequency_rel", "shape_max_diff", "tension_rel", "orthogonality", "mac_min"});
  std::string request = scene;
  request.replace(request.find("[request]\n"), 10, "[request]\nbogus = 1\n");
  expect_lists(
      refusal(request), "[request].bogus",
      {"inplane_modes", "outofplane_modes", "shapes", "points", "tension", "forced", "motion"});
}

}  // namespace
}  // namespace catena
