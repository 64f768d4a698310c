// SPDX-License-Identifier: MIT
// run_process: arguments reach the program unchanged (no shell), the exit status comes back,
// output can go to a file, and a program that cannot start reports 127.
#include "io/internal/process.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "catena/core/error.hpp"

namespace catena::internal {
namespace {

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::filesystem::path temp_file(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("catena_process_test_" + name);
}

TEST(Process, ReturnsTheExitStatus) {
  EXPECT_EQ(run_process({"/bin/sh", "-c", "exit 0"}), 0);
  EXPECT_EQ(run_process({"/bin/sh", "-c", "exit 3"}), 3);
  EXPECT_EQ(run_process({"false"}), 1);  // found on PATH
}

TEST(Process, ArgumentsAreNotInterpretedByAShell) {
  // Spaces, quotes, $ and ; would be split or expanded by a shell; here each reaches printf as is.
  const auto out = temp_file("args.txt");
  const std::string tricky = "a b 'c' \"d\" $HOME; rm -rf /nonexistent";
  ASSERT_EQ(run_process({"printf", "%s|", tricky, "second"}, out), 0);
  EXPECT_EQ(read(out), tricky + "|second|");
}

TEST(Process, StdoutAndStderrGoToTheOutputFile) {
  const auto out = temp_file("both.txt");
  ASSERT_EQ(run_process({"/bin/sh", "-c", "echo to-out; echo to-err >&2"}, out), 0);
  const std::string text = read(out);
  EXPECT_NE(text.find("to-out"), std::string::npos) << text;
  EXPECT_NE(text.find("to-err"), std::string::npos) << text;
}

TEST(Process, MissingProgramIs127AndEmptyArgumentsAreBadInput) {
  EXPECT_EQ(run_process({"/nonexistent/program"}), 127);
  EXPECT_EQ(run_process({"catena-no-such-program-on-path"}), 127);
  EXPECT_THROW(run_process({}), InvalidInput);
}

TEST(Process, AKilledProgramReports128PlusTheSignal) {
  EXPECT_EQ(run_process({"/bin/sh", "-c", "kill -9 $$"}), 128 + 9);
}

}  // namespace
}  // namespace catena::internal
