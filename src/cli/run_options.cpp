// SPDX-License-Identifier: MIT
// What the commands share: the tables a run checks against, the check on path options, and one
// rule for the exit code.
#include "catena/io/findings_reader.hpp"
#include "catena/io/tolerance_reader.hpp"
#include "cli/commands.hpp"

namespace catena::cli {

CLI::Validator non_empty_path() {
  return CLI::Validator(
      [](std::string& value) {
        return value.empty() ? std::string("an empty path; give a file or directory name")
                             : std::string();
      },
      "", "non-empty path");
}

void add_table_options(CLI::App& command, TableArguments& tables) {
  command
      .add_option("--tolerances", tables.tolerances,
                  "Tolerance table (TOML) instead of the built-in verification/tolerances.toml")
      ->check(non_empty_path());
  command
      .add_option("--findings", tables.findings,
                  "Reviewed findings (TOML) instead of the built-in verification/findings.toml")
      ->check(non_empty_path());
}

CLI::Option* add_time_limit_option(CLI::App& command, double& seconds, const std::string& what) {
  return command.add_option(
      "--time-limit", seconds,
      "Wall-clock limit in seconds " + what +
          " (default: none). When it runs out, each solver stops after the mode, "
          "forcing frequency or mesh level it is working on and reports what it has "
          "as 'no-convergence: time limit of X s reached after k of n ...'; the "
          "parts not started are reported with nothing done.");
}

void apply_time_limit(const CLI::Option& option, double seconds, SceneRunOptions& options) {
  if (option.count() == 0) return;
  RunLimits::check_time_limit(seconds, "--time-limit");
  options.time_limit_s = seconds;
}

SceneRunOptions run_options_with_tables(const TableArguments& tables) {
  SceneRunOptions options;
  options.tolerances = tables.tolerances.empty() ? builtin_tolerance_table()
                                                 : read_tolerance_file(tables.tolerances);
  options.findings =
      tables.findings.empty() ? builtin_findings_table() : read_findings_file(tables.findings);
  return options;
}

int exit_code_of(const std::vector<SceneResult>& results) {
  bool bad_input = false, numerical_failure = false, failed_checks = false;
  for (const auto& result : results) {
    bad_input |= result.error_kind == SceneError::BadInput;
    numerical_failure |= result.error_kind == SceneError::NumericalFailure;
    failed_checks |= result.failed_checks() > 0;
  }
  if (bad_input) return 2;
  if (numerical_failure) return 3;
  return failed_checks ? 1 : 0;
}

}  // namespace catena::cli
