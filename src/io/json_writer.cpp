// SPDX-License-Identifier: MIT
#include "catena/io/json_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/core/version.hpp"
#include "catena/io/file_access.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "io/internal/check_table.hpp"
#include "io/internal/dynamic_tension_json.hpp"
#include "io/internal/json_records.hpp"
#include "io/internal/json_text.hpp"
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
          {key::missed_modes, summary.missed_modes}};
}

json mode_json(const Mode& mode) {
  json out = {{key::index, mode.index},
              {key::omega_rad_s, number(mode.omega_rad_s)},
              {key::frequency_hz, number(mode.frequency_hz)},
              {key::k_l_over_pi, number(mode.k_l_over_pi)},
              {key::gale_ratio, mode.gale_ratio ? number(*mode.gale_ratio) : json(nullptr)},
              {key::relative_error_estimate, number(mode.relative_error_estimate)},
              {key::meets_target, mode.meets_target},
              {key::decay_rate_1_s, number(mode.decay_rate_1_s)},
              {key::damping_ratio, number(mode.damping_ratio)}};
  if (mode.decay_rate_error_estimate >= 0.0)
    out[key::decay_rate_error_estimate] = number(mode.decay_rate_error_estimate);
  if (mode.max_abs_tension_n >= 0.0) out[key::max_abs_tension_n] = number(mode.max_abs_tension_n);
  if (mode.modal_mass_kg >= 0.0) out[key::modal_mass_kg] = number(mode.modal_mass_kg);
  if (mode.s_m.size()) {
    json shape = {{key::s_m, vector_json(mode.s_m)}, {key::normalised_by, mode.normalised_by}};
    if (mode.u.size()) shape[key::u] = vector_json(mode.u);
    if (mode.w.size()) shape[key::w] = vector_json(mode.w);
    if (mode.v.size()) shape[key::v] = vector_json(mode.v);
    if (mode.tension_n.size()) shape[key::tension_n] = vector_json(mode.tension_n);
    if (mode.u_imag.size()) shape[key::u_imag] = vector_json(mode.u_imag);
    if (mode.w_imag.size()) shape[key::w_imag] = vector_json(mode.w_imag);
    if (mode.v_imag.size()) shape[key::v_imag] = vector_json(mode.v_imag);
    if (mode.tension_imag_n.size()) shape[key::tension_imag_n] = vector_json(mode.tension_imag_n);
    out[key::shape] = shape;
  }
  return out;
}

json modal_json(const ModalResult& result) {
  json modes = json::array();
  for (const auto& mode : result.modes) modes.push_back(mode_json(mode));
  json out = {{key::proved_count_below_top, result.proved_count_below_top},
              {key::summary, summary_json(result.summary)},
              {key::modes, modes}};
  if (!result.overdamped.empty()) {
    json overdamped = json::array();
    for (const auto& mode : result.overdamped) overdamped.push_back(mode_json(mode));
    out[key::overdamped] = overdamped;
  }
  return out;
}

// The response along the cable (s, u, w, v, tension) is written only when the request asks for
// shapes: the suite's 301-frequency curves would otherwise make up most of report.json.
json forced_json(const ForcedResponse& response, bool along_cable) {
  json out = {{key::omega_rad_s, number(response.omega_rad_s)},
              {key::max_abs_tension_n, number(response.max_abs_tension_n)},
              {key::relative_error_estimate, number(response.relative_error_estimate)},
              {key::diagnostic, response.diagnostic},
              {key::at_resonance, response.at_resonance},
              {key::near_resonance, response.near_resonance}};
  if (!along_cable) return out;
  if (response.s_m.size()) out[key::s_m] = vector_json(response.s_m);
  if (response.u.size()) out[key::u_m] = vector_json(response.u);
  if (response.w.size()) out[key::w_m] = vector_json(response.w);
  if (response.v.size()) out[key::v_m] = vector_json(response.v);
  if (response.tension_n.size()) out[key::tension_n] = vector_json(response.tension_n);
  if (response.u_imag.size()) out[key::u_imag_m] = vector_json(response.u_imag);
  if (response.w_imag.size()) out[key::w_imag_m] = vector_json(response.w_imag);
  if (response.v_imag.size()) out[key::v_imag_m] = vector_json(response.v_imag);
  if (response.tension_imag_n.size())
    out[key::tension_imag_n] = vector_json(response.tension_imag_n);
  return out;
}

