// SPDX-License-Identifier: MIT
// The `catena` command-line tool: solve a scene, run the verification suite, list solvers.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <filesystem>
#include <functional>

#include "catena/core/error.hpp"
#include "catena/core/version.hpp"
#include "catena/io/file_access.hpp"
#include "cli/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "catena: linear dynamics of cables (natural frequencies, mode shapes, dynamic tension,\n"
      "forced response) by independent methods, cross-checked against each other and against\n"
      "published tables.\n\n"
      "Exit codes: 0 ok, 1 a verification check failed, 2 bad input, usage or a file that cannot\n"
      "be read or written (the path is named), 3 internal error\n"
      "or a numerical failure that left a scene unsolved (e.g. statics that do not converge).",
      "catena"};
  app.set_version_flag(
      "--version", fmt::format("catena {} (git {}, {}, {})", catena::version(), catena::git_hash(),
                               catena::compiler(), catena::build_type()));
  app.require_subcommand(1);
  std::function<int()> run;
  catena::cli::add_solve_command(app, run);
  catena::cli::add_verify_command(app, run);
  catena::cli::add_report_command(app, run);
  catena::cli::add_solvers_command(app, run);
  catena::cli::add_check_command(app, run);
  catena::cli::add_import_command(app, run);
  catena::cli::add_sweep_command(app, run);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : 2;
  }
  try {
    return run ? run() : 2;
  } catch (const catena::Error& error) {
    fmt::print(stderr, "error: {}\n", error.what());
    return 2;
  } catch (const std::filesystem::filesystem_error& error) {
    // The environment, not catena: a file or directory that cannot be read or created.
    fmt::print(stderr, "error: {}{}: {}\n", catena::path_text(error.path1()),
               error.path2().empty() ? "" : " -> " + catena::path_text(error.path2()),
               error.code().message());
    return 2;
  } catch (const std::exception& error) {
    fmt::print(stderr, "internal error: {}\n", error.what());
    return 3;
  }
}
