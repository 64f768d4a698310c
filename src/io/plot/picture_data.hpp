// SPDX-License-Identifier: MIT
#pragma once
// A LinearFigure as JSON, for the matplotlib drawing (python/catena/_plot.py): the layout is
// scene_picture_data()'s in include/catena/io/scene_picture.hpp.

#include <nlohmann/json.hpp>

#include "io/report/svg_plot.hpp"

namespace catena::internal {

/// Non-finite coordinates become null (JSON has no NaN; the drawing breaks the line there).
nlohmann::json figure_json(const LinearFigure& figure);

}  // namespace catena::internal
