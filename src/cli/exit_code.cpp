// One rule for the exit code of `catena solve` and `catena verify`.
#include "cli/commands.hpp"

namespace catena::cli {

int exit_code_of(const std::vector<SceneResult>& results) {
  bool bad_input = false, numerical_failure = false, failed_checks = false;
  for (const auto& result : results) {
    bad_input |= result.error_kind == SceneError::BadInput;
    numerical_failure |= result.error_kind == SceneError::NumericalFailure;
    failed_checks |= result.failed_checks() > 0;
  }
  if (bad_input) return 2;
  if (numerical_failure) return 3;
  return failed_checks ? 1 : 0;
}

}  // namespace catena::cli
