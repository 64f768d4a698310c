// SPDX-License-Identifier: MIT
// `catena sweep`: a scene solved at every point of a SPEC's axes, on Dask. The engine is the Python
// package's (python/catena/_sweep_run.py: Dask is a Python library), so this command replaces the
// process with Debian's interpreter running `python3 -m catena sweep` on the same arguments, with
// PYTHONPATH set to the package next to this binary (build tree or installed). Signals (Ctrl-C)
// and the exit code are then the Python command's own.
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/commands.hpp"

namespace catena::cli {

namespace {

namespace fs = std::filesystem;

struct SweepArguments {
  std::string spec;
  std::string out;
  std::string scheduler;
  int workers = 0;
  double batch_seconds = 0.1;
  bool quiet = false;
};

// Runs the package's command, or exits 2 naming what cannot be imported (a missing Debian package
// or a package not found on PYTHONPATH) instead of Python's traceback.
constexpr const char* kBootstrap =
    "import os, sys\n"
    "try:\n"
    "    import catena.__main__ as command, distributed, pandas\n"
    "except ImportError as error:\n"
    "    sys.stderr.write(f'error: catena sweep runs in Python ({sys.executable}) and cannot "
    "import '\n"
    "                     f'{error.name}: {error}. Dask and pandas: apt-get install "
    "python3-distributed '\n"
    "                     f'python3-pandas (scripts/setup.sh); the catena package: cmake "
    "--install, or '\n"
    "                     f'PYTHONPATH=<build>/python (now: {os.environ.get(\"PYTHONPATH\", "
    "\"unset\")})\\n')\n"
    "    sys.exit(2)\n"
    "sys.exit(command.main(sys.argv[1:]))\n";

// The directory holding the package `catena` for this binary: <dir of catena>/python in a build
// tree, <prefix>/<CATENA_PYTHON_INSTALL_DIR> installed; empty if neither holds it.
std::string package_parent() {
  std::error_code error;
  const fs::path binary = fs::read_symlink("/proc/self/exe", error);
  if (error) {
    return {};
  }
  std::vector<fs::path> candidates{binary.parent_path() / "python"};
#ifdef CATENA_PYTHON_INSTALL_DIR
  candidates.push_back(binary.parent_path().parent_path() / CATENA_PYTHON_INSTALL_DIR);
#endif
  for (const auto& candidate : candidates) {
    if (fs::exists(candidate / "catena" / "__main__.py", error)) {
      return candidate.string();
    }
  }
  return {};
}

int run_sweep(const SweepArguments& arguments, bool workers_given, bool scheduler_given) {
  const char* override_interpreter = std::getenv("CATENA_PYTHON");
  const std::string interpreter = override_interpreter != nullptr && *override_interpreter != '\0'
                                      ? override_interpreter
                                      : "/usr/bin/python3";
  const std::string parent = package_parent();
  if (!parent.empty()) {
    const char* path = std::getenv("PYTHONPATH");
    const std::string value = path != nullptr && *path != '\0' ? parent + ":" + path : parent;
    ::setenv("PYTHONPATH", value.c_str(), 1);
  }
  std::vector<std::string> words{interpreter,
                                 "-c",
                                 kBootstrap,
                                 "sweep",
                                 arguments.spec,
                                 "--out",
                                 arguments.out,
                                 "--batch-seconds",
                                 fmt::format("{}", arguments.batch_seconds)};
  if (workers_given) {
    words.insert(words.end(), {"--workers", std::to_string(arguments.workers)});
  }
  if (scheduler_given) {
    words.insert(words.end(), {"--scheduler", arguments.scheduler});
  }
  if (arguments.quiet) {
    words.emplace_back("--quiet");
  }
  std::vector<char*> argv;
  for (auto& word : words) {
    argv.push_back(word.data());
  }
  argv.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  ::execv(interpreter.c_str(), argv.data());
  // Only reached when the interpreter cannot be started.
  fmt::print(
      stderr,
      "error: catena sweep runs in Python and cannot start {}: {} (install python3, or name an "
      "interpreter in CATENA_PYTHON)\n",
      interpreter, std::strerror(errno));
  return 2;
}

}  // namespace

void add_sweep_command(CLI::App& app, std::function<int()>& run) {
  CLI::App* command = app.add_subcommand(
      "sweep",
      "Solve a scene at every point of a SPEC's axes on Dask (a local cluster, or --scheduler):\n"
      "DIR/points.csv (one row per point: the axis values, each solver's status, frequencies\n"
      "[rad/s], error estimates, differences, statics [N], groups, wall_time_s [s]),\n"
      "DIR/summary.json and DIR/journal.csv. Rerunning the same command resumes: only the points\n"
      "not yet written are solved. Runs `python3 -m catena sweep` (needs python3-distributed and\n"
      "python3-pandas; CATENA_PYTHON names another interpreter). SPEC format and columns:\n"
      "docs/how-to/sweep.md.");
  static SweepArguments arguments;
  command->add_option("SPEC", arguments.spec, "the sweep's SPEC file (TOML)")
      ->required()
      ->check(non_empty_path());
  command
      ->add_option("--out", arguments.out,
                   "output directory DIR (created; a sweep of the same SPEC in it is resumed)")
      ->required()
      ->check(non_empty_path());
  CLI::Option* workers =
      command
          ->add_option("--workers", arguments.workers,
                       "local Dask cluster of N worker processes, one thread each\n"
                       "(default: all cores)")
          ->check(CLI::PositiveNumber);
  CLI::Option* scheduler =
      command->add_option("--scheduler", arguments.scheduler,
                          "address of an existing Dask scheduler, e.g. tcp://host:8786\n"
                          "(its workers need catena importable); it must answer within 5 s");
  workers->excludes(scheduler);
  command
      ->add_option("--batch-seconds", arguments.batch_seconds,
                   "target solve time of one Dask task [s]")
      ->check(CLI::Range(1e-6, 3600.0))
      ->capture_default_str();
  command->add_flag("--quiet", arguments.quiet,
                    "no progress line (points done, rate, ETA) on stderr");
  command->callback([&run, workers, scheduler] {
    run = [workers, scheduler] {
      return run_sweep(arguments, workers->count() > 0, scheduler->count() > 0);
    };
  });
}

}  // namespace catena::cli
