// SPDX-License-Identifier: MIT
// `catena import moordyn DECK --out DIR`: MoorDyn lines as Catena scenes
// (docs/how-to/moordyn-import.md).
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <memory>

#include "catena/io/file_access.hpp"
#include "catena/io/moordyn_deck.hpp"
#include "catena/io/moordyn_import.hpp"
#include "catena/io/moordyn_notes.hpp"
#include "catena/io/scene_picture.hpp"
#include "catena/io/scene_reader.hpp"
#include "cli/commands.hpp"

namespace catena::cli {
namespace {

struct ImportArguments {
  std::string deck;
  std::string out;
  bool quiet = false;
  bool plot = false;
};

std::string line_list(const std::vector<int>& lines) {
  std::string out;
  for (int id : lines) out += (out.empty() ? "" : "+") + std::to_string(id);
  return out;
}

// The summary: a short table (one row per line or chain: its scene and tables, and the statics
// with its seabed, or why it was not converted), then the notes per line, then what became of the
// rest of the deck. Refused rows keep the form "<ids> not converted: <reason>" (scripts read it).
void print_summary(const MoorDynDeck& deck,
                   const std::vector<ImportedScene>& scenes,
                   const std::filesystem::path& out) {
  fmt::print("{:<10} {}\n", "line(s)",
             "scene file  tables: statics with the seabed, or why not converted");
  for (const auto& scene : scenes) {
    if (scene.reason.empty()) {
      fmt::print("{:<10} {}  {}: {}\n", line_list(scene.lines), path_text(out / scene.file_name),
                 scene.tables, scene.statics);
    } else {
      fmt::print("{:<10} not converted: {}\n", line_list(scene.lines), scene.reason);
    }
  }
  bool any = false;
  for (const auto& scene : scenes) {
    for (const auto& note : scene.notes) {
      if (!any) fmt::print("\nNotes (also in each scene's header):\n");
      any = true;
      fmt::print("  {}: {}\n", line_list(scene.lines), note);
    }
  }
  const std::vector<MoorDynNote> notes = moordyn_deck_notes(deck);
  if (!notes.empty()) fmt::print("\nWhat became of the rest of the deck:\n");
  for (const auto& note : notes) fmt::print("  {}: {} - {}\n", note.item, note.fate, note.detail);
}

// --plot: each converted line solved as its scene says, with shapes, and drawn next to its scene
// file as <scene>.svg. A line whose statics with its seabed was refused is solved and drawn without
// it, under the seabed it should rest on, so that a line hanging below the water depth is seen.
// Returns 0, or 2 when a picture could not be drawn (the reason is printed).
int plot_scenes(const std::vector<ImportedScene>& scenes, const ImportArguments& arguments) {
  SceneRunOptions run_options;  // the picture needs no checks
  run_options.checks = false;
  int code = 0;
  for (const auto& imported : scenes) {
    if (!imported.reason.empty()) continue;
    const std::filesystem::path file = std::filesystem::path(arguments.out) / imported.file_name;
    ScenePictureOptions options;
    std::vector<SceneResult> results;
    for (Scene scene : parse_scene_text(imported.toml, path_text(file))) {
      scene.request.shapes = true;
      if (!imported.statics_solved && scene.problem.seabed) {
        options.seabed_z_m = scene.problem.seabed->z_m;
        options.caption =
            "drawn as solved WITHOUT its seabed: the statics with it was refused (see the notes)";
        scene.problem.seabed.reset();
      }
      results.push_back(run_scene(scene, run_options));
    }
    code = std::max(
        code, draw_results(results, std::filesystem::path(file).replace_extension(".svg").string(),
                           options, arguments.quiet, 0));
  }
  return code;
}

int run_import(const ImportArguments& arguments) {
  check_output_directory(arguments.out);
  const MoorDynDeck deck = read_moordyn_deck(arguments.deck);
  const std::vector<ImportedScene> scenes =
      convert_moordyn_deck(deck, std::filesystem::path(arguments.deck).stem().string());
  // Before the first file is written: no scene file may replace the deck (or any input).
  for (const auto& scene : scenes) {
    if (scene.reason.empty())
      check_not_an_input(std::filesystem::path(arguments.out) / scene.file_name, {arguments.deck},
                         "--out");
  }
  for (const auto& scene : scenes) {
    if (scene.reason.empty())
      write_file_atomically(std::filesystem::path(arguments.out) / scene.file_name, scene.toml);
  }
  if (!arguments.quiet && deck.lines.empty())
    fmt::print("{}: the deck has no lines\n", arguments.deck);
  if (!arguments.quiet) print_summary(deck, scenes, arguments.out);
  return arguments.plot ? plot_scenes(scenes, arguments) : 0;
}

}  // namespace

void add_import_command(CLI::App& app, std::function<int()>& run) {
  CLI::App* command =
      app.add_subcommand("import", "Convert another program's input into Catena scenes");
  command->require_subcommand(1);
  auto arguments = std::make_shared<ImportArguments>();
  CLI::App* moordyn = command->add_subcommand(
      "moordyn",
      "Convert a MoorDyn input file (v1 or v2) into one scene per line, or per chain of lines "
      "joined\n"
      "at free points (docs/how-to/moordyn-import.md). Each scene is the vertical plane through "
      "the line's\n"
      "two held ends (Fixed/Anchor and Vessel/Coupled points), end A the lower. Conversions:\n"
      "weight = (MassDen - rho_w pi/4 Diam^2) g [N/m], added_mass = Ca rho_w pi/4 Diam^2 [kg/m],\n"
      "point weight = (M - rho_w V) g [N], seabed z = -WtrDpth, stiffness = kBot Diam [N/m/m],\n"
      "damping = cBot Diam, friction 0, under every line when the deck has a depth (else the\n"
      "deepest point, MoorDyn-C's rule);\n"
      "diameter = Diam, drag_normal = Cd, drag_tangential = CdAx, added_mass_tangential =\n"
      "CaAx rho_w pi/4 Diam^2, axial_damping = BA [N s] (BA = -zeta < 0: zeta (UnstrLen/NumSegs)\n"
      "sqrt(EA MassDen), as MoorDyn computes it); [environment] water_density = rho_w, gravity = "
      "g;\n"
      "g = 9.80665 m/s^2 and rho_w = 1025 kg/m^3 unless the OPTIONS give g and rho/WtrDnsty.\n"
      "A single uniform line becomes a [cable] scene, chains and buoyant lines [line] scenes.\n"
      "Each scene's statics is solved with its seabed and reported (or the statics' refusal,\n"
      "and whether the line would pass below the water depth without it).\n"
      "Lines attached to bodies or rods, meeting three at a point, with a free end or that may "
      "fail\n"
      "are listed with the reason; the rest still convert. Prints a summary table, notes per line\n"
      "and what became of everything else in the deck (each option, EI, outputs, free points).\n"
      "Exit 0 when the deck was read (whatever could be converted), 2 for a deck that cannot be\n"
      "read (unknown section, missing column, non-numeric value: the line is named).");
  moordyn->add_option("deck", arguments->deck, "MoorDyn input file")
      ->required()
      ->check(non_empty_path());
  moordyn
      ->add_option("--out", arguments->out,
                   std::string("Directory for the scene files (created; a scene file that exists\n"
                               "is replaced).") +
                       kOutputPathHelp)
      ->required()
      ->check(non_empty_path());
  moordyn->add_flag("--quiet,-q", arguments->quiet, "Print nothing but errors");
  moordyn->add_flag(
      "--plot", arguments->plot,
      "Also solve each converted line (shapes asked) and draw it next to its scene\n"
      "file, as <scene>.svg: the profile with the seabed at the deck's depth and the\n"
      "water surface, the modes and the tension (docs/how-to/plot.md). A line whose\n"
      "statics with the seabed was refused is drawn as solved without it, under the\n"
      "seabed (a line hanging below the water depth is seen at once)");
  moordyn->callback([arguments, &run] { run = [arguments] { return run_import(*arguments); }; });
}

}  // namespace catena::cli
