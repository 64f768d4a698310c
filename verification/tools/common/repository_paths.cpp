// SPDX-License-Identifier: MIT
#include "common/repository_paths.hpp"

#include "catena/core/version.hpp"

namespace catena_tools {

RepositoryPaths repository_paths(int argc, char** argv, int first_argument) {
  const std::string root = argc > first_argument ? argv[first_argument] : CATENA_SOURCE_DIR;
  return {root + "/verification/reference/published", root + "/verification/comparisons"};
}

std::string generated_line() {
  return "generated: " + catena::utc_timestamp() + ", " + catena::provenance();
}

}  // namespace catena_tools
