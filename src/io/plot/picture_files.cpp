// SPDX-License-Identifier: MIT
// The scene picture's entry points (include/catena/io/scene_picture.hpp): the results document
// read, each scene's figure rendered as SVG here or as PNG by plot.py (matplotlib) in the data dir.
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "catena/io/scene_picture.hpp"
#include "io/internal/data_dir.hpp"
#include "io/internal/json_strict.hpp"
#include "io/internal/json_text.hpp"
#include "io/internal/process.hpp"
#include "io/internal/results_keys.hpp"
#include "io/plot/picture_data.hpp"
#include "io/plot/scene_picture.hpp"

namespace catena {
namespace {

using nlohmann::json;

// A results document is about 8 levels deep (json-layout.md); deeper is not one.
constexpr int kMaxDepth = 64;
// Exit status of plot.py when matplotlib cannot be imported (its --check-matplotlib).
constexpr int kNoMatplotlib = 4;

json read_document(const std::string& text, const std::string& origin) {
  json document = internal::parse_json_strict(text, origin, kMaxDepth);
  if (!document.is_object() || !document.contains(internal::key::scenes) ||
      !document.at(internal::key::scenes).is_array()) {
    throw ParseError(fmt::format(
        "{}: not a catena results JSON (no \"scenes\" list; write one with `catena solve SCENE "
        "--json FILE`)",
        origin));
  }
  return document;
}

std::string scene_name(const json& record) {
  return record.is_object() && record.contains(internal::key::name) &&
                 record.at(internal::key::name).is_string()
             ? record.at(internal::key::name).get<std::string>()
             : std::string();
}

// The records to draw with their JSON paths: the one named, else every one.
std::vector<std::pair<const json*, std::string>> selected_scenes(const json& document,
                                                                 const std::string& origin,
                                                                 const std::string& name) {
  std::vector<std::pair<const json*, std::string>> out;
  std::string names;
  const json& scenes = document.at(internal::key::scenes);
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const std::string scene = scene_name(scenes[i]);
    names += (names.empty() ? "" : ", ") + scene;
    if (name.empty() || scene == name)
      out.emplace_back(&scenes[i], fmt::format("{}: scenes[{}]", origin, i));
  }
  if (out.empty()) {
    throw InvalidInput(name.empty() ? fmt::format("{}: the results hold no scene", origin)
                                    : fmt::format("--scene {}: no such scene in {} (it has: {})",
                                                  name, origin, names));
  }
  return out;
}

internal::LinearFigure figure_of(const std::string& text,
                                 const std::string& origin,
                                 const std::string& scene,
                                 const ScenePictureOptions& options) {
  options.validate();
  const json document = read_document(text, origin);
  const auto records = selected_scenes(document, origin, scene);
  if (records.size() > 1) {
    throw InvalidInput(fmt::format("{}: {} scenes; name the one to draw", origin, records.size()));
  }
  return internal::scene_figure(internal::read_picture_input(*records[0].first, records[0].second),
                                options);
}

std::filesystem::path plot_script(const ScenePictureOptions& options) {
  const std::filesystem::path dir = options.data_dir.empty()
                                        ? internal::data_dir().value_or(std::filesystem::path())
                                        : options.data_dir;
  return dir.empty() ? std::filesystem::path() : dir / "plot.py";
}

// plot.py draws the figure's data into a PNG in the temporary directory; its bytes are then
// written to `out` like any other output (whole or not at all).
void write_png(const internal::LinearFigure& figure,
               const std::filesystem::path& out,
               const ScenePictureOptions& options) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    fmt::format("catena-plot-{}", static_cast<long>(::getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path data = dir / "picture.json", png = dir / "picture.png",
                              log = dir / "plot.log";
  write_file_atomically(data, internal::json_text(internal::figure_json(figure)));
  const int status = internal::run_process({options.python, plot_script(options).string(), "--data",
                                            data.string(), "--out", png.string()},
                                           log);
  std::ifstream log_file(log), image(png, std::ios::binary);
  std::stringstream message, bytes;
  message << log_file.rdbuf();
  if (status == 0 && image) bytes << image.rdbuf();
  std::filesystem::remove_all(dir);
  if (status != 0 || bytes.str().empty()) {
    throw InvalidInput(fmt::format("{}: the PNG was not drawn ('{}' {} exited with status {}): {}",
                                   path_text(out), options.python, plot_script(options).string(),
                                   status, message.str()));
  }
  write_file_atomically(out, bytes.str());
}

bool is_png(const std::filesystem::path& out) { return out.extension() == ".png"; }

}  // namespace

void ScenePictureOptions::validate() const {
  for (int mode : modes) {
    if (mode < 1)
      throw InvalidInput(fmt::format("Invalid ScenePictureOptions::modes: {}: must be >= 1", mode));
  }
  if (!(mode_scale > 0.0 && mode_scale <= 1.0))
    throw InvalidInput(
        fmt::format("Invalid ScenePictureOptions::mode_scale = {}: must be in (0, 1]", mode_scale));
}

std::string scene_picture_svg(const std::string& results_json_text,
                              const std::string& origin,
                              const std::string& scene,
                              const ScenePictureOptions& options) {
  return internal::render_svg(figure_of(results_json_text, origin, scene, options));
}

std::string scene_picture_data(const std::string& results_json_text,
                               const std::string& origin,
                               const std::string& scene,
                               const ScenePictureOptions& options) {
  return internal::json_text(
      internal::figure_json(figure_of(results_json_text, origin, scene, options)));
}

std::filesystem::path scene_picture_path(const std::filesystem::path& out,
                                         const std::string& scene_name,
                                         std::size_t count) {
  if (count <= 1) return out;
  std::filesystem::path path = out;
  path.replace_filename(out.stem().string() + "-" + scene_name + out.extension().string());
  return path;
}

void check_scene_picture_output(const std::filesystem::path& out,
                                const std::string& option,
                                const ScenePictureOptions& options) {
  options.validate();
  // A character device or FIFO (/dev/stdout, a pipe) has no extension to go by: SVG goes through.
  std::error_code error;
  const auto type = std::filesystem::status(out, error).type();
  const bool stream =
      type == std::filesystem::file_type::character || type == std::filesystem::file_type::fifo;
  if (out.extension() != ".svg" && !is_png(out) && !stream) {
    throw InvalidInput(
        fmt::format("{} {}: the picture is written as .svg (native) or .png "
                    "(matplotlib): name the file so",
                    option, path_text(out)));
  }
  check_output_file(out);
  if (!is_png(out)) return;
  const std::filesystem::path script = plot_script(options);
  if (script.empty() || !std::filesystem::exists(script)) {
    throw InvalidInput(
        fmt::format("{} {}: a PNG needs plot.py from the data dir (share/catena), "
                    "not found{}; write an .svg instead",
                    option, path_text(out), script.empty() ? "" : ": " + script.string()));
  }
  const int status =
      internal::run_process({options.python, script.string(), "--check-matplotlib"}, "/dev/null");
  if (status != 0) {
    throw InvalidInput(fmt::format(
        "{} {}: a PNG needs Python with matplotlib, and '{}' {} (install python3-matplotlib, or "
        "write an .svg, which needs no Python)",
        option, path_text(out), options.python,
        status == kNoMatplotlib ? "cannot import matplotlib"
        : status == 127         ? "cannot be run"
                                : fmt::format("failed (status {})", status)));
  }
}

std::vector<ScenePictureFile> write_scene_pictures(const std::string& results_json_text,
                                                   const std::string& origin,
                                                   const std::filesystem::path& out,
                                                   const ScenePictureOptions& options) {
  options.validate();
  const json document = read_document(results_json_text, origin);
  const auto records = selected_scenes(document, origin, options.scene);
  std::vector<ScenePictureFile> files;
  std::string reasons;
  for (const auto& [record, where] : records) {
    ScenePictureFile file{scene_name(*record), {}, {}};
    try {
      const internal::LinearFigure figure =
          internal::scene_figure(internal::read_picture_input(*record, where), options);
      file.path = scene_picture_path(out, file.scene, records.size());
      if (is_png(out)) {
        write_png(figure, file.path, options);
      } else {
        write_file_atomically(file.path, internal::render_svg(figure));
      }
    } catch (const InvalidInput& error) {
      if (records.size() == 1 || !file.path.empty()) throw;  // one scene, or a file not written
      file.note = error.what();
      reasons += "\n  " + file.note;
    }
    files.push_back(std::move(file));
  }
  if (std::none_of(files.begin(), files.end(), [](const auto& f) { return !f.path.empty(); }))
    throw InvalidInput(fmt::format("{}: no scene could be drawn:{}", origin, reasons));
  return files;
}

}  // namespace catena
