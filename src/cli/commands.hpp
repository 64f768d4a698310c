// SPDX-License-Identifier: MIT
#pragma once
// The `catena` subcommands. Each returns the process exit code:
// 0 ok, 1 a verification check failed, 2 bad input or usage, 3 internal error or a numerical
// failure that left a scene without a solution (e.g. statics that do not converge).

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "catena/verification/scene_runner.hpp"

namespace catena::cli {

/// Registers `solve` on `app`; `run` is set to the command's body.
void add_solve_command(CLI::App& app, std::function<int()>& run);
void add_verify_command(CLI::App& app, std::function<int()>& run);
void add_solvers_command(CLI::App& app, std::function<int()>& run);
void add_report_command(CLI::App& app, std::function<int()>& run);
/// `check`: another program's results against Catena's reference (src/cli/check_command.cpp).
void add_check_command(CLI::App& app, std::function<int()>& run);
/// `import moordyn`: MoorDyn decks as scenes (src/cli/import_command.cpp).
void add_import_command(CLI::App& app, std::function<int()>& run);
/// `sweep`: a SPEC's points on Dask, by the Python package's `python3 -m catena sweep`
/// (src/cli/sweep_command.cpp, docs/how-to/sweep.md).
void add_sweep_command(CLI::App& app, std::function<int()>& run);

/// For every option naming a file or directory: an empty value ("--json ''", often an unset
/// shell variable) is a usage error naming the option (exit 2), never "no output" or "the
/// built-in table".
CLI::Validator non_empty_path();

/// What every output option's help says about the kinds of path it writes (file_access.hpp).
inline constexpr const char* kOutputPathHelp =
    "\nA symlink is followed (its target replaced, the link kept); a character device\n"
    "or FIFO (/dev/null, /dev/stdout, a named pipe) is written through; a block\n"
    "device, a socket or an input of the same run is refused.";

/// --tolerances and --findings (empty: the tables built into the library).
struct TableArguments {
  std::string tolerances;
  std::string findings;
};
void add_table_options(CLI::App& command, TableArguments& tables);
/// --time-limit SECONDS (per scene); `what` completes the help text.
CLI::Option* add_time_limit_option(CLI::App& command, double& seconds, const std::string& what);
/// Sets options.time_limit_s when the option was given; InvalidInput naming --time-limit unless
/// 0 < seconds <= RunLimits::kMaxTimeLimit.
void apply_time_limit(const CLI::Option& option, double seconds, SceneRunOptions& options);

/// Run options holding the chosen tables (ParseError/InvalidInput when a file is bad).
SceneRunOptions run_options_with_tables(const TableArguments& tables);

/// The exit code of a run of scenes: 2 if any scene had bad input, else 3 if any scene failed
/// numerically, else 1 if any check failed, else 0.
int exit_code_of(const std::vector<SceneResult>& results);

}  // namespace catena::cli
