// SPDX-License-Identifier: MIT
#pragma once
// Independent work items on a pool of threads (the suite's scenes, the mutations of each scene).

#include <cstddef>
#include <functional>

namespace catena::internal {

/// Calls body(i) for every i in [0, count) on `jobs` threads (0: all cores); a shared counter
/// hands out the items, so each item is done once. `body` must not throw (an exception may not
/// escape a thread) and may only write state of its own item, or take its own lock.
void parallel_for(std::size_t count, int jobs, const std::function<void(std::size_t)>& body);

/// The threads parallel_for uses for `jobs` (0: all cores, at least 1).
int thread_count(int jobs);

}  // namespace catena::internal
