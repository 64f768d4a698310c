// SPDX-License-Identifier: MIT
#pragma once
// The scene picture as panels (include/catena/io/scene_picture.hpp says what it shows), built from
// what picture_input.hpp read; rendered by svg_plot.hpp (SVG) or by python/catena/_plot.py
// (matplotlib) from picture_data.hpp's JSON.

#include "catena/io/scene_picture.hpp"
#include "io/plot/picture_input.hpp"
#include "io/report/svg_plot.hpp"

namespace catena::internal {

/// The picture's panels: "profile" (to scale, with the in-plane modes), "out-of-plane" (when
/// out-of-plane shapes are drawn) and "tension".
LinearFigure scene_figure(const PictureInput& in, const ScenePictureOptions& options);

}  // namespace catena::internal
