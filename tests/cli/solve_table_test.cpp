// SPDX-License-Identifier: MIT
// `catena solve`'s text (docs/reference/solve-output.md), golden-free: every table is parsed back
// and each value, estimate, spread and verdict compared with the JSON written by the same run, to
// the digits printed; the verdict line with the JSON's checks; the units recomputed from omega.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_support.hpp"

namespace {

namespace fs = std::filesystem;
using catena::testing::CliRun;
using catena::testing::run_cli;
using nlohmann::json;

const std::string kFolder = "catena_solve_table_test";
const std::string kMooring = R"(
[cable]
length = 1000.0
weight = 1000.0
EA = 5.0e8
mass = 120.0
added_mass = 80.0
a = [0.0, 0.0]
b = [900.0, 300.0]
[request]
inplane_modes = 6
outofplane_modes = 4
)";
constexpr double kPi = 3.14159265358979323846;

std::string source_scene(const std::string& relative) {
  return std::string(CATENA_SOURCE_DIR) + "/verification/scenes/" + relative;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> split(const std::string& text, const std::regex& separator) {
  std::vector<std::string> parts;
  for (std::sregex_token_iterator it(text.begin(), text.end(), separator, -1), end; it != end; ++it)
    if (!it->str().empty()) parts.push_back(*it);
  return parts;
}

// One plane's tables (the first and its continuations) as printed.
struct PrintedPlane {
  std::map<std::string, std::string> units;  // solver -> unit
  std::map<std::string, std::map<int, std::vector<std::string>>>
      solver;                                              // solver -> mode -> {value, est}
  std::map<std::string, std::map<int, std::string>> tail;  // column -> mode -> text
};

// The modal tables of `text`, by plane ("in-plane", "out-of-plane"). Headers are split at two or
// more spaces; a solver's column is the one followed by "est".
std::map<std::string, PrintedPlane> parse_modal_tables(const std::string& text) {
  std::map<std::string, PrintedPlane> planes;
  const std::vector<std::string> lines = lines_of(text);
  const std::regex title(R"(^  (in-plane|out-of-plane) modes)"), row(R"(^\s+\d+\s)");
  std::string plane;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::smatch m;
    if (std::regex_search(lines[i], m, title))
      plane = m[1];
    else if (lines[i] != "  (continued)")
      continue;
    const std::vector<std::string> header = split(lines[++i], std::regex(R"(\s{2,})"));
    std::vector<std::string> columns;  // per row token after the label: solver or tail column
    for (std::size_t h = 1; h < header.size(); ++h) {
      if (header[h] == "est") continue;
      const bool is_solver = h + 1 < header.size() && header[h + 1] == "est";
      columns.push_back(is_solver ? "solver:" + header[h] : header[h]);
    }
    for (; i + 1 < lines.size() && std::regex_search(lines[i + 1], row); ++i) {
      const std::vector<std::string> tokens = split(lines[i + 1], std::regex(R"(\s+)"));
      const int mode = std::stoi(tokens.at(0));
      std::size_t t = 1;
      for (const auto& column : columns) {
        if (column.rfind("solver:", 0) == 0) {
          const std::string name_unit = column.substr(7);
          const std::string name = name_unit.substr(0, name_unit.find(" ["));
          planes[plane].units[name] = name_unit.substr(name.size());
          planes[plane].solver[name][mode] = {tokens.at(t), tokens.at(t + 1)};
          t += 2;
        } else {
          planes[plane].tail[column][mode] = tokens.at(t++);
        }
      }
      EXPECT_EQ(t, tokens.size()) << lines[i + 1];
    }
  }
  return planes;
}

// |printed - exact| within half a unit of the last printed digit of `digits` significant ones.
void expect_printed(const std::string& printed, double exact, int digits, const std::string& what) {
  const double value = std::stod(printed);
  const double magnitude = std::max(std::abs(value), std::abs(exact));
  const double half_unit =
      magnitude > 0.0 ? 0.5 * std::pow(10.0, std::floor(std::log10(magnitude)) - (digits - 1))
                      : 0.0;
  EXPECT_LE(std::abs(value - exact), half_unit * (1.0 + 1e-6))
      << what << ": " << printed << " vs " << exact;
}

int severity(const std::string& verdict) {
  const std::vector<std::string> order{"SKIP", "PASS", "WARN", "SOURCE", "FAIL"};
  return static_cast<int>(std::find(order.begin(), order.end(), verdict) - order.begin());
}

// The JSON's checks as objects, keyed by field name.
std::vector<json> checks_of(const json& scene) {
  std::vector<json> checks;
  const json& fields = scene["checks"]["fields"];
  for (const auto& row : scene["checks"]["rows"]) {
    json check;
    for (std::size_t f = 0; f < fields.size(); ++f) check[fields[f].get<std::string>()] = row[f];
    checks.push_back(check);
  }
  return checks;
}

