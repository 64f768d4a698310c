// SPDX-License-Identifier: MIT
#include "io/plot/scene_picture.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "catena/solvers/solver_registry.hpp"

namespace catena::internal {
namespace {

constexpr const char* kSegmentColours[] = {"#1f4e79", "#c55a11", "#548235",
                                           "#7030a0", "#bf9000", "#2e75b6"};
constexpr const char* kModeColours[] = {"#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                        "#17becf", "#e377c2", "#8c564b", "#bcbd22"};
constexpr const char* kModeDash = "7,4";

const char* segment_colour(std::size_t k) {
  return kSegmentColours[k % std::size(kSegmentColours)];
}
const char* mode_colour(std::size_t k) { return kModeColours[k % std::size(kModeColours)]; }

// Position and unit tangent of the profile at arc length s: linear between the stations, the
// tangent of the chord between the two stations around s (a picture's accuracy; at a kink, a
// point weight, it is the chord's direction on the side of b).
struct Place {
  double x, z, tx, tz;
};
Place place_at(const PictureProfile& p, double s) {
  const auto it = std::upper_bound(p.s_m.begin(), p.s_m.end(), s);
  std::size_t i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - p.s_m.begin(), 1)) - 1;
  i = std::min(i, p.s_m.size() - 2);
  const double ds = p.s_m[i + 1] - p.s_m[i];
  const double t = ds > 0.0 ? (s - p.s_m[i]) / ds : 0.0;
  const double dx = p.x_m[i + 1] - p.x_m[i], dz = p.z_m[i + 1] - p.z_m[i];
  const double length = std::hypot(dx, dz);
  return {p.x_m[i] + t * dx, p.z_m[i] + t * dz, length > 0.0 ? dx / length : 1.0,
          length > 0.0 ? dz / length : 0.0};
}

// The larger of the profile's width and height [m]: the scale of the mode drawings.
double profile_extent(const PictureProfile& p) {
  const auto [x0, x1] = std::minmax_element(p.x_m.begin(), p.x_m.end());
  const auto [z0, z1] = std::minmax_element(p.z_m.begin(), p.z_m.end());
  const double extent = std::max(*x1 - *x0, *z1 - *z0);
  return std::isfinite(extent) && extent > 0.0 ? extent : 1.0;
}

// The stations of segment k, with its ends placed exactly (a joint from the statics' nodes).
void segment_path(const PictureInput& in,
                  std::size_t k,
                  std::vector<double>& x,
                  std::vector<double>& z,
                  std::vector<double>& s) {
  const PictureSegment& seg = in.segments[k];
  const auto end_point = [&](double at) {
    for (std::size_t j = 0; j < in.joints_s_m.size(); ++j) {
      if (in.joints_s_m[j] == at)
        return std::make_pair(in.joints_xz[j].first, in.joints_xz[j].second);
    }
    const Place p = place_at(in.profile, at);
    return std::make_pair(p.x, p.z);
  };
  const auto push = [&](double si, std::pair<double, double> r) {
    s.push_back(si), x.push_back(r.first), z.push_back(r.second);
  };
  push(seg.s_begin_m, end_point(seg.s_begin_m));
  const PictureProfile& p = in.profile;
  for (std::size_t i = 0; i < p.s_m.size(); ++i) {
    if (p.s_m[i] > seg.s_begin_m && p.s_m[i] < seg.s_end_m) push(p.s_m[i], {p.x_m[i], p.z_m[i]});
  }
  push(seg.s_end_m, end_point(seg.s_end_m));
}

// Tension at the segment's stations, interpolated at its ends.
std::vector<double> tension_on(const PictureProfile& p, const std::vector<double>& s) {
  std::vector<double> out;
  for (double si : s) {
    const auto it = std::upper_bound(p.s_m.begin(), p.s_m.end(), si);
    std::size_t i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - p.s_m.begin(), 1)) - 1;
    i = std::min(i, p.s_m.size() - 2);
    const double ds = p.s_m[i + 1] - p.s_m[i];
    const double t = ds > 0.0 ? (si - p.s_m[i]) / ds : 0.0;
    out.push_back(1e-3 * (p.tension_n[i] + t * (p.tension_n[i + 1] - p.tension_n[i])));
  }
  return out;
}

