// SPDX-License-Identifier: MIT
// The fuzz targets of the readers of other programs' files (see input_fuzz_target.hpp).
#include "input_fuzz_target.hpp"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

#include "../io/report/report_test_support.hpp"
#include "catena/core/error.hpp"
#include "catena/io/external_results_reader.hpp"
#include "catena/io/external_tension_reader.hpp"
#include "catena/io/json_writer.hpp"
#include "catena/io/moordyn_deck.hpp"
#include "catena/io/moordyn_import.hpp"
#include "catena/io/report.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/io/tolerance_reader.hpp"
#include "catena/verification/scene_runner.hpp"
#include "catena/verification/tension_check.hpp"

namespace catena::fuzz {
namespace {

namespace fs = std::filesystem;

// Seeds of the report target: two small scenes solved, with forced responses and published values.
const char* const kReportScenes[] = {
    R"(name = "fuzz-report-cable"
tags = ["gale"]
[cable]
length = 10.0
weight = 1.0
EA = 1e6
mass = 1.0
a = [0.0, 0.0]
b = [8.0, 1.0]
[request]
inplane_modes = 3
outofplane_modes = 2
[request.forced]
end = "b"
direction = "tangential"
amplitude = 0.01
frequencies = [0.5, 2.0]
[[published]]
source = "made up for the fuzz corpus"
quantity = "inplane_frequency"
unit = "rad/s"
modes = [1, 2]
values = [3.0, 6.0]
solvers = ["fe"]
decimals = 3
)",
    R"(name = "fuzz-report-taut"
[cable]
length = 20.0
weight = 0.5
EA = 1e5
mass = 0.1
a = [0.0, 0.0]
b = [19.9, 0.0]
[request]
inplane_modes = 2
outofplane_modes = 2
)"};

std::string file_text(const fs::path& path) {
  std::ostringstream text;
  text << std::ifstream(path, std::ios::binary).rdbuf();
  return text.str();
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

// The scene the check corpus was written for (a sagging cable, cheap to solve, 8 modes per plane
// with shapes and tension): its references are computed once per run.
const char* const kCheckSceneFile = "scene.toml";

// Wall times, as values and in messages ("[0.00441 ms]", "statics 958.2 us"), set to one value.
void fix_wall_times(nlohmann::json& value) {
  static const std::regex kTime(R"([0-9][0-9.]*(e[+-]?[0-9]+)? (us|ms|s)\b)");
  if (value.is_string()) {
    value = std::regex_replace(value.get<std::string>(), kTime, "1 ms");
  } else if (value.is_object()) {
    for (auto& [key, item] : value.items()) {
      if (key == "wall_time_s") item = 0.001;
      fix_wall_times(item);
    }
  } else if (value.is_array()) {
    for (auto& item : value) fix_wall_times(item);
  }
}

bool fuzz_moordyn(const std::string& text, std::vector<std::string>& violations) {
  const MoorDynDeck deck = parse_moordyn_deck_text(text, "fuzz.txt");
  for (const ImportedScene& scene : convert_moordyn_deck(deck, "fuzz")) {
    if (scene.toml.empty()) continue;
    try {
      parse_scene_text(scene.toml, scene.file_name);
    } catch (const Error& error) {
      violations.push_back("the importer wrote " + scene.file_name +
                           ", which the scene reader refuses: " + error.what());
    }
  }
  return true;
}

bool fuzz_check(const InputFuzzContext& context, const SeedScene& seed, const std::string& text) {
  if (seed.file.extension() == ".json") {
    const auto results = parse_external_results_json(text, "fuzz.json");
    validate_external_results(results);
    check_external_results(results, context.references);
    return true;
  }
  const fs::path csv = context.work_dir / "results.csv";
  write_text(csv, text);
  if (is_tension_results_file(csv)) {
    validate_external_tension(read_external_tension(csv), 100.0);
    return true;
  }
  const auto results = read_external_results(csv);
  validate_external_results(results);
  check_external_results(results, context.references);
  return true;
}

bool fuzz_report(const InputFuzzContext& context, const std::string& text) {
  const fs::path json = context.work_dir / "report.json";
  write_text(json, text);
  ReportOptions options;
  options.out_dir = context.work_dir / "report";
  options.data_dir = context.work_dir / "no-data";  // no benchmark table to read
  options.figures = false;
  write_report(json, options);
  return true;
}

}  // namespace

bool parse_input_target(const std::string& name, InputTarget& target) {
  if (name == "moordyn")
    target = InputTarget::MoorDyn;
  else if (name == "check")
    target = InputTarget::Check;
  else if (name == "report")
    target = InputTarget::Report;
  else
    return false;
  return true;
}

InputFuzzContext make_context(InputTarget target,
                              const fs::path& corpus,
                              const fs::path& work_dir) {
  InputFuzzContext context;
  context.target = target;
  context.work_dir = work_dir;
  fs::create_directories(work_dir / "no-data");
  if (target != InputTarget::Check) return context;
  SceneRunOptions run;
  run.checks = false;
  const SceneResult solved = run_scene(read_scene_file(corpus / kCheckSceneFile).front(), run);
  for (const Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    std::string why;
    auto reference = certified_reference(solved.outputs, plane, why);
    if (!reference) throw std::runtime_error("fuzz check scene has no reference: " + why);
    context.references.push_back(std::move(*reference));
  }
  return context;
}

std::vector<SeedScene> input_seed_corpus(InputTarget target, const fs::path& directory) {
  std::vector<SeedScene> corpus;
  if (target == InputTarget::Report) {
    SceneRunOptions run;
    run.tolerances = builtin_tolerance_table();
    std::vector<SceneResult> results;
    for (const char* text : kReportScenes)
      results.push_back(run_scene(parse_scene_text(text, "fuzz-report.toml").front(), run));
    // The same seed on every machine and run: the build's identity and the wall times replaced.
    nlohmann::json written = nlohmann::json::parse(results_to_json(results));
    written["catena"] = {{"version", "0"},
                         {"git", "fuzz"},
                         {"compiler", "-"},
                         {"build_type", "-"},
                         {"generated_utc", "2026-01-01T00:00:00Z"}};
    fix_wall_times(written);
    corpus.push_back({"catena-written.json", written.dump(1)});
    corpus.push_back({"synthetic.json", catena::testing::synthetic_results().dump(1)});
    return corpus;
  }
  const std::vector<std::string> extensions = target == InputTarget::MoorDyn
                                                  ? std::vector<std::string>{".txt"}
                                                  : std::vector<std::string>{".csv", ".json"};
  for (const auto& entry : fs::directory_iterator(directory)) {
    const std::string extension = entry.path().extension().string();
    if (entry.is_regular_file() &&
        std::find(extensions.begin(), extensions.end(), extension) != extensions.end())
      corpus.push_back({entry.path(), file_text(entry.path())});
  }
  std::sort(corpus.begin(), corpus.end(),
            [](const SeedScene& x, const SeedScene& y) { return x.file < y.file; });
  return corpus;
}

bool fuzz_input(const InputFuzzContext& context,
                const SeedScene& seed,
                const std::string& text,
                std::vector<std::string>& violations) {
  try {
    switch (context.target) {
      case InputTarget::MoorDyn:
        return fuzz_moordyn(text, violations);
      case InputTarget::Check:
        return fuzz_check(context, seed, text);
      case InputTarget::Report:
        return fuzz_report(context, text);
    }
  } catch (const Error&) {
    return false;  // bad input, named: what the readers must do
  } catch (const fs::filesystem_error&) {
    return false;  // the environment (the CLI reports it as such, exit 2)
  }
  return false;
}

}  // namespace catena::fuzz
