// SPDX-License-Identifier: MIT
#include "verification/internal/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace catena::internal {

int thread_count(int jobs) {
  return jobs > 0 ? jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void parallel_for(std::size_t count, int jobs, const std::function<void(std::size_t)>& body) {
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < count; i = next++) body(i);
  };
  const std::size_t threads = std::min<std::size_t>(static_cast<std::size_t>(thread_count(jobs)),
                                                    std::max<std::size_t>(count, 1));
  std::vector<std::thread> pool;
  for (std::size_t j = 0; j < threads; ++j) pool.emplace_back(worker);
  for (auto& thread : pool) thread.join();
}

}  // namespace catena::internal