void add_segments(const PictureInput& in, LinearPanel& profile, LinearPanel& tension) {
  for (std::size_t k = 0; k < in.segments.size(); ++k) {
    LinearPanel::Series path;
    std::vector<double> s;
    segment_path(in, k, path.x, path.y, s);
    const PictureSegment& seg = in.segments[k];
    path.label = in.segments.size() == 1
                     ? fmt::format("line, {:g} m", seg.s_end_m)
                     : fmt::format("segment {}: {:g} m, {:.4g} N/m", k + 1,
                                   seg.s_end_m - seg.s_begin_m, seg.weight_n_per_m);
    path.colour = segment_colour(k);
    path.width = 2.5;
    path.role = "segment";
    tension.series.push_back(
        {path.label, s, tension_on(in.profile, s), path.colour, "", 2.0, "tension", false});
    profile.series.push_back(std::move(path));
  }
}

void add_markers(const PictureInput& in, LinearPanel& profile) {
  profile.markers.push_back({fmt::format("end a ({:.6g}, {:.6g}) m", in.a_m[0], in.a_m[1]),
                             in.a_m[0], in.a_m[1], "square", "#222", "end"});
  profile.markers.push_back({fmt::format("end b ({:.6g}, {:.6g}) m", in.b_m[0], in.b_m[1]),
                             in.b_m[0], in.b_m[1], "diamond", "#222", "end"});
  for (std::size_t i = 0; i < in.points.size(); ++i) {
    const PicturePoint& p = in.points[i];
    if (p.weight_n > 0.0) {
      profile.markers.push_back(
          {fmt::format("point {}: clump, {:.4g} kN", i + 1, 1e-3 * p.weight_n), p.x_m, p.z_m,
           "triangle-down", "#555", "point"});
    } else if (p.weight_n < 0.0) {
      profile.markers.push_back(
          {fmt::format("point {}: buoy, lifts {:.4g} kN", i + 1, -1e-3 * p.weight_n), p.x_m, p.z_m,
           "triangle-up", "#f2c200", "point"});
    } else {
      profile.markers.push_back({fmt::format("point {}: mass {:.4g} t", i + 1, 1e-3 * p.mass_kg),
                                 p.x_m, p.z_m, "circle", "#999", "point"});
    }
  }
  for (const auto& [s, x] : in.touchdowns_sx) {
    profile.markers.push_back({fmt::format("touchdown at s = {:.5g} m", s), x,
                               in.seabed_z_m.value_or(0.0), "circle", "#ff7f0e", "touchdown"});
  }
}

bool has_tag(const PictureInput& in, const std::string& tag) {
  return std::find(in.tags.begin(), in.tags.end(), tag) != in.tags.end();
}

// The seabed and, for a scene whose z is measured from the still water level (an imported
// MoorDyn line: z = MoorDyn's z), the surface and the water depth.
void add_water(const PictureInput& in, LinearPanel& profile, std::vector<std::string>& notes) {
  const bool from_surface = has_tag(in, "moordyn-import");
  if (from_surface) {
    profile.levels.push_back({"water surface, z = 0", 0.0, "#3a7fc1", "3,3", "surface"});
  }
  if (!in.seabed_z_m) return;
  const double bed = *in.seabed_z_m;
  profile.levels.push_back({from_surface ? fmt::format("seabed, depth {:g} m", -bed)
                                         : fmt::format("seabed, z = {:g} m", bed),
                            bed, "#8b5a2b", "", "seabed"});
  const double lowest = *std::min_element(in.profile.z_m.begin(), in.profile.z_m.end());
  if (lowest < bed - 1e-6 * profile_extent(in.profile)) {
    notes.push_back(fmt::format("WARNING: the line passes {:.4g} m below the seabed (z = {:g} m)",
                                bed - lowest, bed));
  }
}

