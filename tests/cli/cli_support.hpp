// SPDX-License-Identifier: MIT
#pragma once
// Running the built `catena` binary from tests: its exit code and its combined output.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace catena::testing {

struct CliRun {
  int exit_code;
  std::string output;  // stdout and stderr
};

/// Runs `catena <arguments>` through the shell (arguments are not quoted).
inline CliRun run_cli(const std::string& arguments) {
  const std::string command = std::string(CATENA_CLI_PATH) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer{};
  while (pipe && fgets(buffer.data(), buffer.size(), pipe)) output += buffer.data();
  const int status = pipe ? pclose(pipe) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

/// Writes `text` to <temp>/<folder>/<name> and returns the path.
inline std::filesystem::path write_temp_file(const std::string& folder,
                                             const std::string& name,
                                             const std::string& text) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / folder;
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace catena::testing
