// SPDX-License-Identifier: MIT
#include "catena/statics/line_statics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "catena/core/error.hpp"
#include "statics/internal/line_parts.hpp"
#include "statics/internal/line_pieces.hpp"

namespace catena {
namespace {

struct NewtonRun {
  Vec2 forces;
  double closure = kInfinity;
  int iterations = 0;
};

// Closure residual r(L) - chord of the line with forces (H, V_A).
Vec2 closure_residual(const Line& line, const Vec2& chord, double H, double V_A) {
  return internal::line_end_offset(internal::build_line_pieces(line, H, V_A), H) - chord;
}

// Newton from `start` with a backtracking line search keeping H > 0; stops at `tolerance`, at a
// stall, or after `max_iterations`.
NewtonRun newton_from(
    const Line& line, const Vec2& chord, Vec2 start, double tolerance, int max_iterations) {
  NewtonRun run{start, closure_residual(line, chord, start.x(), start.y()).norm(), 0};
  Vec2 r = closure_residual(line, chord, start.x(), start.y());
  if (!r.allFinite()) return run;
  Vec2& f = run.forces;
  for (; run.iterations < max_iterations && r.norm() > tolerance; ++run.iterations) {
    const Eigen::Matrix2d J =
        internal::line_end_jacobian(internal::build_line_pieces(line, f.x(), f.y()), f.x());
    const Vec2 step = J.fullPivLu().solve(-r);
    if (!step.allFinite()) break;
    bool accepted = false;
    for (double alpha = 1.0; alpha > 1e-18 && !accepted; alpha *= 0.5) {
      const Vec2 trial = f + alpha * step;
      if (!(trial.x() > 0.0)) continue;
      const Vec2 r_trial = closure_residual(line, chord, trial.x(), trial.y());
      if (r_trial.allFinite() && r_trial.norm() < (1.0 - 1e-4 * alpha) * r.norm()) {
        f = trial;
        r = r_trial;
        accepted = true;
      }
    }
    if (!accepted) break;
  }
  run.closure = r.norm();
  return run;
}

using internal::weight_scale;

// The parabolic start of a uniform cable of the same length, total weight and chord (weights
// taken by magnitude, so that a buoyant or weightless line gets a sensible tension scale).
Vec2 equivalent_start(const Line& line, const Vec2& chord) {
  const double L = line.length_m();
  double total_weight = 0.0;
  for (const LineSegment& segment : line.segments)
    total_weight += segment.weight_n_per_m * segment.length_m;
  for (const PointAttachment& point : line.points) total_weight += point.weight_n;
  const double scale = weight_scale(line);
  const double force_scale = scale == 0.0 ? 1.0 : scale;
  const double dx = chord.x();
  const double dz = chord.y();
  const double slack_ratio = (L * L - dz * dz) / (dx * dx) - 1.0;
  const double lambda0 = slack_ratio > 0.0 ? std::sqrt(3.0 * slack_ratio) : 0.2;
  const double H = force_scale * dx / (2.0 * L * std::max(lambda0, 1e-6));
  return {H, H * dz / dx - 0.5 * total_weight};
}

void check_reachable(const Problem& problem) {
  const Line& line = problem.line;
  const Vec2 chord = problem.supports.chord_m();
  const double d = chord.norm();
  if (chord.x() <= 1e-14 * d) {
    throw InvalidInput(
        fmt::format("No static equilibrium computed for a general line on a vertical chord (b - a "
                    "= ({}, {}) m): give the "
                    "ends a horizontal offset",
                    chord.x(), chord.y()));
  }
  if (line.is_inextensible() && line.length_m() <= d * (1.0 + 1e-14)) {
    throw InvalidInput(
        fmt::format("Invalid line.segments: the line is too short for its ends: the chord |b - a| "
                    "= {:.10g} m is {} the "
                    "total length {:.10g} m of an inextensible line",
                    d, line.length_m() < d ? "longer than" : "equal to", line.length_m()));
  }
  // Without weight the line is a straight bar, in tension only when stretched
  // (docs/explanation/physics.md, "General lines": the equilibrium in tension and when it does not
  // exist).
  if (weight_scale(line) == 0.0 && line.length_m() >= d) {
    throw InvalidInput(
        fmt::format("Invalid line.segments[].weight: every segment and point of the line is "
                    "weightless, so it is in "
                    "tension only when stretched, but the chord |b - a| = {:.10g} m does not "
                    "exceed its length {:.10g} m: "
                    "the line would be slack (no equilibrium in tension); give it weight or move "
                    "the ends apart",
                    d, line.length_m()));
  }
}

// Why a run did not close: H collapsing towards 0 means part of the line would be slack (the
// equilibrium in tension does not exist, docs/explanation/physics.md); otherwise Newton failed to
// find it.
std::string closure_failure(const Line& line,
                            const NewtonRun& best,
                            double tolerance,
                            int iterations) {
  const std::string where = fmt::format(
      "closure error {:.3e} m > {:.3e} m after {} Newton iterations from 7 starts "
      "(H = {:.6g} N, V_A = {:.6g} N)",
      best.closure, tolerance, iterations, best.forces.x(), best.forces.y());
  if (best.forces.x() <= 1e-8 * weight_scale(line)) {
    return fmt::format(
        "No static equilibrium in tension: {}: H fell towards 0, so part of the line would be "
        "slack between "
        "these ends (a weightless stretch whose vertical force vanishes, shorter than the room it "
        "has); move "
        "the ends apart or change the weights",
        where);
  }
  return fmt::format("Statics of the line did not converge (a numerical failure): {}", where);
}

}  // namespace

StaticSolution solve_line_statics(const Problem& problem, const StaticsOptions& options) {
  problem.validate();
  options.validate();
  if (problem.is_uniform()) return solve_statics(problem, options);
  check_reachable(problem);
  const Line& line = problem.line;
  const Vec2 chord = problem.supports.chord_m();
  const double scale = std::max(line.length_m(), chord.norm());
  const double tolerance = options.relative_tolerance * scale;
  // Newton can stall a few ulps above a very tight tolerance: the rounding floor is accepted.
  const double accepted = std::max(tolerance, 1e-11 * scale);
  const Vec2 start = equivalent_start(line, chord);
  NewtonRun best;
  int iterations = 0;
  for (double factor : {1.0, 10.0, 0.1, 100.0, 0.01, 1000.0, 0.001}) {
    const Vec2 scaled(start.x() * factor, start.y() * factor);
    const NewtonRun run = newton_from(line, chord, scaled, tolerance, options.max_iterations);
    iterations += run.iterations;
    if (run.closure < best.closure) best = run;
    if (best.closure <= accepted) break;
  }
  StaticSolution solution(line, problem.supports.a_m, best.forces.x(), best.forces.y());
  solution.iterations = iterations;
  solution.closure_error_m = (solution.offset_m(line.length_m()) - chord).norm();
  if (!(best.closure <= accepted) || !best.forces.allFinite()) {
    solution.converged = false;
    solution.message = closure_failure(line, best, tolerance, iterations);
    // No equilibrium in tension is the input's fault (exit 2), like the other "No static
    // equilibrium" refusals; only a Newton failure stays a numerical failure (exit 3).
    if (best.forces.x() <= 1e-8 * weight_scale(line)) {
      throw InvalidInput("line.segments: " + solution.message);
    }
  }
  return solution;
}

}  // namespace catena