json output_json(const SolverOutput& output, bool along_cable) {
  json out = {{key::summary, summary_json(output.summary)}};
  if (output.inplane) out[key::inplane] = modal_json(*output.inplane);
  if (output.outofplane) out[key::outofplane] = modal_json(*output.outofplane);
  if (!output.forced.empty()) {
    json forced = json::array();
    for (const auto& response : output.forced) forced.push_back(forced_json(response, along_cable));
    out[key::forced] = forced;
  }
  // Absent when empty: no motion asked, or the solver declined it (its summary says why).
  if (!output.dynamic_tension.empty())
    out[key::dynamic_tension] = internal::dynamic_tension_list_json(output.dynamic_tension);
  return out;
}

// A section's damping [N s/m per m, N s], written only when it is damped (undamped documents are
// unchanged).
void add_damping_json(json& out, const SectionDamping& damping) {
  if (damping.is_zero()) return;
  out[key::damping] = {{key::tangential_n_s_per_m2, damping.tangential_n_s_per_m2},
                       {key::normal_n_s_per_m2, damping.normal_n_s_per_m2},
                       {key::axial_n_s, damping.axial_n_s}};
}

// A section's Morison drag and tangential added mass, like its damping written only when non-zero
// (a scene without them is written as before).
void add_hydrodynamics_json(json& out, const MorisonDrag& drag, double added_mass_tangential) {
  if (drag.diameter_m != 0.0 || drag.normal != 0.0 || drag.tangential != 0.0) {
    out[key::drag] = {{key::diameter_m, drag.diameter_m},
                      {key::drag_normal, drag.normal},
                      {key::drag_tangential, drag.tangential}};
  }
  if (added_mass_tangential != 0.0)
    out[key::added_mass_tangential_kg_per_m] = added_mass_tangential;
}

json line_json(const Line& line) {
  json segments = json::array(), points = json::array();
  for (const LineSegment& g : line.segments) {
    json segment = {{key::length_m, g.length_m},
                    {key::weight_n_per_m, g.weight_n_per_m},
                    {key::axial_stiffness_n, number(g.axial_stiffness_n)},
                    {key::inextensible, g.is_inextensible()},
                    {key::mass_kg_per_m, g.mass_kg_per_m},
                    {key::added_mass_kg_per_m, g.added_mass_kg_per_m}};
    add_damping_json(segment, g.damping);
    add_hydrodynamics_json(segment, g.drag, g.added_mass_tangential_kg_per_m);
    segments.push_back(segment);
  }
  for (const PointAttachment& p : line.points) {
    points.push_back(
        {{key::s_m, p.s_m},
         {key::mass_kg, p.mass_kg},
         {key::weight_n, p.weight_n},
         {key::added_mass_kg,
          {p.tangential_added_mass_kg(), p.normal_added_mass_kg(), p.outofplane_added_mass_kg()}}});
  }
  return {{key::segments, segments}, {key::points, points}};
}

json problem_form_json(const Problem& problem) {
  const CableProperties& c = problem.cable;
  if (!problem.is_uniform()) {
    return {{key::form, "line"},
            {key::line, line_json(problem.line)},
            {key::supports,
             {{key::a_m, {problem.supports.a_m.x(), problem.supports.a_m.y()}},
              {key::b_m, {problem.supports.b_m.x(), problem.supports.b_m.y()}}}}};
  }
  json cable = {{key::length_m, c.length_m},
                {key::weight_n_per_m, c.weight_n_per_m},
                {key::axial_stiffness_n, number(c.axial_stiffness_n)},
                {key::inextensible, c.is_inextensible()},
                {key::mass_kg_per_m, c.mass_kg_per_m},
                {key::added_mass_kg_per_m, c.added_mass_kg_per_m}};
  add_damping_json(cable, c.damping);
  add_hydrodynamics_json(cable, c.drag, c.added_mass_tangential_kg_per_m);
  return {{key::form, to_string(problem.form)},
          {key::cable, cable},
          {key::supports,
           {{key::a_m, {problem.supports.a_m.x(), problem.supports.a_m.y()}},
            {key::b_m, {problem.supports.b_m.x(), problem.supports.b_m.y()}}}}};
}

// The problem, with its seabed when it has one, and its water when the line has drag or the water
// is not the default one (as the damping: a scene without drag is written as before).
json problem_json(const Problem& problem) {
  json out = problem_form_json(problem);
  const Environment& water = problem.environment;
  const Environment defaults;
  if (problem.has_drag() || water.water_density_kg_per_m3 != defaults.water_density_kg_per_m3 ||
      water.gravity_m_per_s2 != defaults.gravity_m_per_s2) {
    out[key::environment] = {{key::water_density_kg_per_m3, water.water_density_kg_per_m3},
                             {key::gravity_m_per_s2, water.gravity_m_per_s2}};
  }
  if (problem.seabed) {
    const Seabed& bed = *problem.seabed;
    out[key::seabed] = {{key::z_m, bed.z_m},
                        {key::friction, bed.friction},
                        {key::stiffness_n_per_m2, bed.stiffness_n_per_m2},
                        {key::tangential_stiffness_n_per_m2, bed.tangential_stiffness_n_per_m2}};
    if (bed.damping_n_s_per_m2 > 0.0)
      out[key::seabed][key::damping_n_s_per_m2] = bed.damping_n_s_per_m2;
  }
  return out;
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
  if (request.motion) out[key::motion] = internal::motion_request_json(*request.motion);
  return out;
}

