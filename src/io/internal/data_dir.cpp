// SPDX-License-Identifier: MIT
#include "io/internal/data_dir.hpp"

#include <system_error>

#include "catena/data_dirs.hpp"

namespace catena::internal {

std::filesystem::path executable_path() {
  std::error_code error;
  const std::filesystem::path path = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path() : path;
}

std::optional<std::filesystem::path> find_data_dir(const std::filesystem::path& executable,
                                                   const std::filesystem::path& build_tree_dir) {
  std::error_code error;
  if (!executable.empty()) {
    const std::filesystem::path installed =
        executable.parent_path().parent_path() / "share" / "catena";
    if (std::filesystem::is_directory(installed, error)) return installed;
  }
  if (!build_tree_dir.empty() && std::filesystem::is_directory(build_tree_dir, error))
    return build_tree_dir;
  return std::nullopt;
}

std::optional<std::filesystem::path> data_dir() {
  return find_data_dir(executable_path(), kBuildTreeDataDir);
}

}  // namespace catena::internal
