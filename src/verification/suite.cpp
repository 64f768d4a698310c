#include "catena/verification/suite.hpp"

#include <mutex>

#include "verification/internal/parallel_for.hpp"

namespace catena {

std::vector<SceneResult> run_scenes(const std::vector<Scene>& scenes,
                                    int jobs,
                                    const SceneRunOptions& options,
                                    const SuiteProgress& progress) {
  options.validate();  // before the workers: an exception must not escape a thread
  std::vector<SceneResult> results(scenes.size());
  // Scenes are independent: each worker writes its own slots.
  std::size_t done = 0;
  std::mutex progress_mutex;
  internal::parallel_for(scenes.size(), jobs, [&](std::size_t i) {
    results[i] = run_scene(scenes[i], options);
    std::lock_guard<std::mutex> lock(progress_mutex);
    ++done;
    if (progress) progress(done, scenes.size(), scenes[i].name);
  });
  return results;
}

}  // namespace catena
