// SPDX-License-Identifier: MIT
#include "io/plot/picture_input.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "catena/core/error.hpp"
#include "io/internal/results_keys.hpp"

namespace catena::internal {
namespace {

using json = nlohmann::json;

const json& member(const json& object, const char* key, const std::string& where) {
  if (!object.is_object() || !object.contains(key))
    throw ParseError(fmt::format("{}.{}: missing (not a catena results JSON?)", where, key));
  return object.at(key);
}

double number(const json& object, const char* key, const std::string& where) {
  const json& value = member(object, key, where);
  if (value.is_null()) return std::numeric_limits<double>::quiet_NaN();  // non-finite, written null
  if (!value.is_number()) throw ParseError(fmt::format("{}.{}: not a number", where, key));
  return value.get<double>();
}

std::string text(const json& object, const char* key, const std::string& where) {
  const json& value = member(object, key, where);
  if (!value.is_string()) throw ParseError(fmt::format("{}.{}: not a string", where, key));
  return value.get<std::string>();
}

// An array of numbers (null: a non-finite value, kept as NaN so that the drawing breaks there).
std::vector<double> numbers(const json& object, const char* key, const std::string& where) {
  const json& value = member(object, key, where);
  if (!value.is_array()) throw ParseError(fmt::format("{}.{}: not an array", where, key));
  std::vector<double> out;
  out.reserve(value.size());
  for (const json& item : value) {
    if (item.is_null()) {
      out.push_back(std::numeric_limits<double>::quiet_NaN());
    } else if (item.is_number()) {
      out.push_back(item.get<double>());
    } else {
      throw ParseError(fmt::format("{}.{}[{}]: not a number", where, key, out.size()));
    }
  }
  return out;
}

PictureProfile read_profile(const json& statics, const std::string& where) {
  const json& shape = member(statics, key::shape, where);
  const std::string at = where + ".shape";
  PictureProfile p{numbers(shape, key::s_m, at), numbers(shape, key::x_m, at),
                   numbers(shape, key::z_m, at), numbers(shape, key::tension_n, at)};
  const std::size_t n = p.s_m.size();
  if (n < 2 || p.x_m.size() != n || p.z_m.size() != n || p.tension_n.size() != n)
    throw ParseError(
        fmt::format("{}: s_m, x_m, z_m and tension_n must have the same length >= 2", at));
  return p;
}

void read_line(PictureInput& in, const json& problem, const json& statics, const std::string& at) {
  if (!problem.contains(key::line)) {  // a uniform cable, whatever form gave it
    const json& cable = member(problem, key::cable, at);
    in.segments.push_back({0.0, number(cable, key::length_m, at + ".cable"),
                           number(cable, key::weight_n_per_m, at + ".cable")});
    return;
  }
  const json& line = member(problem, key::line, at);
  double s = 0.0;
  for (const json& segment : member(line, key::segments, at + ".line")) {
    const double length = number(segment, key::length_m, at + ".line.segments[]");
    in.segments.push_back({s, s + length, number(segment, key::weight_n_per_m, at + ".line")});
    s += length;
  }
  for (const json& point : member(line, key::points, at + ".line")) {
    in.points.push_back({number(point, key::s_m, at + ".line.points[]"), 0.0, 0.0,
                         number(point, key::mass_kg, at + ".line.points[]"),
                         number(point, key::weight_n, at + ".line.points[]")});
  }
  // The statics places every joint and point (nodes, in order of s).
  if (!statics.contains(key::nodes)) return;
  for (const json& node : statics.at(key::nodes)) {
    const std::string where = at + ".statics.nodes[]";
    const std::string kind = text(node, key::kind, where);
    const double x = number(node, key::x_m, where), z = number(node, key::z_m, where);
    if (kind == "joint") {
      in.joints_xz.emplace_back(x, z);
      in.joints_s_m.push_back(number(node, key::s_m, where));
    } else if (kind == "point") {
      const double index = number(node, key::index, where);
      if (index >= 0.0 && index < static_cast<double>(in.points.size())) {
        in.points[static_cast<std::size_t>(index)].x_m = x;
        in.points[static_cast<std::size_t>(index)].z_m = z;
      }
    }
  }
}

void read_seabed(PictureInput& in, const json& statics, const std::string& at) {
  if (!statics.contains(key::seabed)) return;
  const json& bed = statics.at(key::seabed);
  const std::string where = at + ".seabed";
  in.seabed_z_m = number(bed, key::z_m, where);
  in.contact = member(bed, key::contact, where).is_boolean() && bed.at(key::contact).get<bool>();
  in.grounded_length_m = number(bed, key::grounded_length_m, where);
  const double length = in.segments.empty() ? 0.0 : in.segments.back().s_end_m;
  // Touchdown and lift-off: the ends of the grounded stretches that are not a support.
  for (const json& interval : member(bed, key::contact_intervals, where)) {
    const std::string w = where + ".contact_intervals[]";
    const double ends[2][2] = {
        {number(interval, key::s_begin_m, w), number(interval, key::x_begin_m, w)},
        {number(interval, key::s_end_m, w), number(interval, key::x_end_m, w)}};
    for (const auto& end : ends) {
      if (end[0] > 1e-9 * length && end[0] < length * (1.0 - 1e-9))
        in.touchdowns_sx.emplace_back(end[0], end[1]);
    }
  }
}

std::vector<PicturePlane> read_planes(const json& solvers,
                                      const char* plane,
                                      const std::string& at) {
  std::vector<PicturePlane> out;
  for (const auto& [name, output] : solvers.items()) {
    if (!output.is_object() || !output.contains(plane) || !output.at(plane).is_object()) continue;
    const json& record = output.at(plane);
    const std::string where = fmt::format("{}.solvers.{}.{}", at, name, plane);
    PicturePlane p{name, text(member(record, key::summary, where), key::termination, where), {}};
    for (const json& mode : member(record, key::modes, where)) {
      if (!mode.is_object() || !mode.contains(key::shape)) continue;
      const json& shape = mode.at(key::shape);
      const std::string w = where + ".modes[].shape";
      const bool in_plane = std::string(plane) == key::inplane;
      PictureMode m{static_cast<int>(number(mode, key::index, where + ".modes[]")),
                    number(mode, key::frequency_hz, where + ".modes[]"),
                    numbers(shape, key::s_m, w),
                    in_plane ? numbers(shape, key::u, w) : std::vector<double>(),
                    in_plane ? numbers(shape, key::w, w) : std::vector<double>(),
                    in_plane ? std::vector<double>() : numbers(shape, key::v, w)};
      const std::size_t n = m.s_m.size();
      if (in_plane ? (m.u.size() != n || m.w.size() != n) : m.v.size() != n)
        throw ParseError(fmt::format("{}: the shape's arrays differ in length", w));
      p.modes.push_back(std::move(m));
    }
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace

PictureInput read_picture_input(const json& record, const std::string& where) {
  PictureInput in;
  in.name = text(record, key::name, where);
  if (record.contains(key::tags) && record.at(key::tags).is_array()) {
    for (const json& tag : record.at(key::tags))
      if (tag.is_string()) in.tags.push_back(tag.get<std::string>());
  }
  if (!record.contains(key::statics) || !record.at(key::statics).is_object()) {
    const json* error = record.contains(key::error) ? &record.at(key::error) : nullptr;
    throw InvalidInput(fmt::format("{} (scene '{}'): no statics in the results{}", where, in.name,
                                   error && error->is_string()
                                       ? ": the scene failed: " + error->get<std::string>()
                                       : std::string()));
  }
  const json& statics = record.at(key::statics);
  const std::string at = where + ".statics";
  if (!statics.contains(key::shape)) {
    throw InvalidInput(fmt::format(
        "{} (scene '{}'): no static profile (statics.shape) in the results: they were written "
        "without shapes; solve the scene with [request].shapes = true, or draw it with `catena "
        "solve SCENE --plot FILE`, which asks for them",
        where, in.name));
  }
  in.profile = read_profile(statics, at);
  const json& problem = member(record, key::problem, where);
  const json& supports = member(problem, key::supports, where + ".problem");
  in.a_m = numbers(supports, key::a_m, where + ".problem.supports");
  in.b_m = numbers(supports, key::b_m, where + ".problem.supports");
  if (in.a_m.size() != 2 || in.b_m.size() != 2)
    throw ParseError(fmt::format("{}.problem.supports: a_m and b_m must be [x, z]", where));
  read_line(in, problem, statics, where + ".problem");
  in.horizontal_force_n = number(statics, key::horizontal_force_n, at);
  in.tension_a_n = number(statics, key::tension_a_n, at);
  in.tension_b_n = number(statics, key::tension_b_n, at);
  read_seabed(in, statics, at);
  if (record.contains(key::solvers) && record.at(key::solvers).is_object()) {
    in.inplane = read_planes(record.at(key::solvers), key::inplane, where);
    in.outofplane = read_planes(record.at(key::solvers), key::outofplane, where);
  }
  return in;
}

}  // namespace catena::internal
