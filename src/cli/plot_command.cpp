// SPDX-License-Identifier: MIT
// `catena plot RESULTS.json [--out FILE.svg|.png] [--modes ...]`: a picture of each solved scene
// (include/catena/io/scene_picture.hpp; docs/how-to/plot.md). Also the --plot options of `solve`
// and `import moordyn`, which draw through the same functions.
#include <fmt/format.h>

#include <filesystem>
#include <memory>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "catena/io/json_writer.hpp"
#include "catena/io/scene_picture.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "cli/commands.hpp"

namespace catena::cli {
namespace {

// Debian's interpreter, where python3-matplotlib installs (a python3 earlier on PATH, e.g.
// pyenv's, may not have it); as `catena report`.
std::string default_python() {
  return std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

struct PlotArguments {
  std::string results;
  std::string out;
  std::string modes = "1,2,3";
  std::string scene;
  std::string python = default_python();
  double mode_scale = 0.08;
  bool quiet = false;
};

// "1,2,3", "all" (every mode the results hold) or "none", into options.modes / all_modes.
void parse_modes(const std::string& text, const char* option, ScenePictureOptions& options) {
  options.modes.clear();
  options.all_modes = text == "all";
  if (text == "none" || text == "all") return;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    std::size_t used = 0;
    int value = 0;
    try {
      value = std::stoi(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || value < 1) {
      throw InvalidInput(
          fmt::format("{} {}: '{}' is not a mode number >= 1 (give e.g. 1,2,3, all or none)",
                      option, text, item));
    }
    options.modes.push_back(value);
    start = comma + 1;
  }
}

void print_files(const std::vector<ScenePictureFile>& files) {
  for (const auto& file : files) {
    if (file.path.empty()) {
      fmt::print("scene {}: not drawn: {}\n", file.scene, file.note);
    } else {
      fmt::print("wrote {} (scene {})\n", path_text(file.path), file.scene);
    }
  }
}

int run_plot(const PlotArguments& arguments) {
  ScenePictureOptions options;
  parse_modes(arguments.modes, "--modes", options);
  options.mode_scale = arguments.mode_scale;
  options.scene = arguments.scene;
  options.python = arguments.python;
  std::filesystem::path out = arguments.out;
  if (out.empty()) out = std::filesystem::path(arguments.results).replace_extension(".svg");
  check_not_an_input(out, {arguments.results}, "--out");
  check_scene_picture_output(out, "--out", options);
  const std::string text =
      read_input_file(arguments.results, "results JSON", std::uintmax_t(4) << 30);
  const auto files = write_scene_pictures(text, path_text(arguments.results), out, options);
  if (!arguments.quiet) print_files(files);
  return 0;
}

}  // namespace

void add_picture_options(CLI::App& command, PictureArguments& picture) {
  command
      .add_option("--plot-modes", picture.modes,
                  "With --plot: the modes drawn in each plane (1,2,3, all or none)")
      ->capture_default_str();
  command
      .add_option("--python", picture.python, "With --plot FILE.png: the Python with matplotlib")
      ->capture_default_str();
}

ScenePictureOptions picture_options(const PictureArguments& picture) {
  ScenePictureOptions options;
  parse_modes(picture.modes, "--plot-modes", options);
  options.python = picture.python.empty() ? default_python() : picture.python;
  return options;
}

std::vector<SceneResult> results_with_shapes(const std::vector<Scene>& scenes,
                                             const std::vector<SceneResult>& results,
                                             SceneRunOptions options) {
  options.checks = false;
  std::vector<SceneResult> out;
  for (std::size_t i = 0; i < results.size() && i < scenes.size(); ++i) {
    if (scenes[i].request.shapes || !results[i].statics) {
      out.push_back(results[i]);  // already drawable, or nothing to draw (its error says why)
      continue;
    }
    Scene scene = scenes[i];
    scene.request.shapes = true;
    options.only_solvers.clear();
    for (const auto& output : results[i].outputs) {
      if (is_exact_solver(output.solver) &&
          output.summary.termination != Termination::NotApplicable)
        options.only_solvers.push_back(output.solver);
    }
    out.push_back(run_scene(scene, options));
  }
  return out;
}

int draw_results(const std::vector<SceneResult>& results,
                 const std::string& out,
                 const ScenePictureOptions& options,
                 bool quiet,
                 int exit_code) {
  try {
    const auto files = write_scene_pictures(results_to_json(results), "the results", out, options);
    if (!quiet) print_files(files);
    return exit_code;
  } catch (const Error& error) {
    // The solve's own outcome stands (its errors were printed); a picture that could not be drawn
    // is a usage error of its own.
    fmt::print(stderr, "error: --plot {}: {}\n", out, error.what());
    return exit_code != 0 ? exit_code : 2;
  }
}

void add_plot_command(CLI::App& app, std::function<int()>& run) {
  auto arguments = std::make_shared<PlotArguments>();
  CLI::App* command = app.add_subcommand(
      "plot",
      "Draw each scene of a results JSON (`catena solve SCENE --json FILE`): the static profile\n"
      "to scale (x, z [m]; one path per segment; ends, clump weights and buoys, the seabed at its\n"
      "z with the touchdown points, the water surface for an imported MoorDyn line), the modes of\n"
      "the most accurate exact solver that gave shapes (named in the title; in-plane as the\n"
      "displaced profile, out-of-plane as v(s) in a second panel) and the static tension T(s)\n"
      "[kN]. The profile and the shapes are in the JSON only when the scene asks for shapes\n"
      "([request].shapes = true); `catena solve SCENE --plot FILE` asks for them itself.\n"
      "SVG is written natively; PNG needs Python with matplotlib (docs/how-to/plot.md).");
  command->add_option("results", arguments->results, "Results JSON of `catena solve --json`")
      ->required()
      ->check(non_empty_path());
  command
      ->add_option("--out", arguments->out,
                   std::string("Picture file, .svg or .png (default: RESULTS with .svg). With\n"
                               "several scenes, one file each: <stem>-<scene name>.svg.") +
                       kOutputPathHelp)
      ->check(non_empty_path());
  command
      ->add_option("--modes", arguments->modes,
                   "Modes drawn in each plane: numbers (1,2,3), all or none")
      ->capture_default_str();
  command->add_option("--scene", arguments->scene, "Draw only the scene of this name");
  command
      ->add_option("--mode-scale", arguments->mode_scale,
                   "Largest displacement of a drawn in-plane mode, as a fraction of the\n"
                   "profile's extent, in (0, 1]")
      ->capture_default_str();
  command->add_option("--python", arguments->python, "Python with matplotlib, for .png")
      ->capture_default_str();
  command->add_flag("--quiet,-q", arguments->quiet, "Print nothing but errors");
  command->callback([arguments, &run] { run = [arguments] { return run_plot(*arguments); }; });
}

}  // namespace catena::cli