// The plane's modes of the most accurate exact solver that gave shapes, else of any solver that
// did (a model), with why it was chosen.
const PicturePlane* pick_plane(const std::vector<PicturePlane>& planes, std::string& why) {
  const auto usable = [](const PicturePlane& p) {
    return (p.termination == "converged" || p.termination == "no-convergence") && !p.modes.empty();
  };
  for (const std::string& name : exact_solvers_by_accuracy()) {
    for (const PicturePlane& p : planes) {
      if (p.solver == name && usable(p)) {
        why = "the most accurate exact solver with shapes";
        return &p;
      }
    }
  }
  for (const PicturePlane& p : planes) {
    if (usable(p)) {
      why = "an approximate model: no exact solver gave shapes";
      return &p;
    }
  }
  return nullptr;
}

// The chosen modes: those asked that the plane holds; the others named in a note.
std::vector<const PictureMode*> chosen_modes(const PicturePlane& plane,
                                             const ScenePictureOptions& options,
                                             const char* what,
                                             std::vector<std::string>& notes) {
  std::vector<const PictureMode*> out;
  if (options.all_modes) {
    for (const PictureMode& m : plane.modes) out.push_back(&m);
    return out;
  }
  for (int index : options.modes) {
    const auto it = std::find_if(plane.modes.begin(), plane.modes.end(),
                                 [&](const PictureMode& m) { return m.index == index; });
    if (it != plane.modes.end()) {
      out.push_back(&*it);
    } else {
      notes.push_back(fmt::format("{} mode {}: not in {}'s results (it has {} with shapes)", what,
                                  index, plane.solver, plane.modes.size()));
    }
  }
  return out;
}

// In-plane modes on the profile: r(s) + A (u t + w n), n the tangent turned +90 degrees.
double add_inplane_modes(const PictureInput& in,
                         const std::vector<const PictureMode*>& modes,
                         double scale,
                         LinearPanel& profile) {
  const double extent = profile_extent(in.profile);
  double largest = 0.0;
  for (std::size_t k = 0; k < modes.size(); ++k) {
    const PictureMode& m = *modes[k];
    double peak = 0.0;
    for (std::size_t j = 0; j < m.s_m.size(); ++j)
      peak = std::max(peak, std::hypot(m.u[j], m.w[j]));
    const double amplitude = peak > 0.0 ? scale * extent / peak : 0.0;
    largest = std::max(largest, amplitude * peak);
    LinearPanel::Series path{fmt::format("in-plane {}: {:.5g} Hz", m.index, m.frequency_hz),
                             {},
                             {},
                             mode_colour(k),
                             kModeDash,
                             1.6,
                             "mode",
                             true};
    for (std::size_t j = 0; j < m.s_m.size(); ++j) {
      const Place p = place_at(in.profile, m.s_m[j]);
      path.x.push_back(p.x + amplitude * (m.u[j] * p.tx - m.w[j] * p.tz));
      path.y.push_back(p.z + amplitude * (m.u[j] * p.tz + m.w[j] * p.tx));
    }
    profile.series.push_back(std::move(path));
  }
  return largest;
}

LinearPanel outofplane_panel(const std::vector<const PictureMode*>& modes, const std::string& by) {
  LinearPanel panel{"out-of-plane",
                    "Out-of-plane modes (" + by + "), normalised to max |v| = 1",
                    "s, unstretched arc length from end a [m]",
                    "v [-]",
                    false,
                    200.0,
                    {},
                    {},
                    {}};
  for (std::size_t k = 0; k < modes.size(); ++k) {
    const PictureMode& m = *modes[k];
    panel.series.push_back({fmt::format("out-of-plane {}: {:.5g} Hz", m.index, m.frequency_hz),
                            m.s_m, m.v, mode_colour(k), kModeDash, 1.6, "mode", true});
  }
  return panel;
}

