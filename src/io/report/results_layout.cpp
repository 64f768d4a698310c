// SPDX-License-Identifier: MIT
#include "io/report/results_layout.hpp"

#include <fmt/format.h>

#include <cmath>

#include "catena/core/error.hpp"

namespace catena::internal {
namespace {

// The largest number a published entry may list (a mode, or a forcing row counted from 0): the
// report makes a table row for every number up to it.
constexpr double kMaxPublishedMode = 100000.0;

const char* const kCheckKeys[] = {key::check,   key::compare, key::plane,    key::mode,
                                  key::value_a, key::value_b, key::measured, key::tolerance,
                                  key::verdict, key::detail};
const char* const kModeKeys[] = {key::index,       key::omega_rad_s, key::frequency_hz,
                                 key::k_l_over_pi, key::gale_ratio,  key::relative_error_estimate};
const char* const kGroupKeys[] = {key::eps, key::chord_angle_deg, key::lambda2, key::mass_ratio};

struct Layout {
  const std::string& file;

  [[noreturn]] void fail(const std::string& where, const std::string& why) const {
    throw ParseError(
        fmt::format("{}: {}: {} (not the layout `catena verify` writes)", file, where, why));
  }
  void object(const json& value, const std::string& where) const {
    if (!value.is_object()) fail(where, "not an object");
  }
  void array(const json& value, const std::string& where) const {
    if (!value.is_array()) fail(where, "not an array");
  }
  const json& member(const json& value, const char* key, const std::string& where) const {
    if (!value.contains(key)) fail(where, fmt::format("no \"{}\"", key));
    return value.at(key);
  }
  template <std::size_t N>
  void members(const json& value, const char* const (&keys)[N], const std::string& where) const {
    object(value, where);
    for (const char* key : keys) member(value, key, where);
  }
  // An array of objects, each holding `keys`.
  template <std::size_t N>
  void records(const json& value, const char* const (&keys)[N], const std::string& where) const {
    array(value, where);
    for (std::size_t i = 0; i < value.size(); ++i)
      members(value[i], keys, fmt::format("{}[{}]", where, i));
  }
};

void check_solver(const Layout& l, const json& output, const std::string& where) {
  l.object(output, where);
  l.object(l.member(output, key::summary, where), where + ".summary");
  for (const char* plane : {key::inplane, key::outofplane}) {
    if (!output.contains(plane)) continue;
    const std::string at = where + "." + plane;
    l.object(output.at(plane), at);
    l.records(l.member(output.at(plane), key::modes, at), kModeKeys, at + ".modes");
    if (output.at(plane).contains(key::overdamped)) {
      const char* const none[] = {key::index};
      l.records(output.at(plane).at(key::overdamped), none, at + ".overdamped");
    }
  }
  if (output.contains(key::forced)) {
    const char* const forced[] = {key::omega_rad_s};
    l.records(output.at(key::forced), forced, where + ".forced");
  }
}

void check_published(const Layout& l, const json& list, const std::string& where) {
  l.array(list, where);
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = fmt::format("{}[{}]", where, i);
    const char* const keys[] = {key::modes, key::values};
    l.members(list[i], keys, at);
    const json& modes = list[i].at(key::modes);
    const json& values = list[i].at(key::values);
    l.array(modes, at + ".modes");
    l.array(values, at + ".values");
    if (modes.empty() || modes.size() != values.size())
      l.fail(at, "\"modes\" and \"values\" must be non-empty arrays of one length");
    for (const json& mode : modes) {
      const double m = mode.is_number() ? mode.get<double>() : 0.0;
      if (!mode.is_number() || !(m >= 0.0 && m <= kMaxPublishedMode && m == std::floor(m)))
        l.fail(at + ".modes", fmt::format("{} is not a whole number from 0 to {}", mode.dump(),
                                          kMaxPublishedMode));
    }
    for (const json& value : values) {
      if (!value.is_number() && !value.is_null())
        l.fail(at + ".values", fmt::format("{} is not a number", value.dump()));
    }
  }
}

void check_scene(const Layout& l, const json& scene, const std::string& where) {
  l.object(scene, where);
  const json& name = l.member(scene, key::name, where);
  if (!name.is_string()) l.fail(where + ".name", "not a string");
  const json& error = l.member(scene, key::error, where);
  if (!error.is_null() && !error.is_string()) l.fail(where + ".error", "not null or a string");
  l.records(l.member(scene, key::checks, where), kCheckKeys, where + ".checks");
  const json& solvers = l.member(scene, key::solvers, where);
  l.object(solvers, where + ".solvers");
  for (const auto& [solver, output] : solvers.items())
    check_solver(l, output, where + ".solvers." + solver);
  if (scene.contains(key::groups)) {
    const json& groups = scene.at(key::groups);
    l.members(groups, kGroupKeys, where + ".groups");
    if (groups.contains(key::gale)) {
      const char* const gale[] = {key::xi1, key::xi2};
      l.members(groups.at(key::gale), gale, where + ".groups.gale");
    }
  }
  // The forced table divides by the statics' H: required when a solver has forced responses.
  bool forced = false;
  for (const auto& [solver, output] : solvers.items())
    forced = forced || output.contains(key::forced);
  if (forced || scene.contains(key::statics))
    l.object(l.member(scene, key::statics, where), where + ".statics");
  if (scene.contains(key::published))
    check_published(l, scene.at(key::published), where + ".published");
}

}  // namespace

void check_results_layout(const json& document, const std::string& file) {
  const Layout l{file};
  l.object(document, "the document");
  l.object(l.member(document, key::catena, "the document"), "catena");
  const json& scenes = l.member(document, key::scenes, "the document");
  l.array(scenes, "scenes");
  for (std::size_t i = 0; i < scenes.size(); ++i)
    check_scene(l, scenes[i], fmt::format("scenes[{}]", i));
  if (document.contains(key::mutation)) {
    const char* const mutation[] = {key::exact_with_witness};
    l.members(document.at(key::mutation), mutation, "mutation");
    l.object(document.at(key::mutation).at(key::exact_with_witness), "mutation.exact_with_witness");
  }
}

}  // namespace catena::internal
