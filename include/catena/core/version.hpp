#pragma once
/// \file
/// Library version and build provenance (reports print these).

#include <string>

namespace catena {

/// "0.1.0"
std::string version();
/// Short git hash of the source tree at configure time, or "unknown".
std::string git_hash();
/// Compiler id and version, e.g. "GNU 12.2.0".
std::string compiler();
/// CMake build type, e.g. "Release".
std::string build_type();

}  // namespace catena
