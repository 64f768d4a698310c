// ToleranceTable::find: the first rule that matches check, solver pair (either order, "*"), scene
// glob and tag wins.
#include "catena/verification/tolerance_table.hpp"

#include <gtest/gtest.h>

namespace catena {
namespace {

ToleranceRule rule(std::string check, std::string a, std::string b, double max,
                   std::string scene = "*", std::string tag = "") {
  ToleranceRule r;
  r.check = std::move(check);
  r.compare = {std::move(a), std::move(b)};
  r.scene_pattern = std::move(scene);
  r.tag = std::move(tag);
  r.max = max;
  r.reason = "test";
  return r;
}

TEST(ToleranceTable, FirstMatchingRuleWins) {
  const ToleranceTable table({rule("frequency", "fe", "shooting", 1e-6, "gale-*"),
                              rule("frequency", "fe", "*", 1e-4, "*", "stress"),
                              rule("frequency", "*", "*", 1e-2)});
  EXPECT_EQ(table.find("frequency", "shooting", "fe", "gale-1", {})->max, 1e-6);   // either order
  EXPECT_EQ(table.find("frequency", "fe", "shooting", "other", {"stress"})->max, 1e-4);
  EXPECT_EQ(table.find("frequency", "fe", "shooting", "other", {})->max, 1e-2);
  EXPECT_EQ(table.find("frequency", "airy", "frobenius", "gale-1", {})->max, 1e-2);
  EXPECT_EQ(table.find("mac", "fe", "shooting", "gale-1", {}), nullptr);
}

TEST(ToleranceTable, EmptyTableFindsNothing) {
  const ToleranceTable table;
  EXPECT_TRUE(table.rules().empty());
  EXPECT_EQ(table.find("frequency", "fe", "shooting", "x", {}), nullptr);
}

}  // namespace
}  // namespace catena
