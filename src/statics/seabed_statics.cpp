// SPDX-License-Identifier: MIT
#include "catena/statics/seabed_statics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "catena/core/error.hpp"
#include "statics/internal/bisection.hpp"
#include "statics/internal/contact_arcs.hpp"
#include "statics/internal/general_contact.hpp"
#include "statics/internal/line_parts.hpp"
#include "statics/internal/line_pieces.hpp"
#include "statics/internal/seabed_pieces.hpp"

namespace catena {
namespace {

using internal::bisect;

// The contact equations of one problem: the end offset of the line as a function of (H, L_g).
struct ContactSystem {
  const Line& line;
  const Seabed& seabed;
  double seabed_offset_z_m;
  Vec2 chord_m;
  // Evaluations of the reach residual (each one bisection for L_g): reported as the iterations.
  mutable int evaluations = 0;

  Vec2 end_offset(double H, double grounded_length) const {
    const auto pieces =
        internal::build_seabed_pieces(line, seabed.friction, seabed_offset_z_m, H, grounded_length);
    return internal::line_end_offset(pieces, H);
  }
  // L_g with which the suspended part reaches the fairlead's height, or -1 when even L_g = 0 is
  // too low (H too large for contact).
  double grounded_length_for(double H) const {
    auto above = [&](double Lg) { return end_offset(H, Lg).y() >= chord_m.y(); };
    if (!above(0.0)) return -1.0;
    return bisect(0.0, line.length_m() * (1.0 - 1e-12), above);
  }
  // Horizontal miss of the fairlead with force H (+inf when H is too large for contact).
  double reach_residual(double H) const {
    ++evaluations;
    const double grounded_length = grounded_length_for(H);
    if (grounded_length < 0.0) return kInfinity;
    return end_offset(H, grounded_length).x() - chord_m.x();
  }
};

// The H of the contact solution by bisection on the reach residual (increasing in H), after
// bracketing it by doubling and halving from the line's weight.
double contact_horizontal_force(const ContactSystem& system) {
  double hi = std::max(internal::weight_scale(system.line), 1.0);
  for (int i = 0; i < 200 && !(system.reach_residual(hi) > 0.0); ++i) hi *= 2.0;
  double lo = hi;
  for (int i = 0; i < 120 && system.reach_residual(lo) >= 0.0; ++i) lo *= 0.5;
  if (system.reach_residual(lo) >= 0.0) return -1.0;
  return bisect(lo, hi, [&](double H) { return system.reach_residual(H) < 0.0; });
}

// The cases outside the model, with the limit they hit.
void check_supported(const StaticSolution& solution, const Line& line, double tolerance) {
  const double Lg = solution.grounded_length_m();
  for (std::size_t k = 0; k < line.segments.size(); ++k) {
    if (line.segment_start_m(k) < Lg && !(line.segments[k].weight_n_per_m > 0.0)) {
      throw InvalidInput(
          fmt::format("Invalid line.segments[{}]: seabed contact with a buoyant or weightless "
                      "segment on the grounded part "
                      "(weight {} N/m, grounded length {:.6g} m) is not supported",
                      k, line.segments[k].weight_n_per_m, Lg));
    }
  }
  for (std::size_t i = 0; i < line.points.size(); ++i) {
    if (line.points[i].s_m <= Lg && line.points[i].weight_n < 0.0) {
      throw InvalidInput(
          fmt::format("Invalid line.points[{}]: a buoy on the grounded part (s = {:.6g} m <= "
                      "grounded length {:.6g} m) is "
                      "not supported",
                      i, line.points[i].s_m, Lg));
    }
  }
  const double lowest = solution.position_m(solution.lowest_point_s_m()).y();
  if (lowest < solution.seabed().z_m - tolerance) {
    throw InvalidInput(
        fmt::format("seabed: the suspended line would pass {:.6g} m below the seabed at s = "
                    "{:.6g} m: a configuration outside the model of tangential contact (not "
                    "supported)",
                    solution.seabed().z_m - lowest, solution.lowest_point_s_m()));
  }
}

// The no-seabed solution is the answer when it stays on or above the seabed (leaving an anchor
// that lies on the seabed upward, V_A >= 0).
bool stays_off_seabed(const StaticSolution& free,
                      const Seabed& seabed,
                      double tolerance,
                      bool anchor_on_seabed) {
  if (!free.converged || (anchor_on_seabed && free.vertical_force_a_n() < 0.0)) return false;
  return free.position_m(free.lowest_point_s_m()).y() >= seabed.z_m - tolerance;
}

// The contact model's one known gap, diagnosed: the touchdown falls at a point weight (a clump),
// where the line would leave the seabed at an angle with the clump's weight shared between the
// seabed and the suspended part. The reach residual then jumps across zero as L_g crosses the
// point (the clump's weight is wholly on one side or the other), and no (H, L_g) closes. Bad input
// for this model (exit 2, what to change), not a numerical failure.
void refuse_touchdown_at_point(const Line& line, double H, double grounded_length, double miss) {
  const double near = 1e-6 * line.length_m();
  for (std::size_t i = 0; i < line.points.size(); ++i) {
    const PointAttachment& point = line.points[i];
    if (!(point.weight_n > 0.0) || std::abs(point.s_m - grounded_length) > near) continue;
    throw InvalidInput(fmt::format(
        "Invalid line.points[{}]: the touchdown falls at this point weight (s = {:.6g} m, weight "
        "{:.6g} N, H = {:.6g} N; the ends miss by {:.3e} m): the clump rests on the seabed with "
        "the line leaving it at an angle, which the seabed statics does not model (not "
        "supported). Move the point along the line (s), change its weight, or move the fairlead "
        "so that the touchdown falls clear of it",
        i, point.s_m, point.weight_n, H, miss));
  }
}

StaticSolution solve_contact(const Problem& problem, const StaticsOptions& options) {
  const Line line = problem.as_line();
  const Seabed& seabed = *problem.seabed;
  const Vec2 chord = problem.supports.chord_m();
  const ContactSystem system{line, seabed, seabed.z_m - problem.supports.a_m.y(), chord};
  const double H = contact_horizontal_force(system);
  if (H < 0.0) return internal::solve_general_contact(problem, options);
  const double grounded_length = system.grounded_length_for(H);
  StaticSolution solution(line, problem.supports.a_m, seabed, H, std::max(grounded_length, 0.0));
  const double scale = std::max(line.length_m(), chord.norm());
  solution.iterations = system.evaluations;
  solution.closure_error_m = (solution.offset_m(line.length_m()) - chord).norm();
  check_supported(solution, line, 1e-9 * std::max(1.0, scale));
  const double accepted = std::max(options.relative_tolerance * scale, 1e-11 * scale);
  if (!(solution.closure_error_m <= accepted) || !std::isfinite(H)) {
    refuse_touchdown_at_point(line, H, grounded_length, solution.closure_error_m);
    solution.converged = false;
    solution.message = fmt::format(
        "Statics on the seabed did not converge: closure error {:.3e} m > {:.3e} m (H = {:.6g} N, "
        "grounded length {:.6g} m)",
        solution.closure_error_m, accepted, H, grounded_length);
  }
  return solution;
}

}  // namespace

StaticSolution solve_seabed_statics(const Problem& problem, const StaticsOptions& options) {
  problem.validate();
  options.validate();
  Problem free = problem;
  free.seabed.reset();
  if (!problem.seabed) return solve_statics(free, options);
  const Seabed& seabed = *problem.seabed;
  const double tolerance = 1e-9 * std::max(1.0, std::abs(seabed.z_m));
  const bool anchor_on_seabed = std::abs(problem.supports.a_m.y() - seabed.z_m) <= tolerance;
  if (problem.supports.b_m.y() <= seabed.z_m + tolerance && anchor_on_seabed) {
    throw InvalidInput(
        fmt::format("Invalid seabed.z = {}: end B (the fairlead) lies on the seabed (b.z = {}): a "
                    "line entirely on the seabed is not supported; the fairlead must be above the "
                    "seabed",
                    seabed.z_m, problem.supports.b_m.y()));
  }
  if (problem.supports.b_m.y() <= seabed.z_m + tolerance) {
    throw InvalidInput(
        fmt::format("Invalid seabed.z = {}: end B lies on the seabed (b.z = {}) with end A above "
                    "it: not supported; mirror the line so that s runs from the end on the seabed",
                    seabed.z_m, problem.supports.b_m.y()));
  }
  StaticSolution solution = solve_statics(free, options);
  if (stays_off_seabed(solution, seabed, tolerance, anchor_on_seabed)) {
    solution.set_seabed_without_contact(seabed);
    return solution;
  }
  // One contact interval from the anchor (no buoyancy to lift an arc): the two nested bisections
  // of the original model, bit for bit; everything else in general contact.
  if (!anchor_on_seabed) return internal::solve_general_contact(problem, options);
  if (internal::buoyant_stretches(problem.as_line()).empty())
    return solve_contact(problem, options);
  // With buoyancy the one-interval state is still the answer when it passes its checks (nothing
  // below the seabed, nothing buoyant on it): the equilibrium is unique, so a state that satisfies
  // every contact condition is it (MoorPy tests/case3.dat: a buoy and a clump weight beyond the
  // touchdown). Otherwise the buoyancy lifts arcs off the seabed: general contact.
  try {
    StaticSolution solution = solve_contact(problem, options);
    if (solution.converged) return solution;
  } catch (const InvalidInput&) {
  }
  return internal::solve_general_contact(problem, options);
}

}  // namespace catena