std::string worst_verdict(const std::vector<json>& checks, const std::string& plane, int mode) {
  std::string worst = "-";
  for (const auto& check : checks) {
    if (check["plane"] != plane || check["mode"] != mode) continue;
    const std::string verdict = check["verdict"];
    if (worst == "-" || severity(verdict) > severity(worst)) worst = verdict;
  }
  return worst;
}

struct Solved {
  CliRun run;
  json scene;
};

Solved solve(const std::string& scene, const std::string& options = "") {
  // Named by the test: ctest runs each test in a process of its own, in parallel.
  static int count = 0;
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const fs::path json_path =
      fs::temp_directory_path() / kFolder / (test + std::to_string(count++) + ".json");
  fs::create_directories(json_path.parent_path());
  CliRun run = run_cli("solve " + scene + " " + options + " --json " + json_path.string());
  json document = json::parse(std::ifstream(json_path));
  return {run, document["scenes"][0]};
}

// Every modal table of `solved` against its JSON: the values in `unit` (a Mode field), the
// estimates, the spread of the exact solvers, delta and zeta of the named solver, the verdicts.
void expect_tables_match_json(const Solved& solved, const std::string& unit_field) {
  const auto planes = parse_modal_tables(solved.run.output);
  const std::vector<json> checks = checks_of(solved.scene);
  int compared = 0;
  for (const auto& [plane, printed] : planes) {
    const std::string key = plane == "in-plane" ? "inplane" : "outofplane";
    std::map<int, std::vector<double>> exact_values;
    for (const auto& [solver, modes] : printed.solver) {
      const json& result = solved.scene["solvers"][solver][key];
      ASSERT_TRUE(result.is_object()) << solver << " " << plane;
      ASSERT_EQ(modes.size(), result["modes"].size()) << solver << " " << plane;
      for (const auto& mode : result["modes"]) {
        const int index = mode["index"];
        const auto& cell = modes.at(index);
        expect_printed(cell[0], mode[unit_field].get<double>(), 12,
                       solver + " " + plane + " mode " + std::to_string(index));
        const double estimate = mode["relative_error_estimate"];
        if (cell[1] == "-")
          EXPECT_LT(estimate, 0.0) << solver;  // none
        else
          expect_printed(cell[1].substr(0, cell[1].find('*')), estimate, 1, solver + " estimate");
        EXPECT_EQ(cell[1].back() == '*', !mode["meets_target"].get<bool>()) << cell[1];
        if (solver == "fe" || solver == "shooting" || solver == "frobenius")
          exact_values[index].push_back(mode["omega_rad_s"]);
        ++compared;
      }
    }
    for (const auto& [index, values] : exact_values) {
      const auto [low, high] = std::minmax_element(values.begin(), values.end());
      if (values.size() >= 2)
        expect_printed(printed.tail.at("spread").at(index), (*high - *low) / *high, 1, "spread");
      EXPECT_EQ(printed.tail.at("check").at(index), worst_verdict(checks, plane, index))
          << plane << " mode " << index;
    }
    for (const auto& [column, cells] : printed.tail) {
      const std::smatch m = [&] {
        std::smatch match;
        std::regex_match(column, match, std::regex(R"((\w+) (delta \[1/s\]|zeta))"));
        return match;
      }();
      if (m.empty()) continue;
      const std::string field = m[2] == "zeta" ? "damping_ratio" : "decay_rate_1_s";
      for (const auto& mode : solved.scene["solvers"][m[1].str()][key]["modes"])
        expect_printed(cells.at(mode["index"]), mode[field].get<double>(), m[2] == "zeta" ? 6 : 10,
                       column);
    }
  }
  EXPECT_GT(compared, 0) << solved.run.output;
}

// The verdict line against the JSON's checks: FAIL when one failed, each verdict's count.
void expect_verdict_matches_json(const std::string& line, const json& scene) {
  std::map<std::string, int> counts;
  for (const auto& check : checks_of(scene)) ++counts[check["verdict"].get<std::string>()];
  std::smatch m;
  ASSERT_TRUE(
      std::regex_search(line, m, std::regex(R"(^verdict: (PASS|FAIL), (\S+): (\d+) checks: )")))
      << line;
  EXPECT_EQ(m[1], counts["FAIL"] > 0 ? "FAIL" : "PASS") << line;
  EXPECT_EQ(m[2], scene["name"].get<std::string>());
  EXPECT_EQ(std::stoul(m[3]), scene["checks"]["rows"].size());
  for (const char* verdict : {"PASS", "FAIL", "SOURCE", "WARN", "SKIP"}) {
    const std::regex count_of(std::string(R"((\d+) )") + verdict + R"(\b)");
    std::smatch c;
    const int printed = std::regex_search(line, c, count_of) ? std::stoi(c[1]) : 0;
    EXPECT_EQ(printed, counts[verdict]) << verdict << " in " << line;
  }
}

