// SPDX-License-Identifier: MIT
// Every output of the `catena` commands (issue 32): devices and FIFOs written through, symlinks
// kept, inputs of the same run never replaced, empty paths and -j < 1 refused, nothing created on
// bad input, and one unreadable scene never losing verify's report.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>

#include "cli/cli_support.hpp"

namespace {

namespace fs = std::filesystem;

using catena::testing::CliRun;
using catena::testing::run_cli;

const std::string kScene =
    std::string(CATENA_SOURCE_DIR) + "/verification/scenes/analytic/taut-string.toml";

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("catena_output_paths_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string contents(const fs::path& path) {
  std::stringstream text;
  text << std::ifstream(path, std::ios::binary).rdbuf();
  return text.str();
}

bool contains(const std::string& text, const std::string& word) {
  return text.find(word) != std::string::npos;
}

TEST(OutputPaths, SolveWritesThroughDevNullAndItStaysADevice) {
  const CliRun run = run_cli("solve " + kScene + " -q --json /dev/null");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  struct stat after {};
  ASSERT_EQ(::lstat("/dev/null", &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode)) << "/dev/null was replaced";
}

TEST(OutputPaths, SolveWritesThroughAFifoToItsReader) {
  const fs::path dir = fresh_dir("fifo");
  const fs::path fifo = dir / "results.json";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  std::string received;
  std::thread reader([&] { received = contents(fifo); });
  const CliRun run = run_cli("solve " + kScene + " -q --json " + fifo.string());
  reader.join();
  EXPECT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json document = nlohmann::json::parse(received);
  EXPECT_EQ(document["scenes"].size(), 1u);
  EXPECT_EQ(fs::symlink_status(fifo).type(), fs::file_type::fifo);
}

// `--json /dev/stdout > file`: /dev/stdout leads to a regular file, the shell's; the JSON goes
// through the process's own descriptor, after the summary and before "wrote", nothing overwritten.
TEST(OutputPaths, SolveWritesToDevStdoutRedirectedToAFile) {
  const fs::path dir = fresh_dir("stdout");
  const fs::path file = dir / "out.txt";
  CliRun run = run_cli("solve " + kScene + " --json /dev/stdout > " + file.string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  const std::string text = contents(file);
  const auto json_start = text.find("\n{\n");
  const auto wrote = text.find("\nwrote /dev/stdout\n");
  ASSERT_NE(json_start, std::string::npos) << text.substr(0, 300);
  ASSERT_NE(wrote, std::string::npos) << text.substr(text.size() - 300);
  EXPECT_EQ(text.rfind("scene taut-string", 0), 0u);  // the summary first
  EXPECT_EQ(nlohmann::json::parse(text.substr(json_start, wrote - json_start))["scenes"].size(),
            1u);
  EXPECT_EQ(fs::symlink_status(file).type(), fs::file_type::regular);
  run = run_cli("solve " + kScene + " -q --json /dev/stdout > " + file.string());
  EXPECT_EQ(nlohmann::json::parse(contents(file))["scenes"].size(), 1u);
}

TEST(OutputPaths, SolveFollowsASymlinkAndKeepsIt) {
  const fs::path dir = fresh_dir("symlink");
  std::ofstream(dir / "real.json") << "old\n";
  fs::create_symlink("real.json", dir / "latest.json");
  const CliRun run = run_cli("solve " + kScene + " -q --json " + (dir / "latest.json").string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::is_symlink(dir / "latest.json"));
  EXPECT_EQ(nlohmann::json::parse(contents(dir / "real.json"))["scenes"].size(), 1u);
}

TEST(OutputPaths, NoCommandOverwritesItsOwnInput) {
  const fs::path dir = fresh_dir("same_file");
  const fs::path scene = dir / "s.toml";
  fs::copy_file(kScene, scene);
  fs::create_hard_link(scene, dir / "hard.toml");
  const std::string before = contents(scene);
  for (const std::string& json :
       {scene.string(), (dir / "." / "s.toml").string(), (dir / "hard.toml").string()}) {
    const CliRun run = run_cli("solve " + scene.string() + " -q --json " + json);
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_TRUE(contains(run.output, "--json " + json +
                                         ": cannot write: it is the same file as "
                                         "the input " +
                                         scene.string()))
        << run.output;
  }
  const fs::path results = dir / "r.csv";
  std::ofstream(results) << "plane,mode,frequency_hz\ninplane,1,1.0\n";
  CliRun run = run_cli("check " + results.string() + " --scene " + scene.string() + " --json " +
                       results.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "same file as the input " + results.string())) << run.output;
  EXPECT_EQ(contents(results), "plane,mode,frequency_hz\ninplane,1,1.0\n");
  // verify's report.json is checked against every scene it reads.
  fs::create_directories(dir / "suite");
  fs::copy_file(kScene, dir / "suite" / "report.json");
  fs::copy_file(kScene, dir / "suite" / "a.toml");
  fs::create_symlink("report.json", dir / "suite" / "b.toml");
  run = run_cli("verify -q --scenes " + (dir / "suite").string() + " --out " +
                (dir / "suite").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "--out " + (dir / "suite" / "report.json").string()))
      << run.output;
  EXPECT_EQ(contents(dir / "suite" / "report.json"), before);
  EXPECT_EQ(contents(scene), before);
}