// The state at arc length s: position, stretched length from a, and the forces on both sides (they
// differ at a point attachment by its weight).
// On the seabed (s < L_g) the force is horizontal and set by friction: it jumps at a clump weight.
json node_json(const StaticSolution& statics,
               const std::string& kind,
               std::size_t index,
               double s) {
  const Vec2 r = statics.position_m(s);
  const double before = statics.vertical_force_before_n(s);
  const double after = statics.vertical_force_n(s);
  const bool grounded = statics.grounded_at(s);
  const double H = grounded ? statics.tension_n(s) : statics.horizontal_force_n();
  const double tension_before =
      grounded ? statics.tension_n(std::nextafter(s, 0.0)) : std::hypot(H, before);
  return {{key::kind, kind},
          {key::index, index},
          {key::s_m, s},
          {key::x_m, r.x()},
          {key::z_m, r.y()},
          {key::stretched_length_m, statics.stretched_length_m(s)},
          {key::horizontal_force_n, H},
          {key::vertical_force_before_n, before},
          {key::vertical_force_after_n, after},
          {key::tension_before_n, tension_before},
          {key::tension_after_n, std::hypot(H, after)}};
}

// The stretches resting on the seabed: unstretched arc lengths and x of their ends.
json contact_intervals_json(const StaticSolution& statics) {
  json list = json::array();
  for (const ContactInterval& interval : statics.contact_intervals()) {
    list.push_back({{key::s_begin_m, interval.s_begin_m},
                    {key::s_end_m, interval.s_end_m},
                    {key::x_begin_m, statics.position_m(interval.s_begin_m).x()},
                    {key::x_end_m, statics.position_m(interval.s_end_m).x()}});
  }
  return list;
}

// The seabed block (docs/reference/json-layout.md, "Seabed"): contact, the contact intervals,
// grounded and slack lengths, the first touchdown point from A, the forces on the ends A and B.
json seabed_json(const StaticSolution& statics) {
  const Seabed& seabed = statics.seabed();
  const double L = statics.cable().length_m;
  const std::vector<ContactInterval> intervals = statics.contact_intervals();
  // The first touchdown from A: where the line from A reaches the seabed, or with A on the
  // seabed where it leaves it (the end of the stretch from A); s = 0 without contact.
  double touchdown_s = 0.0;
  if (!intervals.empty()) {
    touchdown_s =
        statics.anchor_grounded() ? intervals.front().s_end_m : intervals.front().s_begin_m;
  }
  const Vec2 touchdown = statics.position_m(touchdown_s);
  const char* model =
      statics.has_contact()
          ? "flat seabed: grounded stretches straight on it, tangential touchdown and lift-off; "
            "Coulomb friction C_B w per unit length on the stretch from an anchor on the seabed "
            "(MAP++/MoorPy convention), tension H on the others"
          : "flat seabed: no contact (the line stays on or above the seabed)";
  return {{key::z_m, seabed.z_m},
          {key::friction, seabed.friction},
          {key::stiffness_n_per_m2, seabed.stiffness_n_per_m2},
          {key::tangential_stiffness_n_per_m2, seabed.tangential_stiffness_n_per_m2},
          {key::contact, statics.has_contact()},
          {key::contact_model, model},
          {key::contact_intervals, contact_intervals_json(statics)},
          {key::grounded_length_m, statics.grounded_length_m()},
          {key::slack_length_m, statics.slack_length_m()},
          {key::touchdown,
           {{key::s_m, touchdown_s}, {key::x_m, touchdown.x()}, {key::z_m, touchdown.y()}}},
          {key::anchor_horizontal_force_n, statics.anchor_horizontal_force_n()},
          {key::anchor_vertical_force_n, statics.vertical_force_a_n()},
          {key::fairlead_horizontal_force_n, statics.horizontal_force_n()},
          {key::fairlead_vertical_force_n, statics.vertical_force_n(L)}};
}