std::string verdict_line(const std::string& output) {
  for (const auto& line : lines_of(output))
    if (line.rfind("verdict: ", 0) == 0) return line;
  return {};
}

TEST(SolveTable, EveryPrintedValueIsTheJsonsToItsDigits) {
  const fs::path scene = catena::testing::write_temp_file(kFolder, "mooring.toml", kMooring);
  const Solved solved = solve(scene.string());
  ASSERT_EQ(solved.run.exit_code, 0) << solved.run.output;
  expect_tables_match_json(solved, "omega_rad_s");
  expect_verdict_matches_json(verdict_line(solved.run.output), solved.scene);
  // The reference: of fe and shooting, the one with the smaller largest estimate in each plane.
  const auto estimate = [&](const char* solver, const char* plane) {
    return solved.scene["solvers"][solver][plane]["summary"]["max_error_estimate"].get<double>();
  };
  for (const char* plane : {"inplane", "outofplane"}) {
    const std::string expected =
        estimate("fe", plane) < estimate("shooting", plane) ? "fe" : "shooting";
    EXPECT_NE(verdict_line(solved.run.output).find("reference: " + expected), std::string::npos)
        << plane << ": " << solved.run.output;
  }
  for (const auto& line : lines_of(solved.run.output)) EXPECT_LE(line.size(), 120u) << line;
  // A declined solver: one short line, why.
  EXPECT_NE(solved.run.output.find("  frobenius: not applicable: "), std::string::npos);
}

// Damped modes: delta and zeta beside the damped frequencies; more solvers than fit in 120
// columns continue in a second table.
TEST(SolveTable, DampedModesAndWideTablesHoldTheJsonsValues) {
  const Solved solved = solve(
      source_scene("damped/taut-inclined-eps0.18-phi23.46-lambda2-30-light-normal-damped.toml"));
  ASSERT_EQ(solved.run.exit_code, 0) << solved.run.output;
  EXPECT_NE(solved.run.output.find("  (continued)"), std::string::npos) << solved.run.output;
  EXPECT_NE(solved.run.output.find("delta [1/s]"), std::string::npos) << solved.run.output;
  expect_tables_match_json(solved, "omega_rad_s");
  expect_verdict_matches_json(verdict_line(solved.run.output), solved.scene);
  // Every line but the scene's name and verdict, whose name alone is 62 characters.
  for (const auto& line : lines_of(solved.run.output)) {
    if (line.rfind("  ", 0) == 0) EXPECT_LE(line.size(), 120u) << line;
  }
}

// A check held to an impossible tolerance fails: the row says FAIL, the verdict line too (as the
// JSON), exit code 1.
TEST(SolveTable, AFailedCheckShowsInItsRowAndInTheVerdictLine) {
  const fs::path scene = catena::testing::write_temp_file(
      kFolder, "strict.toml", kMooring + "[checks]\nfrequency_rel = 1e-16\n");
  const Solved solved = solve(scene.string(), "--solver fe --solver shooting");
  EXPECT_EQ(solved.run.exit_code, 1) << solved.run.output;
  EXPECT_EQ(verdict_line(solved.run.output).rfind("verdict: FAIL", 0), 0u) << solved.run.output;
  expect_tables_match_json(solved, "omega_rad_s");
  expect_verdict_matches_json(verdict_line(solved.run.output), solved.scene);
}

// Hz = omega / 2 pi; kL/pi = omega L sqrt((m + ma) / T0) / pi; Gale's omega / sqrt(g/a) with
// g/a = (W0/m) / (H/W0): each recomputed from the JSON's omega, not read from its own field.
TEST(SolveTable, UnitsAreConvertedFromOmega) {
  const fs::path scene = catena::testing::write_temp_file(kFolder, "units.toml", kMooring);
  const double L = 1000.0, W0 = 1000.0, m = 120.0, ma = 80.0;
  for (const char* unit : {"hz", "kl-pi", "gale", "rad/s"}) {
    const Solved solved = solve(scene.string(), std::string("--units ") + unit);
    ASSERT_EQ(solved.run.exit_code, 0) << solved.run.output;
    const double T0 = solved.scene["groups"]["t0_n"];
    const double H = solved.scene["statics"]["horizontal_force_n"];
    const std::map<std::string, double> per_rad_s{{"hz", 1.0 / (2.0 * kPi)},
                                                  {"kl-pi", L * std::sqrt((m + ma) / T0) / kPi},
                                                  {"gale", 1.0 / std::sqrt((W0 / m) / (H / W0))},
                                                  {"rad/s", 1.0}};
    const std::map<std::string, std::string> header{
        {"hz", " [Hz]"}, {"kl-pi", " [kL/pi]"}, {"gale", " [w/sqrt(g/a)]"}, {"rad/s", " [rad/s]"}};
    const auto planes = parse_modal_tables(solved.run.output);
    ASSERT_EQ(planes.size(), 2u) << solved.run.output;
    for (const auto& [plane, printed] : planes) {
      const std::string key = plane == "in-plane" ? "inplane" : "outofplane";
      for (const auto& [solver, modes] : printed.solver) {
        EXPECT_EQ(printed.units.at(solver), header.at(unit)) << unit;
        for (const auto& mode : solved.scene["solvers"][solver][key]["modes"]) {
          // 12 digits of a value recomputed in double: allow the recomputation's rounding too.
          const double expected = mode["omega_rad_s"].get<double>() * per_rad_s.at(unit);
          expect_printed(modes.at(mode["index"])[0], expected, 11,
                         std::string(unit) + " " + solver);
        }
      }
    }
  }
  const CliRun bad = run_cli("solve " + scene.string() + " --units furlongs");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(
      bad.output.find("--units furlongs: unknown unit (choose one of rad/s, hz, kl-pi, gale)"),
      std::string::npos)
      << bad.output;
}

