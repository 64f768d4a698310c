// SPDX-License-Identifier: MIT
// The `catena` executable: exit codes (0 ok, 1 failed check, 2 bad input/usage, 3 numerical
// failure of a scene), error messages on stderr naming file/table/key, and JSON without NaN. Runs
// the built binary on scenes written to a temporary directory.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_support.hpp"

namespace {

namespace fs = std::filesystem;

using catena::testing::CliRun;
using catena::testing::run_cli;

fs::path write_scene(const std::string& name, const std::string& text) {
  return catena::testing::write_temp_file("catena_cli_test", name, text);
}

const std::string kGood = R"(
[cable]
length = 1000.0
weight = 1000.0
EA = 5.0e8
mass = 120.0
added_mass = 80.0
a = [0.0, 0.0]
b = [900.0, 300.0]
)";

TEST(Cli, HelpExitsZeroOnEveryCommand) {
  for (const char* args : {"--help", "solve --help", "verify --help", "solvers --help"}) {
    const CliRun run = run_cli(args);
    EXPECT_EQ(run.exit_code, 0) << args << "\n" << run.output;
    EXPECT_NE(run.output.find("Usage"), std::string::npos) << args;
  }
}

TEST(Cli, SolveWritesJsonWithoutNaN) {
  const fs::path scene = write_scene("good.toml", kGood);
  const fs::path json = scene.parent_path() / "good.json";
  const CliRun run = run_cli("solve " + scene.string() + " --json " + json.string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  std::stringstream text;
  text << std::ifstream(json).rdbuf();
  EXPECT_NE(text.str().find("\"horizontal_force_n\""), std::string::npos);
  EXPECT_EQ(text.str().find("NaN"), std::string::npos);
  EXPECT_EQ(text.str().find("nan"), std::string::npos);
}

TEST(Cli, BadInputExitsTwoNamingTheKey) {
  const fs::path scene = write_scene("bad.toml", kGood + "colour = \"red\"\n");
  const CliRun run = run_cli("solve " + scene.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("[cable].colour"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("bad.toml"), std::string::npos) << run.output;
}

TEST(Cli, UnreachableChordExitsTwo) {
  // An inextensible 100 m cable cannot reach supports 150 m apart.
  const fs::path scene = write_scene("unreachable.toml", R"(
[cable]
length = 100.0
weight = 10.0
EA = "inf"
mass = 1.0
a = [0.0, 0.0]
b = [150.0, 0.0]
)");
  const CliRun run = run_cli("solve " + scene.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("farther apart than the cable can reach"), std::string::npos)
      << run.output;
}

// A heavy (W0 L = 1e9 N), very compliant (EA = 1e3 N) line on a nearly vertical chord: the
// stretched cable is ~1e6 times its length, and Newton stalls at a closure error of ~1e-8 m, far
// above its 1e-11 m target. That is a numerical failure of a valid problem, not bad input.
const std::string kStaticsStall = R"(
[cable]
length = 1000.0
weight = 1.0e6
EA = 1.0e3
mass = 1.0
a = [0.0, 0.0]
b = [1.0, 999.0]
)";

TEST(Cli, StaticsThatDoNotConvergeExitThreeNotTwo) {
  const fs::path scene = write_scene("stall.toml", kStaticsStall);
  const CliRun run = run_cli("solve " + scene.string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_NE(run.output.find("Statics did not converge"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("stall.toml"), std::string::npos) << run.output;

  const fs::path dir = fs::temp_directory_path() / "catena_cli_verify_stall";
  fs::create_directories(dir / "scenes");
  std::ofstream(dir / "scenes" / "stall.toml") << kStaticsStall;
  const CliRun verify =
      run_cli("verify --scenes " + (dir / "scenes").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(verify.exit_code, 3) << verify.output;
  EXPECT_NE(verify.output.find("1 scene errors"), std::string::npos) << verify.output;
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(run_cli("").exit_code, 2);
  EXPECT_EQ(run_cli("frobnicate").exit_code, 2);
  EXPECT_EQ(run_cli("solve").exit_code, 2);
  EXPECT_EQ(run_cli("solve /nonexistent.toml").exit_code, 2);
  const fs::path scene = write_scene("good2.toml", kGood);
  EXPECT_EQ(run_cli("solve " + scene.string() + " --solver nonsense").exit_code, 2);
  EXPECT_EQ(run_cli("verify --scenes /nonexistent-dir").exit_code, 2);
}

TEST(Cli, VerifyRunsADirectoryAndWritesReport) {
  const fs::path dir = fs::temp_directory_path() / "catena_cli_verify";
  fs::create_directories(dir / "scenes");
  std::ofstream(dir / "scenes" / "one.toml") << kGood;
  const CliRun run =
      run_cli("verify --scenes " + (dir / "scenes").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "report.json"));
  EXPECT_NE(run.output.find("1 scenes"), std::string::npos) << run.output;
}

TEST(Cli, ABrokenSolverMakesVerifyFailWithAReadableMessage) {
  // One shooting frequency perturbed by 1e-3 on the mooring scene: the frequency checks against
  // fe must fail, naming scene, check, solvers, mode, values and tolerance; exit code 1.
  const std::string scenes = std::string(CATENA_SOURCE_DIR) + "/verification/scenes/physical";
  const fs::path out = fs::temp_directory_path() / "catena_cli_perturb";
  const CliRun run = run_cli("verify --scenes " + scenes + " --filter mooring-line-900m --out " +
                             out.string() + " --perturb shooting:inplane:2:1e-3");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("FAIL mooring-line-900m / frequency / fe vs shooting mode 2"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("measured 9.99"), std::string::npos)
      << run.output;  // 1e-3 / (1 + 1e-3)
  EXPECT_NE(run.output.find("tolerance"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("rad/s"), std::string::npos) << run.output;  // both values shown
  // Unperturbed, the same run passes.
  EXPECT_EQ(
      run_cli("verify --scenes " + scenes + " --filter mooring-line-900m --out " + out.string())
          .exit_code,
      0);
}

TEST(Cli, VerifyReportsEveryBadSceneAndExitsTwo) {
  const fs::path dir = fs::temp_directory_path() / "catena_cli_verify_bad";
  fs::create_directories(dir);
  std::ofstream(dir / "a.toml") << kGood + "x = 1\n";
  std::ofstream(dir / "b.toml") << "[cable]\nlength = -1.0\n";
  const CliRun run =
      run_cli("verify --scenes " + dir.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("2 scene file(s)"), std::string::npos) << run.output;
}

// Unwritable outputs used to end in an internal error (exit 3) after all the solving, leaving a
// 0-byte file; they are now bad input (exit 2) named before the solving.
TEST(Cli, UnwritableOutputExitsTwoBeforeSolving) {
  const fs::path scene = write_scene("good3.toml", kGood);
  const fs::path afile = scene.parent_path() / "afile";
  std::ofstream(afile) << "x";
  for (const std::string& json : {std::string("/proc/x/out.json"), (afile / "out.json").string()}) {
    const CliRun run = run_cli("solve " + scene.string() + " --json " + json);
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find(json + ": cannot write"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("scene good"), std::string::npos) << "solved before failing:\n"
                                                                << run.output;
  }
  const CliRun verify = run_cli("verify --scenes " + scene.parent_path().string() +
                                " --filter good3 --out " + afile.string());
  EXPECT_EQ(verify.exit_code, 2) << verify.output;
  EXPECT_NE(verify.output.find("afile/report.json: cannot write"), std::string::npos)
      << verify.output;
}

// `solve /dev/zero` ran out of memory after 41 s.
TEST(Cli, SolveRefusesADeviceAndADeeplyNestedFile) {
  CliRun run = run_cli("solve /dev/zero");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("/dev/zero: cannot read scene file: a character device"),
            std::string::npos)
      << run.output;
  const fs::path deep =
      write_scene("deep.toml", kGood + "x = " + std::string(6000, '[') + std::string(6000, ']'));
  run = run_cli("solve " + deep.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("nested deeper than 64 levels"), std::string::npos) << run.output;
}

TEST(Cli, ReportRefusesAResultsFileThatIsADevice) {
  const fs::path out = fs::temp_directory_path() / "catena_cli_report_dev";
  const CliRun run = run_cli("report --from /dev/zero --no-figures --out " + out.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("/dev/zero: cannot read results JSON: a character device"),
            std::string::npos)
      << run.output;
}

// A scene file name that is not UTF-8 ended in an internal error when the JSON was written
// (exit 3, 0-byte file): the name is now stored escaped.
TEST(Cli, AFileNameThatIsNotUtf8IsStoredEscaped) {
  const fs::path dir = fs::temp_directory_path() / "catena_cli_latin1";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir /
                "c\xe2"
                "ble.toml")
      << kGood;
  const CliRun run = run_cli("solve '" +
                             (dir / "c\xe2"
                                    "ble.toml")
                                 .string() +
                             "' -q --json " + (dir / "out.json").string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  std::stringstream text;
  text << std::ifstream(dir / "out.json").rdbuf();
  EXPECT_NE(text.str().find("\"name\": \"c\\\\xE2ble\""), std::string::npos)
      << text.str().substr(0, 400);
}

// A deeply nested file killed `verify` (SIGSEGV, no report); dangling symlinks and FIFOs were
// skipped without a word; a symlink loop was an internal error. Each is now a scene error: the
// other scenes run, the report is written, the exit code is 2.
TEST(Cli, VerifyReportsUnreadableEntriesAsSceneErrorsAndStillRunsTheRest) {
  const fs::path dir = fs::temp_directory_path() / "catena_cli_verify_unreadable";
  fs::remove_all(dir);
  fs::create_directories(dir / "scenes");
  std::ofstream(dir / "scenes" / "one.toml") << kGood;
  std::ofstream(dir / "scenes" / "deep.toml")
      << kGood + "x = " + std::string(6000, '{') + std::string(6000, '}');
  fs::create_symlink("nowhere.toml", dir / "scenes" / "dangling.toml");
  fs::create_symlink("loop2.toml", dir / "scenes" / "loop1.toml");
  fs::create_symlink("loop1.toml", dir / "scenes" / "loop2.toml");
  ASSERT_EQ(std::system(("mkfifo " + (dir / "scenes" / "fifo.toml").string()).c_str()), 0);
  const CliRun run =
      run_cli("verify --scenes " + (dir / "scenes").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("6 scenes"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("5 scene errors"), std::string::npos) << run.output;
  for (const char* reason :
       {"deep.toml: line 10: arrays and inline tables nested deeper",
        "dangling.toml: cannot read "
        "scene file: dangling symbolic link",
        "fifo.toml: cannot read scene file: a FIFO",
        "loop1.toml: cannot read scene file: Too many levels of symbolic links"}) {
    EXPECT_NE(run.output.find(reason), std::string::npos) << reason << "\n" << run.output;
  }
  std::stringstream report;
  report << std::ifstream(dir / "out" / "report.json").rdbuf();
  EXPECT_NE(report.str().find("\"horizontal_force_n\""), std::string::npos);  // one.toml was solved
  EXPECT_NE(report.str().find("dangling symbolic link"), std::string::npos);
}

// `--perturb fe:inplane:99999999999:1` perturbed nothing and passed, though the run must fail.
TEST(Cli, APerturbationThatCannotApplyExitsTwo) {
  const std::string scenes = std::string(CATENA_SOURCE_DIR) + "/verification/scenes/physical";
  const fs::path out = fs::temp_directory_path() / "catena_cli_perturb_bad";
  const std::string base =
      "verify --scenes " + scenes + " --filter mooring-line-900m --out " + out.string();
  for (const std::string perturb : {"fe:inplane:99999999999:1", "fe:inplane:0:1", "fe:inplane:2:0",
                                    "fe:inplane:2:nan", "fe:inplane:2x:1", "fe:inplane:2:1:3"}) {
    const CliRun run = run_cli(base + " --perturb " + perturb);
    EXPECT_EQ(run.exit_code, 2) << perturb << "\n" << run.output;
    EXPECT_NE(run.output.find("--perturb " + perturb), std::string::npos) << run.output;
  }
  const CliRun too_high = run_cli(base + " --perturb fe:inplane:500:1e-3");
  EXPECT_EQ(too_high.exit_code, 2) << too_high.output;
  EXPECT_NE(too_high.output.find("nothing would be perturbed"), std::string::npos)
      << too_high.output;
  // Asked for, but never computed by that solver (asymptotic is not applicable to this scene).
  const CliRun not_run = run_cli(base + " --perturb asymptotic:inplane:1:1e-3");
  EXPECT_EQ(not_run.exit_code, 2) << not_run.output;
  EXPECT_NE(not_run.output.find("nothing was perturbed"), std::string::npos) << not_run.output;
}

}  // namespace

// The SI mooring line with 431 in-plane modes on fe's default 400 elements used to give mode 1 =
// -0.525 rad/s, "converged". A request beyond what the coarsest mesh of a chosen `elements`
// resolves is bad input (exit 2) naming the knob and the count (at the default 400, fe sizes its
// mesh instead: fe_solver_test DefaultMeshGrowsToTheModesAsked).
TEST(Cli, FeRefusesMoreModesThanItsMeshResolves) {
  std::string text = kGood + "[request]\ninplane_modes = 431\n[solvers]\nfe = { elements = 800 }\n";
  const fs::path scene = write_scene("too-many-modes.toml", text);
  const CliRun run = run_cli("solve " + scene.string() + " --solver fe");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("[solvers.fe].elements = 800: too few for 431 in-plane modes"),
            std::string::npos)
      << run.output;
}

const std::string kForcedGale = R"(
[gale]
h_over_b = 0.0
sag_param = 0.70
[request]
inplane_modes = 0
[request.forced]
frequencies = [0.1, 1.0]
)";

struct Response {
  nlohmann::json max_abs_tension_n;  // a number, or null
  std::string diagnostic;
};

// The forced responses of fe, then shooting, from `catena solve --json`.
std::vector<Response> forced_responses(const std::string& name,
                                       const std::string& text,
                                       int& exit_code) {
  const fs::path scene = write_scene(name + ".toml", text);
  const fs::path json = scene.parent_path() / (name + ".json");
  const CliRun run = run_cli("solve " + scene.string() +
                             " --solver fe --solver shooting -q --json " + json.string());
  exit_code = run.exit_code;
  const nlohmann::json results = nlohmann::json::parse(std::ifstream(json));
  std::vector<Response> responses;
  for (const char* solver : {"fe", "shooting"})
    for (const auto& response : results["scenes"][0]["solvers"][solver]["forced"])
      responses.push_back(
          {response["max_abs_tension_n"], response["diagnostic"].get<std::string>()});
  return responses;
}

// direction = [1e308, 1e308] overflowed its norm: both solvers answered max|tau| = 0, "converged".
// It is the direction [1, 1]: the same responses.
TEST(Cli, AHugeForcingDirectionVectorIsNormalisedWithoutOverflow) {
  int huge_exit = -1, unit_exit = -1;
  const std::vector<Response> huge = forced_responses(
      "direction-huge", kForcedGale + "direction = [1e308, 1e308]\namplitude = 0.01\n", huge_exit);
  const std::vector<Response> unit = forced_responses(
      "direction-unit", kForcedGale + "direction = [1.0, 1.0]\namplitude = 0.01\n", unit_exit);
  EXPECT_EQ(huge_exit, 0);
  EXPECT_EQ(unit_exit, 0);
  ASSERT_EQ(huge.size(), 4u);
  ASSERT_EQ(unit.size(), 4u);
  for (std::size_t i = 0; i < huge.size(); ++i) {
    EXPECT_EQ(huge[i].max_abs_tension_n, unit[i].max_abs_tension_n) << "response " << i;
    EXPECT_GT(huge[i].max_abs_tension_n.get<double>(), 0.0) << "response " << i;
    EXPECT_EQ(huge[i].diagnostic, "");
  }
}

// amplitude = 1e308: shooting returned null without a diagnostic and fe claimed a resonance at
// 0.1 rad/s. The response is linear in the amplitude: at 0.1 rad/s it is representable (5.9e307 N
// in both), at 1 rad/s it overflows and says so; never a null without a diagnostic.
TEST(Cli, AHugeAmplitudeGivesTheScaledResponseOrAnOverflowDiagnostic) {
  int exit_code = -1;
  const std::vector<Response> responses = forced_responses(
      "amplitude-huge", kForcedGale + "direction = \"tangential\"\namplitude = 1e308\n", exit_code);
  EXPECT_EQ(exit_code, 0);
  ASSERT_EQ(responses.size(), 4u);
  for (std::size_t i : {0u, 2u}) {
    EXPECT_EQ(responses[i].diagnostic, "");
    EXPECT_NEAR(responses[i].max_abs_tension_n.get<double>() / 5.9046e307, 1.0, 1e-4);
  }
  for (std::size_t i : {1u, 3u})
    EXPECT_NE(responses[i].diagnostic.find("overflows double precision"), std::string::npos)
        << responses[i].diagnostic;
  for (const Response& response : responses)
    EXPECT_TRUE(response.max_abs_tension_n.is_number() || !response.diagnostic.empty());
}

namespace {

// --time-limit: a limit too small for the solve stops it with partial results and says so, exit 0;
// a bad limit is bad usage naming the option; no progress line is written when stderr is not a
// terminal (here a pipe), so logs stay clean.
TEST(Cli, TimeLimitGivesAPartialResultAndNoProgressOffTerminal) {
  const fs::path scene = write_scene("time_limit.toml", kGood + "[request]\ninplane_modes = 4\n");
  const CliRun run = run_cli("solve " + scene.string() + " --solver shooting --time-limit 1e-9");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("time limit of 1e-09 s reached after 1 of 4 in-plane modes"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find('\r'), std::string::npos);
  const CliRun bad = run_cli("solve " + scene.string() + " --time-limit -3");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("--time-limit = -3"), std::string::npos) << bad.output;
  const fs::path dir = scene.parent_path() / "time_limit_suite";
  fs::create_directories(dir / "scenes");
  fs::copy_file(scene, dir / "scenes" / "one.toml", fs::copy_options::overwrite_existing);
  const CliRun verify = run_cli("verify --scenes " + (dir / "scenes").string() + " --out " +
                                (dir / "out").string() + " --time-limit 0");
  EXPECT_EQ(verify.exit_code, 2);
  EXPECT_NE(verify.output.find("--time-limit = 0"), std::string::npos) << verify.output;
}

// (The frequency limit is tested on SolveRequest: a scene of 1e5 frequencies takes a minute to
// parse, see the TOML reader.)
TEST(Cli, TooManyModesExitTwoNamingTheKey) {
  const fs::path modes =
      write_scene("too_many_modes.toml", kGood + "[request]\ninplane_modes = 1001\n");
  const CliRun run = run_cli("solve " + modes.string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("inplane_modes = 1001: must be an integer in [0, 1000]"),
            std::string::npos)
      << run.output;
}

}  // namespace
