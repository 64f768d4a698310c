// SPDX-License-Identifier: MIT
#include "io/report/figures.hpp"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "io/internal/process.hpp"
#include "io/internal/results_keys.hpp"

namespace catena::internal {

std::vector<Image> draw_figures(const std::filesystem::path& results_json,
                                const FigureInputs& inputs,
                                const std::filesystem::path& figures_dir,
                                std::string& note) {
  if (!std::filesystem::exists(inputs.script)) {
    note = "figures not drawn: " + inputs.script.string() + " not found";
    return {};
  }
  std::filesystem::create_directories(figures_dir);
  const std::filesystem::path log = figures_dir / "figures.log";
  const int status =
      run_process({inputs.python, inputs.script.string(), "--results", results_json.string(),
                   "--published", inputs.published_dir.string(), "--time-vs-error",
                   inputs.time_vs_error.string(), "--out", figures_dir.string()},
                  log);
  if (status != 0) {
    note = fmt::format("figures not drawn: '{}' failed (status {}); see {}", inputs.python, status,
                       log.string());
    return {};
  }
  std::ifstream index(figures_dir / "index.json");
  if (!index) {
    note = "figures not drawn: figures.py wrote no index.json";
    return {};
  }
  const nlohmann::json list = nlohmann::json::parse(index, nullptr, false);
  if (!list.is_array()) {
    note = "figures not drawn: unreadable figures/index.json";
    return {};
  }
  std::vector<Image> images;
  for (const auto& item : list) {
    images.push_back({figures_dir / item.value(key::file, ""), item.value(key::caption, "")});
  }
  return images;
}

}  // namespace catena::internal
