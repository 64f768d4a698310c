// SPDX-License-Identifier: MIT
#include "catena/core/version.hpp"

#include <chrono>
#include <ctime>

#include "catena/build_info.hpp"

namespace catena {

std::string version() { return build_info::kVersion; }
std::string git_hash() { return build_info::kGitHash; }
std::string compiler() { return build_info::kCompiler; }
std::string build_type() { return build_info::kBuildType; }

std::string provenance() {
  return "catena " + version() + " (git " + git_hash() + ", " + compiler() + ", " + build_type() +
         ")";
}

std::string utc_timestamp() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

}  // namespace catena
