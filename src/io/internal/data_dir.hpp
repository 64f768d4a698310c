// SPDX-License-Identifier: MIT
#pragma once
// Where the data files the binary needs at run time live (the figure script, the module of JSON
// key names it imports, the transcribed published tables, the benchmark baselines):
//
//     <data dir>/figures.py  results_keys.py  reference/published/*.csv  benchmarks/*.csv|json
//
// Installed, the data dir is <prefix>/share/catena, found from the executable's own location
// (<prefix>/bin/catena -> ../share/catena), so an installed catena never reads its source tree. In
// the build tree it is <build>/share/catena, which CMake fills with links into the sources.

#include <filesystem>
#include <optional>

namespace catena::internal {

/// The running executable (/proc/self/exe); empty when it cannot be read.
std::filesystem::path executable_path();

/// The data dir for an executable at `executable`: <exe dir>/../share/catena when it exists,
/// else `build_tree_dir` when it exists, else nullopt.
std::optional<std::filesystem::path> find_data_dir(const std::filesystem::path& executable,
                                                   const std::filesystem::path& build_tree_dir);

/// find_data_dir for this process, with the build-tree data dir configured by CMake.
std::optional<std::filesystem::path> data_dir();

}  // namespace catena::internal
