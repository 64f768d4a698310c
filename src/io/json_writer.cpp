#include "catena/io/json_writer.hpp"

#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>

#include "catena/core/error.hpp"
#include "catena/core/version.hpp"

namespace catena {
namespace {

using nlohmann::json;

json number(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json vector_json(const Vector& values) {
  json out = json::array();
  for (Index i = 0; i < values.size(); ++i) out.push_back(number(values[i]));
  return out;
}

json summary_json(const SolverSummary& summary) {
  return {{"termination", to_string(summary.termination)},
          {"message", summary.message},
          {"resolution", summary.resolution},
          {"iterations", summary.iterations},
          {"operations", summary.operations},
          {"max_error_estimate", number(summary.max_error_estimate)},
          {"max_residual", number(summary.max_residual)},
          {"wall_time_s", number(summary.wall_time_s)},
          {"warnings", summary.warnings},
          {"notes", summary.notes},
          {"brief", summary.brief_report()}};
}

json mode_json(const Mode& mode) {
  json out = {{"index", mode.index},
              {"omega_rad_s", number(mode.omega_rad_s)},
              {"frequency_hz", number(mode.frequency_hz)},
              {"k_l_over_pi", number(mode.k_l_over_pi)},
              {"gale_ratio", mode.gale_ratio ? number(*mode.gale_ratio) : json(nullptr)},
              {"relative_error_estimate", number(mode.relative_error_estimate)}};
  if (mode.max_abs_tension_n >= 0.0) out["max_abs_tension_n"] = number(mode.max_abs_tension_n);
  if (mode.modal_mass_kg >= 0.0) out["modal_mass_kg"] = number(mode.modal_mass_kg);
  if (mode.s_m.size()) {
    json shape = {{"s_m", vector_json(mode.s_m)}, {"normalised_by", mode.normalised_by}};
    if (mode.u.size()) shape["u"] = vector_json(mode.u);
    if (mode.w.size()) shape["w"] = vector_json(mode.w);
    if (mode.v.size()) shape["v"] = vector_json(mode.v);
    if (mode.tension_n.size()) shape["tension_n"] = vector_json(mode.tension_n);
    out["shape"] = shape;
  }
  return out;
}

json modal_json(const ModalResult& result) {
  json modes = json::array();
  for (const auto& mode : result.modes) modes.push_back(mode_json(mode));
  return {{"proved_count_below_top", result.proved_count_below_top},
          {"summary", summary_json(result.summary)},
          {"modes", modes}};
}

json forced_json(const ForcedResponse& response) {
  json out = {{"omega_rad_s", number(response.omega_rad_s)},
              {"max_abs_tension_n", number(response.max_abs_tension_n)},
              {"relative_error_estimate", number(response.relative_error_estimate)},
              {"diagnostic", response.diagnostic}};
  if (response.s_m.size()) out["s_m"] = vector_json(response.s_m);
  if (response.u.size()) out["u_m"] = vector_json(response.u);
  if (response.w.size()) out["w_m"] = vector_json(response.w);
  if (response.v.size()) out["v_m"] = vector_json(response.v);
  if (response.tension_n.size()) out["tension_n"] = vector_json(response.tension_n);
  return out;
}

json output_json(const SolverOutput& output) {
  json out = {{"summary", summary_json(output.summary)}};
  if (output.inplane) out["inplane"] = modal_json(*output.inplane);
  if (output.outofplane) out["outofplane"] = modal_json(*output.outofplane);
  if (!output.forced.empty()) {
    json forced = json::array();
    for (const auto& response : output.forced) forced.push_back(forced_json(response));
    out["forced"] = forced;
  }
  return out;
}

json problem_json(const Problem& problem) {
  const CableProperties& c = problem.cable;
  return {{"form", to_string(problem.form)},
          {"cable",
           {{"length_m", c.length_m},
            {"weight_n_per_m", c.weight_n_per_m},
            {"axial_stiffness_n", number(c.axial_stiffness_n)},
            {"inextensible", c.is_inextensible()},
            {"mass_kg_per_m", c.mass_kg_per_m},
            {"added_mass_kg_per_m", c.added_mass_kg_per_m}}},
          {"supports",
           {{"a_m", {problem.supports.a_m.x(), problem.supports.a_m.y()}},
            {"b_m", {problem.supports.b_m.x(), problem.supports.b_m.y()}}}}};
}

json request_json(const SolveRequest& request) {
  json out = {{"inplane_modes", request.inplane_modes},
              {"outofplane_modes", request.outofplane_modes},
              {"shapes", request.shapes},
              {"points", request.points},
              {"tension", request.tension}};
  if (request.forced) {
    const ForcedRequest& f = *request.forced;
    out["forced"] = {{"end", to_string(f.end)},
                     {"direction", to_string(f.direction)},
                     {"vector", {f.vector.x(), f.vector.y()}},
                     {"amplitude_m", f.amplitude_m},
                     {"omegas_rad_s", f.omegas_rad_s}};
  }
  return out;
}

json statics_json(const StaticSolution& statics, int points) {
  const double L = statics.cable().length_m;
  json s = json::array(), x = json::array(), z = json::array(), t = json::array();
  for (int i = 0; i < points; ++i) {
    const double si = L * i / (points - 1);
    const Vec2 r = statics.position_m(si);
    s.push_back(si);
    x.push_back(r.x());
    z.push_back(r.y());
    t.push_back(statics.tension_n(si));
  }
  return {{"horizontal_force_n", statics.horizontal_force_n()},
          {"vertical_force_a_n", statics.vertical_force_a_n()},
          {"vertical_force_b_n", statics.vertical_force_n(L)},
          {"tension_a_n", statics.tension_n(0.0)},
          {"tension_b_n", statics.tension_n(L)},
          {"angle_a_deg", statics.angle_rad(0.0) * 180.0 / kPi},
          {"angle_b_deg", statics.angle_rad(L) * 180.0 / kPi},
          {"stretched_length_m", statics.stretched_length_m(L)},
          {"newton_iterations", statics.iterations},
          {"closure_error_m", statics.closure_error_m},
          {"shape", {{"s_m", s}, {"x_m", x}, {"z_m", z}, {"tension_n", t}}}};
}

json groups_json(const DimensionlessGroups& g) {
  json out = {{"chord_angle_deg", g.chord_angle_rad * 180.0 / kPi},
              {"t0_n", g.t0_n},
              {"s_at_chord_angle_m", g.s_at_chord_angle_m},
              {"eps", g.eps},
              {"lambda2", number(g.lambda2)},
              {"mass_ratio", g.mass_ratio},
              {"taut_frequency_scale_rad_s", g.taut_frequency_scale_rad_s}};
  if (g.has_apex_parameterization) {
    out["gale"] = {{"a_m", g.catenary_parameter_m},
                   {"sigma1", g.sigma1},
                   {"sigma2", g.sigma2},
                   {"xi1", g.xi1},
                   {"xi2", g.xi2},
                   {"h_over_b", g.height_over_span ? json(*g.height_over_span) : json(nullptr)},
                   {"sag_param", g.sag_parameter ? json(*g.sag_parameter) : json(nullptr)},
                   {"frequency_scale_rad_s", g.gale_frequency_scale_rad_s}};
  }
  return out;
}

json check_json(const CheckResult& check) {
  return {{"check", check.check},   {"compare", check.compare},   {"plane", check.plane},
          {"mode", check.mode},     {"value_a", number(check.value_a)},
          {"value_b", number(check.value_b)}, {"measured", number(check.measured)},
          {"tolerance", number(check.tolerance)}, {"verdict", to_string(check.verdict)},
          {"detail", check.detail}};
}

json scene_json(const SceneResult& result) {
  const Scene& scene = result.scene;
  json out = {{"name", scene.name},
              {"file", scene.file.string()},
              {"description", scene.description},
              {"tags", scene.tags},
              {"problem", problem_json(scene.problem)},
              {"request", request_json(result.request)},
              {"wall_time_s", result.wall_time_s},
              {"error", result.error.empty() ? json(nullptr) : json(result.error)}};
  if (scene.sweep_point) out["sweep"] = {{"parameter", scene.sweep_point->first}, {"value", scene.sweep_point->second}};
  if (result.statics) out["statics"] = statics_json(*result.statics, result.request.points);
  if (result.groups) out["groups"] = groups_json(*result.groups);
  json solvers = json::object();
  for (const auto& output : result.outputs) solvers[output.solver] = output_json(output);
  out["solvers"] = solvers;
  json published = json::array();
  for (const auto& p : scene.published) {
    published.push_back({{"source", p.source},
                         {"quantity", to_string(p.quantity)},
                         {"unit", to_string(p.unit)},
                         {"modes", p.modes},
                         {"values", p.values},
                         {"decimals", p.decimals},
                         {"solvers", p.compare_with}});
  }
  out["published"] = published;
  json checks = json::array();
  for (const auto& check : result.checks) checks.push_back(check_json(check));
  out["checks"] = checks;
  return out;
}

}  // namespace

std::string results_to_json(const std::vector<SceneResult>& results, int indent) {
  json scenes = json::array();
  for (const auto& result : results) scenes.push_back(scene_json(result));
  json document = {{"catena",
                    {{"version", version()},
                     {"git", git_hash()},
                     {"compiler", compiler()},
                     {"build_type", build_type()},
                     {"generated_utc", utc_timestamp()}}},
                   {"scenes", scenes}};
  return document.dump(indent);
}

void write_results_json(const std::filesystem::path& path, const std::vector<SceneResult>& results) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path);
  if (!out) throw InvalidInput(fmt::format("{}: cannot write JSON file", path.string()));
  out << results_to_json(results) << '\n';
  if (!out) throw InvalidInput(fmt::format("{}: write failed", path.string()));
}

}  // namespace catena
