// SPDX-License-Identifier: MIT
#include "catena/verification/suite.hpp"

#include <algorithm>
#include <mutex>
#include <numeric>

#include "verification/internal/parallel_for.hpp"

namespace catena {

namespace {

// A rough guess of a scene's cost, only to start the expensive scenes first: with the scenes in
// file order the longest one (stress-100-modes, about half the suite's wall time on 2 threads)
// started late and ran alone at the end. The cost of a mode grows with its index (more
// wavelengths to integrate or resolve), so modes count quadratically; forcing frequencies count
// by their number.
double cost_guess(const Scene& scene) {
  const double inplane = scene.request.inplane_modes, outofplane = scene.request.outofplane_modes;
  double cost = inplane * inplane + outofplane * outofplane;
  if (scene.request.forced)
    cost += 10.0 * static_cast<double>(scene.request.forced->omegas_rad_s.size());
  return cost;
}

// Scene indices, most expensive guess first (stable: ties keep file order).
std::vector<std::size_t> start_order(const std::vector<Scene>& scenes) {
  std::vector<std::size_t> order(scenes.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::vector<double> cost(scenes.size());
  for (std::size_t i = 0; i < scenes.size(); ++i) cost[i] = cost_guess(scenes[i]);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  return order;
}

}  // namespace

std::vector<SceneResult> run_scenes(const std::vector<Scene>& scenes,
                                    int jobs,
                                    const SceneRunOptions& options,
                                    const SuiteProgress& progress) {
  options.validate();  // before the workers: an exception must not escape a thread
  std::vector<SceneResult> results(scenes.size());
  const std::vector<std::size_t> order = start_order(scenes);
  // Scenes are independent: each worker writes its own slots (the report keeps file order).
  std::size_t done = 0;
  std::mutex progress_mutex;
  internal::parallel_for(scenes.size(), jobs, [&](std::size_t k) {
    const std::size_t i = order[k];
    results[i] = run_scene(scenes[i], options);
    std::lock_guard<std::mutex> lock(progress_mutex);
    ++done;
    if (progress) progress(done, scenes.size(), scenes[i].name);
  });
  return results;
}

}  // namespace catena