TEST(SolveTable, QuietPrintsTheVerdictOnly) {
  const fs::path scene = catena::testing::write_temp_file(kFolder, "quiet.toml", kMooring);
  const Solved solved = solve(scene.string(), "--quiet");
  ASSERT_EQ(solved.run.exit_code, 0) << solved.run.output;
  const auto lines = lines_of(solved.run.output);
  ASSERT_EQ(lines.size(), 1u) << solved.run.output;
  expect_verdict_matches_json(lines[0], solved.scene);
}

// Colour only on a terminal (script(1) gives the run one), and never with NO_COLOR or TERM=dumb.
TEST(SolveTable, ColourOnATerminalOnlyAndNeverInAPipe) {
  const std::string scene = source_scene("damped/mooring-line-900m-damped.toml");  // has WARN rows
  const CliRun piped = run_cli("solve " + scene);
  ASSERT_EQ(piped.exit_code, 0) << piped.output;
  EXPECT_NE(piped.output.find("WARN"), std::string::npos);
  EXPECT_EQ(piped.output.find('\033'), std::string::npos) << piped.output;
  if (std::system("script --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1)";
  const auto on_terminal = [&](const std::string& environment) {
    // stdout only: the progress on stderr has its own escape codes (terminal_progress.cpp).
    const std::string command = "script -qec \"env " + environment + " " + CATENA_CLI_PATH +
                                " solve " + scene + " 2>/dev/null\" /dev/null";
    FILE* pipe = popen(command.c_str(), "r");
    std::string output;
    for (int c; pipe && (c = fgetc(pipe)) != EOF;) output += static_cast<char>(c);
    if (pipe) pclose(pipe);
    return output;
  };
  const std::string coloured = on_terminal("-u NO_COLOR TERM=xterm");
  EXPECT_NE(coloured.find("\033[33m"), std::string::npos) << coloured;
  for (const char* environment : {"NO_COLOR=1 TERM=xterm", "-u NO_COLOR TERM=dumb"}) {
    const std::string plain = on_terminal(environment);
    EXPECT_NE(plain.find("WARN"), std::string::npos) << environment << "\n" << plain;
    EXPECT_EQ(plain.find('\033'), std::string::npos) << environment << "\n" << plain;
  }
}

// --verbose: each solver's plane summaries, notes and warnings, each exactly once; without it,
// none of them.
TEST(SolveTable, VerboseSaysEachLongMessageOnce) {
  const fs::path scene = catena::testing::write_temp_file(kFolder, "verbose.toml", kMooring);
  const Solved verbose = solve(scene.string(), "--verbose");
  const Solved plain = solve(scene.string());
  ASSERT_EQ(verbose.run.exit_code, 0) << verbose.run.output;
  const auto count = [](const std::string& text, const std::string& what) {
    int n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
      ++n;
    return n;
  };
  int messages = 0;
  for (const auto& [solver, output] : verbose.scene["solvers"].items()) {
    std::vector<std::string> long_messages;
    for (const char* plane : {"inplane", "outofplane"}) {
      if (!output.contains(plane) || output[plane].is_null()) continue;
      long_messages.push_back(output[plane]["summary"]["message"]);
    }
    for (const auto& note : output["summary"]["notes"]) long_messages.push_back(note);
    for (const auto& warning : output["summary"]["warnings"]) long_messages.push_back(warning);
    for (const auto& message : long_messages) {
      EXPECT_EQ(count(verbose.run.output, message), 1) << solver << ": " << message;
      EXPECT_EQ(count(plain.run.output, message), 0) << solver << ": " << message;
      ++messages;
    }
  }
  EXPECT_GE(messages, 4);
}

}  // namespace
