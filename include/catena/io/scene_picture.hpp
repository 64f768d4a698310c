// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// A picture of a solved scene (`catena plot`, `catena solve --plot`, `catena import moordyn
/// --plot`, Python's `Result.plot()`; docs/how-to/plot.md), drawn from a results JSON
/// (docs/reference/json-layout.md):
///
/// - the static profile to scale (equal axes, x and z [m]), one path per segment; the ends a and
///   b, the point masses (clump weights, buoys), the seabed at its z and the touchdown points, and
///   the water surface when the scene's z is measured from it (an imported MoorDyn line);
/// - the requested modes of the reference solver (the most accurate exact solver whose shapes the
///   results hold; the title names it): in-plane modes as the displaced profile, out-of-plane
///   modes as v(s) in a second panel;
/// - the static tension T(s) [kN] along the line.
///
/// The profile and the shapes are in the results only when the scene asked for shapes
/// (`[request].shapes = true`); without them the picture is refused with InvalidInput saying so.
/// SVG is written by the library itself; PNG through python/catena/_plot.py (matplotlib), run
/// without a shell from the data dir (share/catena).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace catena {

struct ScenePictureOptions {
  /// Mode numbers (1-based) drawn in each plane, when the results hold them; empty: none.
  std::vector<int> modes = {1, 2, 3};
  /// Draw every mode the results hold (modes is then ignored).
  bool all_modes = false;
  /// The largest displacement of a drawn in-plane mode, as a fraction of the profile's extent
  /// (the larger of its width and height). In (0, 1].
  double mode_scale = 0.08;
  /// A seabed drawn when the results hold none: the importer draws a line whose statics with its
  /// seabed was refused as solved without it, with the seabed it should rest on, so that a line
  /// hanging below the water depth is seen. Empty: only the results' own seabed.
  std::optional<double> seabed_z_m;
  /// A line added under the picture's title (e.g. why the line was solved without its seabed).
  std::string caption;
  /// The scene to draw, by name (empty: every scene of the document that has statics).
  std::string scene;
  /// Python interpreter for PNG output (searched on PATH when it has no '/').
  std::string python = "python3";
  /// Directory of plot.py (the matplotlib drawing); empty: the data dir found from the executable.
  std::filesystem::path data_dir;

  /// InvalidInput naming the field: a mode number < 1, a mode_scale outside (0, 1].
  void validate() const;
};

/// One scene's picture as a standalone SVG document. `results_json_text` is a document written by
/// write_results_json (`origin` names it in messages); `scene` picks the scene by name (empty: the
/// only one). ParseError when the text is not a results document; InvalidInput when the scene is
/// missing, has no statics (its error is quoted) or no static profile (no shapes asked).
std::string scene_picture_svg(const std::string& results_json_text,
                              const std::string& origin,
                              const std::string& scene,
                              const ScenePictureOptions& options);

/// The same picture as data for matplotlib (JSON text): {"title": [lines], "notes": [lines],
/// "panels": [{"id" ("profile", "out-of-plane", "tension"), "title", "x_label", "y_label",
/// "equal_axes", "series": [{"label", "x", "y", "colour", "dash", "width", "role",
/// "in_legend"}], "markers": [{"label", "x", "y", "shape", "colour", "role"}], "levels":
/// [{"label", "y", "colour", "dash", "role"}]}]}. Same arguments and errors as scene_picture_svg.
std::string scene_picture_data(const std::string& results_json_text,
                               const std::string& origin,
                               const std::string& scene,
                               const ScenePictureOptions& options);

/// What write_scene_pictures did for one scene.
struct ScenePictureFile {
  std::string scene;
  std::filesystem::path path;  ///< empty when not drawn
  std::string note;            ///< why not drawn (no statics, no profile); empty when drawn
};

/// The file of scene `scene_name` when `count` scenes are drawn to `out`: `out` itself for one
/// scene, else `<out stem>-<scene name><out extension>` next to it.
std::filesystem::path scene_picture_path(const std::filesystem::path& out,
                                         const std::string& scene_name,
                                         std::size_t count);

/// InvalidInput naming `option` unless `out` ends in .svg or .png and can be written (and, for
/// .png, plot.py is found and the interpreter imports matplotlib). Called before any work.
void check_scene_picture_output(const std::filesystem::path& out,
                                const std::string& option,
                                const ScenePictureOptions& options);

/// Draws every scene of the results document (or options.scene) to scene_picture_path(out, ...),
/// each file written whole or not at all. A scene without statics or profile is listed with the
/// reason; InvalidInput when options.scene names no scene or when no scene could be drawn.
std::vector<ScenePictureFile> write_scene_pictures(const std::string& results_json_text,
                                                   const std::string& origin,
                                                   const std::filesystem::path& out,
                                                   const ScenePictureOptions& options);

}  // namespace catena
