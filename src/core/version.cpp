#include "catena/core/version.hpp"

#include "catena/build_info.hpp"

namespace catena {

std::string version() { return build_info::kVersion; }
std::string git_hash() { return build_info::kGitHash; }
std::string compiler() { return build_info::kCompiler; }
std::string build_type() { return build_info::kBuildType; }

}  // namespace catena
