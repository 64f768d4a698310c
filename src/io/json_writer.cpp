#include "catena/io/json_writer.hpp"

#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "catena/core/error.hpp"
#include "catena/core/version.hpp"
#include "catena/io/file_access.hpp"
#include "io/internal/results_keys.hpp"

namespace catena {
namespace {

using nlohmann::json;
namespace key = internal::key;

json number(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json vector_json(const Vector& values) {
  json out = json::array();
  for (Index i = 0; i < values.size(); ++i) out.push_back(number(values[i]));
  return out;
}

json summary_json(const SolverSummary& summary) {
  return {{key::termination, to_string(summary.termination)},
          {key::message, summary.message},
          {key::resolution, summary.resolution},
          {key::iterations, summary.iterations},
          {key::operations, summary.operations},
          {key::max_error_estimate, number(summary.max_error_estimate)},
          {key::max_residual, number(summary.max_residual)},
          {key::wall_time_s, number(summary.wall_time_s)},
          {key::warnings, summary.warnings},
          {key::notes, summary.notes},
          {key::accuracy_target, number(summary.accuracy_target)},
          {key::missed_modes, summary.missed_modes},
          {key::brief, summary.brief_report()}};
}

json mode_json(const Mode& mode) {
  json out = {{key::index, mode.index},
              {key::omega_rad_s, number(mode.omega_rad_s)},
              {key::frequency_hz, number(mode.frequency_hz)},
              {key::k_l_over_pi, number(mode.k_l_over_pi)},
              {key::gale_ratio, mode.gale_ratio ? number(*mode.gale_ratio) : json(nullptr)},
              {key::relative_error_estimate, number(mode.relative_error_estimate)},
              {key::meets_target, mode.meets_target}};
  if (mode.max_abs_tension_n >= 0.0) out[key::max_abs_tension_n] = number(mode.max_abs_tension_n);
  if (mode.modal_mass_kg >= 0.0) out[key::modal_mass_kg] = number(mode.modal_mass_kg);
  if (mode.s_m.size()) {
    json shape = {{key::s_m, vector_json(mode.s_m)}, {key::normalised_by, mode.normalised_by}};
    if (mode.u.size()) shape[key::u] = vector_json(mode.u);
    if (mode.w.size()) shape[key::w] = vector_json(mode.w);
    if (mode.v.size()) shape[key::v] = vector_json(mode.v);
    if (mode.tension_n.size()) shape[key::tension_n] = vector_json(mode.tension_n);
    out[key::shape] = shape;
  }
  return out;
}

json modal_json(const ModalResult& result) {
  json modes = json::array();
  for (const auto& mode : result.modes) modes.push_back(mode_json(mode));
  return {{key::proved_count_below_top, result.proved_count_below_top},
          {key::summary, summary_json(result.summary)},
          {key::modes, modes}};
}

json forced_json(const ForcedResponse& response) {
  json out = {{key::omega_rad_s, number(response.omega_rad_s)},
              {key::max_abs_tension_n, number(response.max_abs_tension_n)},
              {key::relative_error_estimate, number(response.relative_error_estimate)},
              {key::diagnostic, response.diagnostic},
              {key::at_resonance, response.at_resonance},
              {key::near_resonance, response.near_resonance}};
  if (response.s_m.size()) out[key::s_m] = vector_json(response.s_m);
  if (response.u.size()) out[key::u_m] = vector_json(response.u);
  if (response.w.size()) out[key::w_m] = vector_json(response.w);
  if (response.v.size()) out[key::v_m] = vector_json(response.v);
  if (response.tension_n.size()) out[key::tension_n] = vector_json(response.tension_n);
  return out;
}

json output_json(const SolverOutput& output) {
  json out = {{key::summary, summary_json(output.summary)}};
  if (output.inplane) out[key::inplane] = modal_json(*output.inplane);
  if (output.outofplane) out[key::outofplane] = modal_json(*output.outofplane);
  if (!output.forced.empty()) {
    json forced = json::array();
    for (const auto& response : output.forced) forced.push_back(forced_json(response));
    out[key::forced] = forced;
  }
  return out;
}

json problem_json(const Problem& problem) {
  const CableProperties& c = problem.cable;
  return {{key::form, to_string(problem.form)},
          {key::cable,
           {{key::length_m, c.length_m},
            {key::weight_n_per_m, c.weight_n_per_m},
            {key::axial_stiffness_n, number(c.axial_stiffness_n)},
            {key::inextensible, c.is_inextensible()},
            {key::mass_kg_per_m, c.mass_kg_per_m},
            {key::added_mass_kg_per_m, c.added_mass_kg_per_m}}},
          {key::supports,
           {{key::a_m, {problem.supports.a_m.x(), problem.supports.a_m.y()}},
            {key::b_m, {problem.supports.b_m.x(), problem.supports.b_m.y()}}}}};
}

json request_json(const SolveRequest& request) {
  json out = {{key::inplane_modes, request.inplane_modes},
              {key::outofplane_modes, request.outofplane_modes},
              {key::shapes, request.shapes},
              {key::points, request.points},
              {key::tension, request.tension}};
  if (request.forced) {
    const ForcedRequest& f = *request.forced;
    out[key::forced] = {{key::end, to_string(f.end)},
                     {key::direction, to_string(f.direction)},
                     {key::vector, {f.vector.x(), f.vector.y()}},
                     {key::amplitude_m, f.amplitude_m},
                     {key::omegas_rad_s, f.omegas_rad_s}};
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
  return {{key::horizontal_force_n, statics.horizontal_force_n()},
          {key::vertical_force_a_n, statics.vertical_force_a_n()},
          {key::vertical_force_b_n, statics.vertical_force_n(L)},
          {key::tension_a_n, statics.tension_n(0.0)},
          {key::tension_b_n, statics.tension_n(L)},
          {key::angle_a_deg, statics.angle_rad(0.0) * 180.0 / kPi},
          {key::angle_b_deg, statics.angle_rad(L) * 180.0 / kPi},
          {key::stretched_length_m, statics.stretched_length_m(L)},
          {key::newton_iterations, statics.iterations},
          {key::closure_error_m, statics.closure_error_m},
          {key::shape, {{key::s_m, s}, {key::x_m, x}, {key::z_m, z}, {key::tension_n, t}}}};
}

json groups_json(const DimensionlessGroups& g) {
  json out = {{key::chord_angle_deg, g.chord_angle_rad * 180.0 / kPi},
              {key::t0_n, g.t0_n},
              {key::s_at_chord_angle_m, g.s_at_chord_angle_m},
              {key::eps, g.eps},
              {key::lambda2, number(g.lambda2)},
              {key::mass_ratio, g.mass_ratio},
              {key::taut_frequency_scale_rad_s, g.taut_frequency_scale_rad_s}};
  if (g.has_apex_parameterization) {
    out[key::gale] = {{key::a_m, g.catenary_parameter_m},
                   {key::sigma1, g.sigma1},
                   {key::sigma2, g.sigma2},
                   {key::xi1, g.xi1},
                   {key::xi2, g.xi2},
                   {key::h_over_b, g.height_over_span ? json(*g.height_over_span) : json(nullptr)},
                   {key::sag_param, g.sag_parameter ? json(*g.sag_parameter) : json(nullptr)},
                   {key::frequency_scale_rad_s, g.gale_frequency_scale_rad_s}};
  }
  return out;
}

json check_json(const CheckResult& check) {
  return {{key::check, check.check},   {key::compare, check.compare},   {key::plane, check.plane},
          {key::mode, check.mode},     {key::value_a, number(check.value_a)},
          {key::value_b, number(check.value_b)}, {key::measured, number(check.measured)},
          {key::tolerance, number(check.tolerance)}, {key::verdict, to_string(check.verdict)},
          {key::detail, check.detail}};
}

json scene_json(const SceneResult& result) {
  const Scene& scene = result.scene;
  json out = {{key::name, scene.name},
              {key::file, path_text(scene.file)},
              {key::description, scene.description},
              {key::tags, scene.tags},
              {key::problem, problem_json(scene.problem)},
              {key::request, request_json(result.request)},
              {key::wall_time_s, result.wall_time_s},
              {key::error, result.error.empty() ? json(nullptr) : json(result.error)}};
  if (scene.sweep_point) out[key::sweep] = {{key::parameter, scene.sweep_point->first}, {key::value, scene.sweep_point->second}};
  if (result.statics) out[key::statics] = statics_json(*result.statics, result.request.points);
  if (result.groups) out[key::groups] = groups_json(*result.groups);
  json solvers = json::object();
  for (const auto& output : result.outputs) solvers[output.solver] = output_json(output);
  out[key::solvers] = solvers;
  json published = json::array();
  for (const auto& p : scene.published) {
    published.push_back({{key::source, p.source},
                         {key::quantity, to_string(p.quantity)},
                         {key::unit, to_string(p.unit)},
                         {key::modes, p.modes},
                         {key::values, p.values},
                         {key::decimals, p.decimals},
                         {key::solvers, p.compare_with}});
  }
  out[key::published] = published;
  json checks = json::array();
  for (const auto& check : result.checks) checks.push_back(check_json(check));
  out[key::checks] = checks;
  return out;
}

}  // namespace

std::string results_to_json(const std::vector<SceneResult>& results, int indent) {
  json scenes = json::array();
  for (const auto& result : results) scenes.push_back(scene_json(result));
  json document = {{key::catena,
                    {{key::version, version()},
                     {key::git, git_hash()},
                     {key::compiler, compiler()},
                     {key::build_type, build_type()},
                     {key::generated_utc, utc_timestamp()}}},
                   {key::scenes, scenes}};
  return document.dump(indent);
}

void write_results_json(const std::filesystem::path& path, const std::vector<SceneResult>& results) {
  write_file_atomically(path, results_to_json(results) + '\n');
}

}  // namespace catena