// Per joint and per point of a general line, in order of s; and the stretched length of each
// segment.
void add_line_statics(json& out, const StaticSolution& statics) {
  const Line line = statics.line();
  std::vector<std::pair<double, json>> nodes;
  json stretched = json::array();
  for (std::size_t k = 0; k < line.segments.size(); ++k) {
    const double begin = line.segment_start_m(k);
    stretched.push_back(statics.stretched_length_m(line.segment_start_m(k + 1)) -
                        statics.stretched_length_m(begin));
    if (k > 0) nodes.emplace_back(begin, node_json(statics, "joint", k - 1, begin));
  }
  for (std::size_t i = 0; i < line.points.size(); ++i) {
    nodes.emplace_back(line.points[i].s_m, node_json(statics, "point", i, line.points[i].s_m));
  }
  std::stable_sort(nodes.begin(), nodes.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  json list = json::array();
  for (auto& node : nodes) list.push_back(std::move(node.second));
  out[key::nodes] = list;
  out[key::segments] = {{key::stretched_length_m, stretched}};
}

json statics_profile_json(const StaticSolution& statics, int points) {
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
  return {{key::s_m, s}, {key::x_m, x}, {key::z_m, z}, {key::tension_n, t}};
}

// The static profile on the request's stations only when shapes are asked (like the forced curves).
json statics_json(const StaticSolution& statics, const SolveRequest& request) {
  const double L = statics.cable().length_m;
  json out = {{key::horizontal_force_n, statics.horizontal_force_n()},
              {key::vertical_force_a_n, statics.vertical_force_a_n()},
              {key::vertical_force_b_n, statics.vertical_force_n(L)},
              {key::tension_a_n, statics.tension_n(0.0)},
              {key::tension_b_n, statics.tension_n(L)},
              {key::angle_a_deg, statics.angle_rad(0.0) * 180.0 / kPi},
              {key::angle_b_deg, statics.angle_rad(L) * 180.0 / kPi},
              {key::stretched_length_m, statics.stretched_length_m(L)},
              {key::newton_iterations, statics.iterations},
              {key::closure_error_m, statics.closure_error_m}};
  if (request.shapes) out[key::shape] = statics_profile_json(statics, request.points);
  const double s_low = statics.lowest_point_s_m();
  const Vec2 low = statics.position_m(s_low);
  out[key::lowest_point] = {{key::s_m, s_low}, {key::x_m, low.x()}, {key::z_m, low.y()}};
  if (statics.is_line()) add_line_statics(out, statics);
  if (statics.has_seabed()) out[key::seabed] = seabed_json(statics);
  return out;
}

json groups_json(const DimensionlessGroups& g) {
  json out = {{key::chord_angle_deg, g.chord_angle_rad * 180.0 / kPi},
              {key::t0_n, g.t0_n},
              {key::s_at_chord_angle_m, g.uniform ? json(g.s_at_chord_angle_m) : json(nullptr)},
              {key::eps, g.uniform ? json(g.eps) : json(nullptr)},
              {key::lambda2, g.uniform ? number(g.lambda2) : json(nullptr)},
              {key::mass_ratio, g.mass_ratio},
              {key::taut_frequency_scale_rad_s, g.taut_frequency_scale_rad_s}};
  if (g.has_apex_parameterization) {
    out[key::gale] = {
        {key::a_m, g.catenary_parameter_m},
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

// Each distinct tolerance reason once, in order of first use; a check refers to it by position.
class ReasonList {
 public:
  json index_of(const std::string& reason) {
    if (reason.empty()) return nullptr;
    const auto [at, added] = index_.try_emplace(reason, static_cast<int>(reasons_.size()));
    if (added) reasons_.push_back(reason);
    return at->second;
  }
  json list() const { return reasons_; }

 private:
  std::map<std::string, int> index_;
  std::vector<std::string> reasons_;
};

// A PASS check's detail only repeats numbers the file has (its values, measured and tolerance, the
// solvers' estimates and summaries): it is left out. Any other verdict keeps its reason.
std::string written_detail(const CheckResult& check) {
  return check.verdict == Verdict::Pass ? std::string() : check.detail;
}

json check_json(const CheckResult& check, ReasonList& reasons) {
  return {{key::check, check.check},
          {key::compare, check.compare},
          {key::plane, check.plane},
          {key::mode, check.mode},
          {key::value_a, number(check.value_a)},
          {key::value_b, number(check.value_b)},
          {key::measured, number(check.measured)},
          {key::tolerance, number(check.tolerance)},
          {key::verdict, to_string(check.verdict)},
          {key::detail, written_detail(check)},
          {key::tolerance_reason, reasons.index_of(check.tolerance_reason)}};
}

json scene_json(const SceneResult& result, ReasonList& reasons) {
  const Scene& scene = result.scene;
  json out = {{key::name, scene.name},
              {key::file, path_text(scene.file)},
              {key::description, scene.description},
              {key::tags, scene.tags},
              {key::problem, problem_json(scene.problem)},
              {key::request, request_json(result.request)},
              {key::wall_time_s, result.wall_time_s},
              {key::error, result.error.empty() ? json(nullptr) : json(result.error)}};
  if (scene.sweep_point)
    out[key::sweep] = {{key::parameter, scene.sweep_point->first},
                       {key::value, scene.sweep_point->second}};
  if (result.statics) out[key::statics] = statics_json(*result.statics, result.request);
  if (result.groups) out[key::groups] = groups_json(*result.groups);
  json solvers = json::object();
  for (const auto& output : result.outputs)
    solvers[output.solver] = output_json(output, result.request.shapes);
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
  for (const auto& check : result.checks) checks.push_back(check_json(check, reasons));
  out[key::checks] = internal::check_table(checks);
  return out;
}

// The accuracy target of each solver that states one, at its default knobs (a scene's knobs may
// set another: frequency_accuracy_target, catena/verification/mutation.hpp).
json default_accuracy_targets() {
  json out = json::object();
  for (const SolverEntry& entry : solver_registry()) {
    if (entry.accuracy_target) out[entry.name] = entry.accuracy_target({});
  }
  return out;
}

json mutation_json(const MutationRun& run) {
  json tallies = json::array();
  for (const auto& [what, tally] : run.tallies()) {
    const auto& [solver, family, quantity] = what;
    tallies.push_back({{key::solver, solver},
                       {key::family, family},
                       {key::quantity, quantity},
                       {key::made, tally.made},
                       {key::caught, tally.caught}});
  }
  // One record per scene, solver, quantity and plane, listing its uncaught modes and their sizes.
  json uncaught = json::array();
  const MutationOutcome* group = nullptr;
  for (const auto& outcome : run.outcomes) {
    if (outcome.caught) continue;
    if (!group || group->scene != outcome.scene || group->solver != outcome.solver ||
        group->quantity != outcome.quantity || group->plane != outcome.plane ||
        group->exact_witness != outcome.exact_witness) {
      group = &outcome;
      uncaught.push_back({{key::scene, outcome.scene},
                          {key::family, outcome.family},
                          {key::solver, outcome.solver},
                          {key::quantity, to_string(outcome.quantity)},
                          {key::plane, outcome.plane},
                          {key::exact_witness, outcome.exact_witness},
                          {key::modes, json::array()},
                          {key::sizes, json::array()},
                          {key::estimates, json::array()}});
    }
    uncaught.back()[key::modes].push_back(outcome.mode);
    uncaught.back()[key::sizes].push_back(number(outcome.size));
    uncaught.back()[key::estimates].push_back(number(outcome.estimate));
  }
  const MutationTally exact = run.exact_with_witness();
  const MutationTally beyond = run.exact_beyond_estimate();
  return {{key::wall_time_s, run.wall_time_s},
          {key::threads, run.threads},
          {key::frequency_factor, kFrequencyMutationFactor},
          {key::shape_factor, kShapeMutationFactor},
          {key::forced_tension_relative, kForcedTensionMutation},
          {key::default_accuracy_targets, default_accuracy_targets()},
          {key::exact_with_witness, {{key::made, exact.made}, {key::caught, exact.caught}}},
          {key::exact_beyond_estimate, {{key::made, beyond.made}, {key::caught, beyond.caught}}},
          {key::tallies, tallies},
          {key::uncaught, uncaught}};
}

}  // namespace

std::string results_to_json(const std::vector<SceneResult>& results,
                            int indent,
                            const MutationRun* mutation) {
  json scenes = json::array();
  ReasonList reasons;
  for (const auto& result : results) scenes.push_back(scene_json(result, reasons));
  json document = {{key::catena,
                    {{key::version, version()},
                     {key::git, git_hash()},
                     {key::compiler, compiler()},
                     {key::build_type, build_type()},
                     {key::generated_utc, utc_timestamp()}}},
                   {key::scenes, scenes},
                   {key::tolerance_reasons, reasons.list()}};
  if (mutation) document[key::mutation] = mutation_json(*mutation);
  return indent < 0 ? internal::json_text(document) : internal::dump_records(document, indent);
}

void write_results_json(const std::filesystem::path& path,
                        const std::vector<SceneResult>& results,
                        const MutationRun* mutation) {
  write_file_atomically(path, results_to_json(results, 1, mutation) + '\n');
}

}  // namespace catena
