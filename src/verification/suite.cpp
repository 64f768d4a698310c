#include "catena/verification/suite.hpp"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>

namespace catena {

std::vector<SceneResult> run_scenes(const std::vector<Scene>& scenes,
                                    int jobs,
                                    const SceneRunOptions& options,
                                    const SuiteProgress& progress) {
  options.validate();  // before the workers: an exception must not escape a thread
  const int threads = jobs > 0 ? jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  std::vector<SceneResult> results(scenes.size());
  // Scenes are independent: a shared counter hands them out, each worker writes its own slots.
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex progress_mutex;
  auto worker = [&] {
    for (std::size_t i = next++; i < scenes.size(); i = next++) {
      results[i] = run_scene(scenes[i], options);
      std::lock_guard<std::mutex> lock(progress_mutex);
      ++done;
      if (progress) progress(done, scenes.size(), scenes[i].name);
    }
  };
  std::vector<std::thread> pool;
  for (int j = 0; j < std::min<int>(threads, static_cast<int>(std::max<std::size_t>(scenes.size(), 1))); ++j) {
    pool.emplace_back(worker);
  }
  for (auto& thread : pool) thread.join();
  return results;
}

}  // namespace catena