// The importer and `report` check the files they write in --out against their input too.
TEST(OutputPaths, ImportAndReportDoNotOverwriteTheirInput) {
  const fs::path dir = fresh_dir("import_report");
  const fs::path deck = dir / "deck.txt";
  fs::copy_file(std::string(CATENA_SOURCE_DIR) + "/docs/examples/moordyn-v2-semitaut.txt", deck);
  const std::string text = contents(deck);
  fs::create_directories(dir / "out");
  fs::create_hard_link(deck, dir / "out" / "deck-line-1.toml");  // the name of a scene it writes
  CliRun run = run_cli("import moordyn " + deck.string() + " -q --out " + (dir / "out").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "same file as the input " + deck.string())) << run.output;
  EXPECT_EQ(contents(deck), text);
  EXPECT_FALSE(fs::exists(dir / "out" / "deck-line-2-3.toml"));  // nothing written
  std::ofstream(dir / "report.md") << "{}\n";
  run = run_cli("report --no-figures --from " + (dir / "report.md").string() + " --out " +
                dir.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "same file as the input")) << run.output;
  EXPECT_EQ(contents(dir / "report.md"), "{}\n");
}

TEST(OutputPaths, EmptyPathsAndJobsBelowOneAreUsageErrors) {
  CliRun run = run_cli("solve " + kScene + " -q --json ''");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "--json: an empty path")) << run.output;
  run = run_cli("solve " + kScene + " -q --tolerances ''");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "--tolerances: an empty path")) << run.output;
  const fs::path dir = fresh_dir("jobs");
  for (const char* jobs : {"0", "-1", "-0"}) {
    run = run_cli(std::string("verify -q -j ") + jobs + " --scenes " + dir.string() + " --out " +
                  (dir / "out").string());
    EXPECT_EQ(run.exit_code, 2) << jobs << ": " << run.output;
    EXPECT_TRUE(
        contains(run.output, "--jobs: must be at least 1 (omit -j/--jobs to use all cores)"))
        << jobs << ": " << run.output;
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(OutputPaths, CheckOnBadInputCreatesNoOutDirectory) {
  const fs::path dir = fresh_dir("check_out");
  const CliRun run = run_cli("check " + (dir / "missing.csv").string() + " --scene " + kScene +
                             " --out " + (dir / "report").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_FALSE(fs::exists(dir / "report"));
}

// One scene with a 0xFF byte in a string and one saved as UTF-16: verify used to stop writing
// report.json with an internal error (exit 3), losing every scene's result.
TEST(OutputPaths, VerifyReportsScenesWithInvalidUtf8AndKeepsTheOthers) {
  const fs::path dir = fresh_dir("utf8");
  fs::create_directories(dir / "scenes");
  const std::string good = contents(kScene);
  std::ofstream(dir / "scenes" / "good.toml") << good;
  std::ofstream(dir / "scenes" / "byte.toml", std::ios::binary) << "name = \"bad \xFF name\"\n"
                                                                << good;
  std::string utf16 = "\xFF\xFE";
  for (char c : good) utf16 += std::string{c, '\0'};
  std::ofstream(dir / "scenes" / "wide.toml", std::ios::binary) << utf16;
  const CliRun run = run_cli("verify -q --scenes " + (dir / "scenes").string() + " --out " +
                             (dir / "out").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;  // a scene error (bad input), documented as exit 2
  ASSERT_TRUE(fs::exists(dir / "out" / "report.json")) << run.output;
  const nlohmann::json report = nlohmann::json::parse(contents(dir / "out" / "report.json"));
  ASSERT_EQ(report["scenes"].size(), 3u);
  int solved = 0;
  for (const auto& scene : report["scenes"]) {
    const std::string file = scene["file"].get<std::string>();
    if (contains(file, "good.toml")) {
      EXPECT_TRUE(scene["error"].is_null()) << scene["error"];
      EXPECT_FALSE(scene["checks"].empty());
      ++solved;
    } else if (contains(file, "byte.toml")) {
      EXPECT_TRUE(contains(scene["error"].get<std::string>(), "\\xFF")) << scene["error"];
    } else {
      EXPECT_TRUE(contains(scene["error"].get<std::string>(), "UTF-16 text")) << scene["error"];
    }
  }
  EXPECT_EQ(solved, 1);
}

}  // namespace
