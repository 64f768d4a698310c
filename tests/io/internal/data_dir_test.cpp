// SPDX-License-Identifier: MIT
// find_data_dir: <exe dir>/../share/catena when installed, else the build tree's data dir.
#include "io/internal/data_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace catena::internal {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("catena_data_dir_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(DataDir, InstalledLayoutWinsOverTheBuildTree) {
  const fs::path prefix = fresh_dir("installed");
  fs::create_directories(prefix / "bin");
  fs::create_directories(prefix / "share" / "catena");
  const fs::path build = fresh_dir("build-tree");
  const auto found = find_data_dir(prefix / "bin" / "catena", build);
  ASSERT_TRUE(found);
  EXPECT_TRUE(fs::equivalent(*found, prefix / "share" / "catena"));
}

TEST(DataDir, FallsBackToTheBuildTreeThenToNothing) {
  const fs::path prefix = fresh_dir("not-installed");
  fs::create_directories(prefix / "bin");
  const fs::path build = fresh_dir("build-tree-2");
  const auto found = find_data_dir(prefix / "bin" / "catena", build);
  ASSERT_TRUE(found);
  EXPECT_EQ(*found, build);
  EXPECT_FALSE(find_data_dir(prefix / "bin" / "catena", prefix / "missing"));
  EXPECT_FALSE(find_data_dir({}, {}));
}

TEST(DataDir, ThisBuildHasAUsableDataDir) {
  // The build tree's data dir holds what the report reads: the figure script, the key module,
  // the published tables and the benchmark baseline.
  EXPECT_FALSE(executable_path().empty());
  const auto found = data_dir();
  ASSERT_TRUE(found);
  EXPECT_TRUE(fs::exists(*found / "figures.py"));
  EXPECT_TRUE(fs::exists(*found / "results_keys.py"));
  EXPECT_TRUE(fs::is_directory(*found / "reference" / "published"));
  EXPECT_TRUE(fs::exists(*found / "benchmarks" / "time-vs-error.csv"));
}

}  // namespace
}  // namespace catena::internal
