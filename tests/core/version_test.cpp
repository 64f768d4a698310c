// SPDX-License-Identifier: MIT
// Provenance strings compiled into the binary.
#include "catena/core/version.hpp"

#include <gtest/gtest.h>

#include <regex>

namespace catena {
namespace {

TEST(Version, ProvenanceNamesVersionGitAndCompiler) {
  EXPECT_TRUE(std::regex_match(version(), std::regex(R"(\d+\.\d+\.\d+)"))) << version();
  EXPECT_FALSE(git_hash().empty());
  EXPECT_FALSE(compiler().empty());
  const std::string p = provenance();
  EXPECT_NE(p.find(version()), std::string::npos) << p;
  EXPECT_NE(p.find(git_hash()), std::string::npos) << p;
}

TEST(Version, TimestampIsIso8601Utc) {
  EXPECT_TRUE(std::regex_match(utc_timestamp(), std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")))
      << utc_timestamp();
}

}  // namespace
}  // namespace catena
