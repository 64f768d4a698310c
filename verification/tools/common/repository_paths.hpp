// SPDX-License-Identifier: MIT
#pragma once
// Where the verification tools read the transcribed published tables and write our comparisons,
// and the provenance line every generated CSV carries.
#include <string>

namespace catena_tools {

/// The two folders a generator uses, under one repository root.
struct RepositoryPaths {
  /// <root>/verification/reference/published: tables transcribed as printed (read only).
  std::string published;
  /// <root>/verification/comparisons: our generated comparisons (written).
  std::string comparisons;
};

/// The repository root is argv[first_argument] when given, else the source tree the tools were
/// built from (so a tool can run from any directory).
RepositoryPaths repository_paths(int argc, char** argv, int first_argument = 1);

/// "generated: <UTC date>, catena <version> (git <hash>, <compiler>, <build type>)".
std::string generated_line();

}  // namespace catena_tools
