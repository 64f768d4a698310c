// SPDX-License-Identifier: MIT
// FindingsTable::find matches scene, quantity, mode and solver exactly.
#include "catena/verification/findings.hpp"

#include <gtest/gtest.h>

namespace catena {
namespace {

TEST(FindingsTable, FindsOnlyTheExactEntry) {
  Finding f;
  f.scene = "s";
  f.quantity = "inplane_frequency";
  f.mode = 2;
  f.solver = "frobenius";
  f.diagnosis = "d";
  const FindingsTable table({f});
  ASSERT_NE(table.find("s", "inplane_frequency", 2, "frobenius"), nullptr);
  EXPECT_EQ(table.find("s", "inplane_frequency", 2, "frobenius")->diagnosis, "d");
  EXPECT_EQ(table.find("s", "inplane_frequency", 1, "frobenius"), nullptr);
  EXPECT_EQ(table.find("s", "outofplane_frequency", 2, "frobenius"), nullptr);
  EXPECT_EQ(table.find("s", "inplane_frequency", 2, "shooting"), nullptr);
  EXPECT_EQ(table.find("t", "inplane_frequency", 2, "frobenius"), nullptr);
}

}  // namespace
}  // namespace catena
