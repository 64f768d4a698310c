// SPDX-License-Identifier: MIT
#include "catena/io/scene_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <toml.hpp>

#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "catena/statics/problem_builders.hpp"
#include "io/internal/hydrodynamics_reader.hpp"
#include "io/internal/toml_table_reader.hpp"

namespace catena {
namespace {

using internal::TableReader;

bool positive(double x) { return x > 0.0; }
bool non_negative(double x) { return x >= 0.0; }
bool any_value(double) { return true; }

double read_axial_stiffness(TableReader& cable) {
  const toml::value& value = cable.require("EA");
  double ea;
  if (value.is_string()) {
    if (value.as_string().str != "inf") {
      throw InvalidInput(fmt::format("{} = \"{}\": must be a number > 0 or \"inf\" [N]",
                                     cable.where("EA"), value.as_string().str));
    }
    ea = kInfinity;
  } else {
    ea = cable.to_number(value, "EA");
  }
  if (std::isnan(ea) || ea <= 0.0) {
    throw InvalidInput(
        fmt::format("{} = {}: must be > 0 or inf (inextensible) [N]", cable.where("EA"), ea));
  }
  return ea;
}

// The damping keys of [cable] and of each [[line.segments]] (docs/reference/scene-format.md,
// "Damping"); all default to 0 (undamped).
SectionDamping read_section_damping(TableReader& table) {
  SectionDamping damping;
  damping.tangential_n_s_per_m2 =
      table.checked("damping_tangential", non_negative, "finite and >= 0", "N s/m per m", 0.0);
  damping.normal_n_s_per_m2 =
      table.checked("damping_normal", non_negative, "finite and >= 0", "N s/m per m", 0.0);
  damping.axial_n_s = table.checked("axial_damping", non_negative, "finite and >= 0", "N s", 0.0);
  return damping;
}

Problem read_physical(TableReader& root, const std::string& origin) {
  Problem problem;
  TableReader cable = root.subtable("cable");
  problem.cable.length_m = cable.checked("length", positive, "finite and > 0", "m");
  problem.cable.weight_n_per_m = cable.checked("weight", positive, "finite and > 0", "N/m");
  problem.cable.axial_stiffness_n = read_axial_stiffness(cable);
  problem.cable.mass_kg_per_m = cable.checked("mass", positive, "finite and > 0", "kg/m");
  problem.cable.added_mass_kg_per_m =
      cable.checked("added_mass", non_negative, "finite and >= 0", "kg/m", 0.0);
  problem.cable.damping = read_section_damping(cable);
  problem.cable.added_mass_tangential_kg_per_m = internal::read_added_mass_tangential(cable);
  problem.cable.drag = internal::read_drag(cable);
  problem.supports.a_m = cable.point("a");
  problem.supports.b_m = cable.point("b");
  cable.finish();
  try {
    problem.validate();
  } catch (const InvalidInput& error) {
    throw InvalidInput(fmt::format("{}: [cable]: {}", origin, error.what()));
  }
  return problem;
}

// The entries of the array of tables `[[<path>.<key>]]`, each read as `<path>.<key>[i]` (0-based,
// as Line::validate names them).
std::vector<TableReader> indexed_tables(TableReader& table,
                                        const std::string& key,
                                        const std::string& path,
                                        const std::string& origin) {
  std::vector<TableReader> tables;
  const toml::value* list = table.find(key);
  if (!list) return tables;
  if (!list->is_array())
    throw ParseError(
        fmt::format("{}: expected an array of tables [[{}.{}]]", table.where(key), path, key));
  for (const auto& item : list->as_array()) {
    const std::string name = fmt::format("{}.{}[{}]", path, key, tables.size());
    if (!item.is_table()) throw ParseError(fmt::format("{}: [{}]: expected a table", origin, name));
    tables.emplace_back(item, origin, name);
  }
  return tables;
}

LineSegment read_segment(TableReader& table) {
  LineSegment segment;
  segment.length_m = table.checked("length", positive, "finite and > 0", "m");
  segment.weight_n_per_m =
      table.checked("weight", any_value, "finite (> 0 hangs, 0 straight, < 0 buoyant)", "N/m");
  segment.axial_stiffness_n = read_axial_stiffness(table);
  segment.mass_kg_per_m = table.checked("mass", positive, "finite and > 0", "kg/m");
  segment.added_mass_kg_per_m =
      table.checked("added_mass", non_negative, "finite and >= 0", "kg/m", 0.0);
  segment.damping = read_section_damping(table);
  segment.added_mass_tangential_kg_per_m = internal::read_added_mass_tangential(table);
  segment.drag = internal::read_drag(table);
  table.finish();
  return segment;
}

PointAttachment read_point(TableReader& table) {
  PointAttachment point;
  point.s_m = table.checked("s", non_negative, "finite and >= 0", "m");
  point.mass_kg = table.checked("mass", non_negative, "finite and >= 0", "kg", 0.0);
  point.weight_n =
      table.checked("weight", any_value, "finite (> 0 a clump weight, < 0 a buoy)", "N", 0.0);
  point.added_mass_kg = table.checked("added_mass", non_negative, "finite and >= 0", "kg", 0.0);
  auto directional = [&](const char* key) -> std::optional<double> {
    if (!table.has(key)) return std::nullopt;
    return table.checked(key, non_negative, "finite and >= 0", "kg");
  };
  point.added_mass_tangential_kg = directional("added_mass_tangential");
  point.added_mass_normal_kg = directional("added_mass_normal");
  point.added_mass_outofplane_kg = directional("added_mass_outofplane");
  table.finish();
  return point;
}

// [line]: segments and points. One segment of positive weight without points is the uniform cable
// (the same Problem as [cable], so every solver sees it as one).
Problem read_line(TableReader& root, const std::string& origin) {
  Problem problem;
  TableReader table = root.subtable("line");
  problem.supports.a_m = table.point("a");
  problem.supports.b_m = table.point("b");
  for (TableReader& entry : indexed_tables(table, "segments", "line", origin)) {
    problem.line.segments.push_back(read_segment(entry));
  }
  for (TableReader& entry : indexed_tables(table, "points", "line", origin)) {
    problem.line.points.push_back(read_point(entry));
  }
  table.finish();
  const Line& line = problem.line;
  if (line.segments.empty()) {
    throw InvalidInput(fmt::format(
        "{}: [line]: Invalid line.segments: a line needs at least one [[line.segments]] entry",
        origin));
  }
  if (line.segments.size() == 1 && line.points.empty() && line.segments[0].weight_n_per_m > 0.0) {
    const LineSegment& segment = line.segments[0];
    problem.cable = {segment.length_m,
                     segment.weight_n_per_m,
                     segment.axial_stiffness_n,
                     segment.mass_kg_per_m,
                     segment.added_mass_kg_per_m,
                     segment.damping,
                     segment.added_mass_tangential_kg_per_m,
                     segment.drag};
    problem.line = Line{};
  }
  try {
    problem.validate();
  } catch (const InvalidInput& error) {
    throw InvalidInput(fmt::format("{}: [line]: {}", origin, error.what()));
  }
  return problem;
}

Problem read_taut_inclined(TableReader& root, const std::string& origin) {
  TableReader form = root.subtable("taut_inclined");
  const double eps = form.checked("eps", positive, "finite and > 0", "-");
  const double phi = form.checked("phi_deg", any_value, "finite", "deg");
  const double lambda2 = form.checked("lambda2", positive, "finite and > 0", "-");
  const double h = form.checked("mass_ratio", positive, "finite and > 0", "-", 1.0);
  // Nondimensional damping (set_taut_inclined_damping; docs/reference/scene-format.md, "Damping").
  SectionDamping damping;
  damping.tangential_n_s_per_m2 =
      form.checked("eta_tangential", non_negative, "finite and >= 0", "-", 0.0);
  damping.normal_n_s_per_m2 = form.checked("eta_normal", non_negative, "finite and >= 0", "-", 0.0);
  damping.axial_n_s = form.checked("eta_axial", non_negative, "finite and >= 0", "-", 0.0);
  form.finish();
  try {
    Problem problem = make_taut_inclined_problem(eps, phi, lambda2, h);
    set_taut_inclined_damping(problem, damping);
    return problem;
  } catch (const InvalidInput& error) {
    throw InvalidInput(fmt::format("{}: [taut_inclined]: {}", origin, error.what()));
  }
}

Problem read_gale(TableReader& root, const std::string& origin) {
  TableReader form = root.subtable("gale");
  const bool by_xi = form.has("xi1") || form.has("xi2");
  const bool by_sag = form.has("h_over_b") || form.has("sag_param");
  if (by_xi == by_sag) {
    throw ParseError(
        fmt::format("{}: [gale] needs either (xi1, xi2) or (h_over_b, sag_param), not {}", origin,
                    by_xi ? "both" : "neither"));
  }
  // Gale's eqs. 2.28e,f: eta = f / rho sqrt(a / g), rho the mass per length (no added mass in his
  // form), so f = eta rho sqrt(g / a) (= eta in the form's units, rho = a = g = 1).
  const double eta1 = form.checked("eta1", non_negative, "finite and >= 0", "-", 0.0);
  const double eta2 = form.checked("eta2", non_negative, "finite and >= 0", "-", 0.0);
  try {
    Problem problem;
    if (by_xi) {
      const double xi1 = form.number("xi1");
      const double xi2 = form.number("xi2");
      form.finish();
      problem = make_gale_xi_problem(xi1, xi2);
    } else {
      const double h_over_b = form.number("h_over_b");
      const double sag = form.number("sag_param");
      form.finish();
      problem = make_gale_sag_problem(h_over_b, sag);
    }
    set_gale_damping(problem, eta1, eta2);
    return problem;
  } catch (const InvalidInput& error) {
    throw InvalidInput(fmt::format("{}: [gale]: {}", origin, error.what()));
  }
}

// Reads the one cable form of the scene into a Problem.
Problem read_cable_form(TableReader& root, const std::string& origin) {
  const bool physical = root.has("cable");
  const bool line = root.has("line");
  const bool taut = root.has("taut_inclined");
  const bool gale = root.has("gale");
  const int forms = int(physical) + int(line) + int(taut) + int(gale);
  if (forms != 1) {
    throw ParseError(
        fmt::format("{}: a scene needs exactly one of the tables [cable], [line], [taut_inclined], "
                    "[gale]; found {}",
                    origin, forms));
  }
  if (physical) return read_physical(root, origin);
  if (line) return read_line(root, origin);
  if (taut) return read_taut_inclined(root, origin);
  return read_gale(root, origin);
}

// [seabed] (docs/reference/scene-format.md): the flat seabed under a [cable] or [line]; no end may
// be below it.
void read_seabed(TableReader& root, Problem& problem, const std::string& origin) {
  TableReader table = root.subtable("seabed");
  Seabed seabed;
  seabed.z_m = table.checked("z", any_value, "finite", "m");
  seabed.friction = table.checked("friction", non_negative, "finite and >= 0", "-", 0.0);
  seabed.stiffness_n_per_m2 =
      table.checked("stiffness", non_negative, "finite and >= 0", "N/m per m", 0.0);
  seabed.tangential_stiffness_n_per_m2 =
      table.checked("tangential_stiffness", non_negative, "finite and >= 0", "N/m per m", 0.0);
  seabed.damping_n_s_per_m2 =
      table.checked("damping", non_negative, "finite and >= 0", "N s/m per m", 0.0);
  table.finish();
  problem.seabed = seabed;
  try {
    problem.validate();
  } catch (const InvalidInput& error) {
    throw InvalidInput(fmt::format("{}: [seabed]: {}", origin, error.what()));
  }
}

// Reads the one cable form of the scene, and its seabed, into a Problem.
Problem read_problem(TableReader& root, const std::string& origin) {
  Problem problem = read_cable_form(root, origin);
  if (root.has("seabed")) {
    if (problem.form != ProblemForm::Physical) {
      throw InvalidInput(fmt::format("{}: [seabed] goes with [cable] or [line], not with [{}]",
                                     origin, to_string(problem.form)));
    }
    read_seabed(root, problem, origin);
  }
  if (root.has("environment")) {
    TableReader table = root.subtable("environment");
    problem.environment = internal::read_environment(table);
    try {
      problem.environment.validate();
    } catch (const InvalidInput& error) {
      throw InvalidInput(fmt::format("{}: [environment]: {}", origin, error.what()));
    }
  }
  return problem;
}

FrequencyUnit read_frequency_unit(TableReader& table,
                                  const std::string& key,
                                  const std::string& fallback) {
  const std::string text = table.string(key, fallback);
  const auto unit = parse_frequency_unit(text);
  if (!unit) {
    throw InvalidInput(
        fmt::format("{} = \"{}\": must be one of \"rad/s\", \"Hz\", \"kL/pi\", \"gale\"",
                    table.where(key), text));
  }
  return *unit;
}

// [request.forced]: the driven end, direction, amplitude and forcing frequencies (in the scene's
// units; resolve_request converts them).
ForcedRequest read_forced(TableReader& forced, Scene& scene) {
  ForcedRequest f;
  const std::string end = forced.string("end", "b");
  if (end != "a" && end != "b") {
    throw InvalidInput(
        fmt::format("{} = \"{}\": must be \"a\" or \"b\"", forced.where("end"), end));
  }
  f.end = end == "a" ? CableEnd::A : CableEnd::B;
  if (const toml::value* direction = forced.find("direction")) {
    if (direction->is_array()) {
      f.direction = ForcingDirection::GivenVector;
      f.vector = forced.point("direction");
      if (f.vector.norm() == 0.0) {
        throw InvalidInput(
            fmt::format("{}: the direction vector must be non-zero", forced.where("direction")));
      }
    } else {
      const std::string text = forced.string("direction", "tangential");
      if (text == "tangential")
        f.direction = ForcingDirection::Tangential;
      else if (text == "normal")
        f.direction = ForcingDirection::Normal;
      else if (text == "out_of_plane")
        f.direction = ForcingDirection::OutOfPlane;
      else {
        throw InvalidInput(fmt::format(
            "{} = \"{}\": must be \"tangential\", \"normal\", \"out_of_plane\" or [x, z]",
            forced.where("direction"), text));
      }
    }
  }
  f.amplitude_m = forced.checked("amplitude", positive, "finite and > 0", "m or a", 0.01);
  const std::string amplitude_unit = forced.string("amplitude_unit", "m");
  if (amplitude_unit != "m" && amplitude_unit != "a") {
    throw InvalidInput(fmt::format("{} = \"{}\": must be \"m\" or \"a\" (Gale's a = H/W0)",
                                   forced.where("amplitude_unit"), amplitude_unit));
  }
  scene.forcing_amplitude_in_a = amplitude_unit == "a";
  f.omegas_rad_s = forced.numbers("frequencies");
  if (f.omegas_rad_s.empty()) {
    throw InvalidInput(
        fmt::format("{}: at least one forcing frequency needed", forced.where("frequencies")));
  }
  if (f.omegas_rad_s.size() > SolveRequest::kMaxForcingFrequencies) {
    throw InvalidInput(fmt::format(
        "{}: {} forcing frequencies, at most {} per request (docs/reference/scene-format.md, "
        "\"Limits on work\")",
        forced.where("frequencies"), f.omegas_rad_s.size(), SolveRequest::kMaxForcingFrequencies));
  }
  for (double omega : f.omegas_rad_s) {
    if (omega < 0.0) {
      throw InvalidInput(
          fmt::format("{}: forcing frequency {} must be >= 0", forced.where("frequencies"), omega));
    }
  }
  scene.forcing_frequency_unit = read_frequency_unit(forced, "frequency_unit", "rad/s");
  forced.finish();
  return f;
}

void read_request(TableReader& root, Scene& scene) {
  if (!root.has("request")) return;
  TableReader request = root.subtable("request");
  // Upper bounds: docs/reference/scene-format.md, "Limits" (SolveRequest::validate enforces the
  // same).
  auto count = [&](const std::string& key, int fallback, long low, long high) {
    return static_cast<int>(request.read_integer(key, low, high, fallback));
  };
  scene.request.inplane_modes =
      count("inplane_modes", scene.request.inplane_modes, 0, kMaxRequestModes);
  scene.request.outofplane_modes =
      count("outofplane_modes", scene.request.outofplane_modes, 0, kMaxRequestModes);
  scene.request.shapes = request.boolean("shapes", scene.request.shapes);
  scene.request.points = count("points", scene.request.points, 2, kMaxRequestPoints);
  scene.request.tension = request.boolean("tension", scene.request.tension);
  if (request.has("forced")) {
    TableReader forced = request.subtable("forced");
    scene.request.forced = read_forced(forced, scene);
  }
  if (request.has("motion")) {
    TableReader motion = request.subtable("motion");
    scene.request.motion = internal::read_motion(motion);
  }
  request.finish();
  try {
    scene.request.validate();
  } catch (const InvalidInput& error) {
    throw InvalidInput(fmt::format("{}: [request]: {}", path_text(scene.file), error.what()));
  }
  // No modes and no forcing: a statics-only scene (the runner computes the statics only).
}

KnobValue to_knob(const toml::value& value, const std::string& where) {
  if (value.is_boolean()) return value.as_boolean();
  if (value.is_integer()) return static_cast<long>(value.as_integer());
  if (value.is_floating()) return value.as_floating();
  if (value.is_string()) return value.as_string().str;
  throw ParseError(fmt::format("{}: a knob must be a number, a boolean or a string, got {}", where,
                               TableReader::type_name(value)));
}

void read_solvers(TableReader& root, Scene& scene) {
  if (!root.has("solvers")) return;
  TableReader solvers = root.subtable("solvers");
  for (const auto& [name, knobs_value] : solvers.value().as_table()) {
    const SolverEntry* entry = find_solver(name);
    if (!entry) {
      std::string known;
      for (const auto& e : solver_registry()) known += (known.empty() ? "" : ", ") + e.name;
      throw ParseError(fmt::format("{}: unknown solver (known: {})", solvers.where(name), known));
    }
    TableReader knob_table = solvers.subtable(name);
    SolverKnobs knobs;
    for (const auto& [knob, value] : knob_table.value().as_table()) {
      knobs[knob] = to_knob(value, knob_table.where(knob));
    }
    try {
      if (entry->validate_knobs) entry->validate_knobs(knobs);
    } catch (const InvalidInput& error) {
      throw InvalidInput(fmt::format("{}: {}", path_text(scene.file), error.what()));
    }
    scene.solvers[name] = knobs;
  }
}

void read_checks(TableReader& root, Scene& scene) {
  if (!root.has("checks")) return;
  TableReader checks = root.subtable("checks");
  auto optional_positive = [&](const std::string& key, std::optional<double>& out) {
    if (checks.has(key)) out = checks.checked(key, positive, "finite and > 0", "-");
  };
  optional_positive("frequency_rel", scene.checks.frequency_rel);
  optional_positive("shape_max_diff", scene.checks.shape_max_diff);
  optional_positive("tension_rel", scene.checks.tension_rel);
  optional_positive("orthogonality", scene.checks.orthogonality);
  if (checks.has("mac_min")) {
    scene.checks.mac_min = checks.checked(
        "mac_min", [](double x) { return x > 0.0 && x <= 1.0; }, "in (0, 1]", "-");
  }
  checks.finish();
}

void read_published(TableReader& root, Scene& scene) {
  for (TableReader& table : root.table_array("published")) {
    PublishedValues published;
    published.source = table.string("source", "");
    if (published.source.empty()) {
      throw ParseError(fmt::format("{}: missing required key (say where the values come from)",
                                   table.where("source")));
    }
    const std::string quantity = table.string("quantity", "");
    const auto parsed = parse_published_quantity(quantity);
    if (!parsed) {
      throw InvalidInput(
          fmt::format("{} = \"{}\": must be \"inplane_frequency\", "
                      "\"outofplane_frequency\" or \"forced_max_tension\"",
                      table.where("quantity"), quantity));
    }
    published.quantity = *parsed;
    published.unit = read_frequency_unit(table, "unit", "rad/s");
    for (long mode : table.integers("modes", 0, kMaxRequestModes))
      published.modes.push_back(static_cast<int>(mode));
    published.values = table.numbers("values");
    if (published.values.size() != published.modes.size()) {
      throw InvalidInput(fmt::format("{}: {} values for {} modes", table.where("values"),
                                     published.values.size(), published.modes.size()));
    }
    // More than 17 decimals would be below the resolution of a double.
    published.decimals = static_cast<int>(table.read_integer("decimals", 0, 17, -1));
    if (const toml::value* solvers = table.find("solvers")) {
      if (!solvers->is_array())
        throw ParseError(
            fmt::format("{}: expected an array of solver names", table.where("solvers")));
      for (const auto& name : solvers->as_array()) {
        if (!name.is_string() || !find_solver(name.as_string().str)) {
          throw ParseError(fmt::format("{}: unknown solver", table.where("solvers")));
        }
        published.compare_with.push_back(name.as_string().str);
      }
    }
    table.finish();
    scene.published.push_back(std::move(published));
  }
}

// Applies one sweep value to the parsed TOML document (so the value is validated exactly like a
// value written in the file).
toml::value with_sweep_value(const toml::value& document,
                             const std::string& parameter,
                             double value,
                             const std::string& origin) {
  const auto dot = parameter.find('.');
  if (dot == std::string::npos) {
    throw InvalidInput(
        fmt::format("{}: [sweep].parameter = \"{}\": expected \"table.key\"", origin, parameter));
  }
  const std::string table = parameter.substr(0, dot);
  const std::string key = parameter.substr(dot + 1);
  toml::value copy = document;
  if (!copy.as_table().count(table) || !copy.as_table().at(table).is_table()) {
    throw InvalidInput(fmt::format("{}: [sweep].parameter = \"{}\": the scene has no table [{}]",
                                   origin, parameter, table));
  }
  copy.as_table().at(table).as_table()[key] = value;
  return copy;
}

std::vector<Scene> read_document(const toml::value& document,
                                 const std::string& origin,
                                 const std::filesystem::path& file) {
  if (!document.is_table()) throw ParseError(fmt::format("{}: not a TOML table", origin));
  // A sweep: read the document once per value.
  if (document.as_table().count("sweep")) {
    TableReader root(document, origin, "");
    TableReader sweep = root.subtable("sweep");
    const std::string parameter = sweep.string("parameter", "");
    if (parameter.empty())
      throw ParseError(fmt::format("{}: missing required key", sweep.where("parameter")));
    const std::vector<double> values = sweep.numbers("values");
    sweep.finish();
    if (values.empty()) throw InvalidInput(fmt::format("{}: no values", sweep.where("values")));
    std::vector<Scene> scenes;
    toml::value base = document;
    base.as_table().erase("sweep");
    for (double value : values) {
      std::vector<Scene> one =
          read_document(with_sweep_value(base, parameter, value, origin), origin, file);
      one.front().name += fmt::format("[{}={}]", parameter.substr(parameter.find('.') + 1), value);
      one.front().sweep_point = std::make_pair(parameter, value);
      scenes.push_back(std::move(one.front()));
    }
    return scenes;
  }

  TableReader root(document, origin, "");
  root.known_elsewhere("sweep");  // read above, before this reader
  Scene scene;
  scene.file = file;
  scene.name = root.string("name", file.empty() ? origin : path_text(file.stem()));
  scene.description = root.string("description", "");
  if (root.has("tags")) scene.tags = root.strings("tags");
  scene.problem = read_problem(root, origin);
  read_request(root, scene);
  read_solvers(root, scene);
  read_checks(root, scene);
  read_published(root, scene);
  root.finish();
  return {scene};
}

}  // namespace

std::vector<Scene> parse_scene_text(const std::string& text, const std::string& origin) {
  return read_document(internal::parse_toml(text, origin), origin, origin);
}

std::vector<Scene> read_scene_file(const std::filesystem::path& path) {
  const std::string text = read_input_file(path, "scene file");
  std::vector<Scene> scenes =
      read_document(internal::parse_toml(text, path_text(path)), path_text(path), path);
  for (auto& scene : scenes) scene.file = path;
  return scenes;
}

std::vector<std::filesystem::path> list_scene_files(const std::filesystem::path& directory) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (!fs::is_directory(directory, error)) {
    throw InvalidInput(fmt::format("{}: not a directory of scenes{}", path_text(directory),
                                   error ? ": " + error.message() : std::string()));
  }
  std::vector<fs::path> files;
  // Directory symlinks are not followed (no loops); every other entry named *.toml is listed, a
  // dangling symlink or a FIFO too, so that reading it reports it instead of skipping it.
  fs::recursive_directory_iterator it(directory, error), end;
  for (; !error && it != end; it.increment(error)) {
    if (it->path().extension() != ".toml") continue;
    std::error_code status_error;
    if (!fs::is_directory(it->symlink_status(status_error))) files.push_back(it->path());
  }
  if (error) {
    throw InvalidInput(fmt::format("{}: cannot list the scenes under it: {}",
                                   path_text(it == end ? directory : it->path()), error.message()));
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace catena
