// SPDX-License-Identifier: MIT
#pragma once
// Running an external program (the report's figure script) without a shell: the arguments go to
// the program as they are, so paths with spaces or quotes need no quoting.

#include <filesystem>
#include <string>
#include <vector>

namespace catena::internal {

/// Runs `arguments[0]` (searched on PATH when it has no '/') with `arguments` as its argv and
/// waits for it. Its stdout and stderr go to `output_file` when given (created or truncated),
/// otherwise they are inherited. Returns the exit status (0-255), 128 + the signal number when it
/// was killed, or 127 when it could not be started (as a shell would). Throws InvalidInput for an
/// empty argument vector.
int run_process(const std::vector<std::string>& arguments,
                const std::filesystem::path& output_file = {});

}  // namespace catena::internal
