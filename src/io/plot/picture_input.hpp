// SPDX-License-Identifier: MIT
#pragma once
// What the scene picture reads from one scene of a results JSON (docs/reference/json-layout.md),
// as plain data. Each read names the JSON path it expected (scenes[0].statics.shape.x_m), since the
// document may come from anywhere (`catena plot FILE`); nlohmann's const operator[] on a missing
// key is undefined behaviour, so every key is looked up with a check.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace catena::internal {

/// The static profile on the request's stations: unstretched arc length, position, tension.
struct PictureProfile {
  std::vector<double> s_m, x_m, z_m, tension_n;
};

/// A point attachment (clump weight, buoy) at arc length s, placed by the statics.
struct PicturePoint {
  double s_m = 0.0;
  double x_m = 0.0;
  double z_m = 0.0;
  double mass_kg = 0.0;
  double weight_n = 0.0;  ///< submerged; < 0 lifts (a buoy)
};

/// A segment: its unstretched extent along the line and its properties for the legend.
struct PictureSegment {
  double s_begin_m = 0.0;
  double s_end_m = 0.0;
  double weight_n_per_m = 0.0;
};

/// One mode's shape (real parts for a damped mode) with its frequency.
struct PictureMode {
  int index = 0;
  double frequency_hz = 0.0;
  std::vector<double> s_m, u, w, v;  ///< u, w in plane; v out of plane
};

/// One solver's modes of one plane, with whether they can be trusted (converged or
/// no-convergence with modes) and whether they carry shapes.
struct PicturePlane {
  std::string solver;
  std::string termination;
  std::vector<PictureMode> modes;
};

struct PictureInput {
  std::string name;
  std::vector<std::string> tags;
  std::vector<double> a_m, b_m;  ///< supports (x, z)
  PictureProfile profile;
  std::vector<PictureSegment> segments;
  std::vector<PicturePoint> points;
  /// Joints between segments, placed by the statics (x, z).
  std::vector<std::pair<double, double>> joints_xz;
  std::vector<double> joints_s_m;
  std::optional<double> seabed_z_m;
  bool contact = false;
  /// Where the line meets the seabed (ends of the grounded stretches away from the supports).
  std::vector<std::pair<double, double>> touchdowns_sx;
  double horizontal_force_n = 0.0;
  double tension_a_n = 0.0;
  double tension_b_n = 0.0;
  double grounded_length_m = 0.0;
  /// Every solver's planes, in the document's order: "inplane" and "outofplane".
  std::vector<PicturePlane> inplane;
  std::vector<PicturePlane> outofplane;
};

/// The scene `record` (at `where`, e.g. "FILE: scenes[2]") read. InvalidInput when it has no
/// statics (quoting its error) or no static profile (the results were written without shapes);
/// ParseError for a key missing or of the wrong type, naming its path.
PictureInput read_picture_input(const nlohmann::json& record, const std::string& where);

}  // namespace catena::internal