// A force in kN, or in N below 1 kN (a dimensionless scene's forces are of order 1 N).
std::string force_text(double force_n) {
  return std::abs(force_n) >= 1e3 ? fmt::format("{:.5g} kN", 1e-3 * force_n)
                                  : fmt::format("{:.5g} N", force_n);
}

std::vector<std::string> title_lines(const PictureInput& in) {
  std::vector<std::string> title{
      fmt::format("scene {}: static profile, mode shapes, tension", in.name)};
  std::string statics =
      fmt::format("H = {}, T at a = {}, T at b = {}", force_text(in.horizontal_force_n),
                  force_text(in.tension_a_n), force_text(in.tension_b_n));
  if (in.seabed_z_m) {
    statics += in.contact ? fmt::format("; {:.5g} m on the seabed", in.grounded_length_m)
                          : std::string("; off the seabed");
  }
  title.push_back(statics);
  return title;
}

}  // namespace

LinearFigure scene_figure(const PictureInput& input, const ScenePictureOptions& options) {
  PictureInput in_with_seabed;
  const bool add_seabed = !input.seabed_z_m && options.seabed_z_m;
  if (add_seabed) {
    in_with_seabed = input;
    in_with_seabed.seabed_z_m = options.seabed_z_m;
  }
  const PictureInput& in = add_seabed ? in_with_seabed : input;
  LinearFigure figure;
  figure.title = title_lines(input);
  if (!options.caption.empty()) figure.title.push_back(options.caption);
  LinearPanel profile{"profile",
                      "Static profile to scale (the line's vertical plane)",
                      "x, horizontal from end a [m]",
                      "z [m]",
                      true,
                      340.0,
                      {},
                      {},
                      {}};
  LinearPanel tension{"tension",
                      "Static tension along the line",
                      "s, unstretched arc length from end a [m]",
                      "T [kN]",
                      false,
                      180.0,
                      {},
                      {},
                      {}};
  add_water(in, profile, figure.notes);
  add_segments(in, profile, tension);
  add_markers(in, profile);
  std::string modes_line;
  std::string why;
  if (const PicturePlane* plane = pick_plane(in.inplane, why);
      plane && (options.all_modes || !options.modes.empty())) {
    const auto modes = chosen_modes(*plane, options, "in-plane", figure.notes);
    const double largest = add_inplane_modes(in, modes, options.mode_scale, profile);
    modes_line = fmt::format("in-plane modes: {} ({})", plane->solver, why);
    if (!modes.empty()) profile.title += fmt::format("; in-plane modes ({})", plane->solver);
    if (!modes.empty()) {
      figure.notes.push_back(fmt::format(
          "In-plane modes drawn as the displaced profile, largest displacement {:.3g} m ({:g} % of "
          "the profile's extent); a damped mode: its real part.",
          largest, 100.0 * options.mode_scale));
    }
  }
  LinearPanel outofplane;
  bool has_outofplane = false;
  if (const PicturePlane* plane = pick_plane(in.outofplane, why);
      plane && (options.all_modes || !options.modes.empty())) {
    const auto modes = chosen_modes(*plane, options, "out-of-plane", figure.notes);
    outofplane = outofplane_panel(modes, plane->solver);
    has_outofplane = !modes.empty();
    modes_line += fmt::format("{}out-of-plane modes: {} ({})", modes_line.empty() ? "" : "; ",
                              plane->solver, why);
  }
  if (modes_line.empty()) {
    modes_line = options.modes.empty() && !options.all_modes
                     ? "no modes asked"
                     : "no mode shapes in the results (no solver gave any)";
  }
  figure.title.push_back(modes_line);
  figure.panels.push_back(std::move(profile));
  if (has_outofplane) figure.panels.push_back(std::move(outofplane));
  figure.panels.push_back(std::move(tension));
  return figure;
}

}  // namespace catena::internal
