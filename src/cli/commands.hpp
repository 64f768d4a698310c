#pragma once
// The `catena` subcommands. Each returns the process exit code:
// 0 ok, 1 a verification check failed, 2 bad input or usage, 3 internal error.

#include <CLI/CLI.hpp>
#include <functional>

namespace catena::cli {

/// Registers `solve` on `app`; `run` is set to the command's body.
void add_solve_command(CLI::App& app, std::function<int()>& run);
void add_verify_command(CLI::App& app, std::function<int()>& run);
void add_solvers_command(CLI::App& app, std::function<int()>& run);
void add_report_command(CLI::App& app, std::function<int()>& run);

}  // namespace catena::cli
