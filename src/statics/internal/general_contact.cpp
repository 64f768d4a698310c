// SPDX-License-Identifier: MIT
// The statics of a line in general seabed contact: see general_contact.hpp.
#include "statics/internal/general_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "catena/core/error.hpp"
#include "statics/internal/bisection.hpp"
#include "statics/internal/contact_arcs.hpp"
#include "statics/internal/contact_pieces.hpp"
#include "statics/internal/line_parts.hpp"
#include "statics/internal/line_pieces.hpp"

namespace catena::internal {
namespace {

// The contact equations of one problem: the pieces at a trial H.
struct GeneralContact {
  ContactGeometry geometry;
  std::vector<BuoyantStretch> stretches;
  double friction = 0.0;
  double seabed_offset_z_m = 0.0;
  Vec2 chord_m = Vec2::Zero();
  // Evaluations of the reach residual: reported as the iterations.
  mutable int evaluations = 0;

  std::optional<ContactPieces> pieces(double H, double heap_length_m) const {
    const auto arcs = contact_arcs(geometry, stretches, H);
    if (!arcs) return std::nullopt;
    return build_contact_pieces(geometry, friction, seabed_offset_z_m, H, *arcs, heap_length_m);
  }
  // Horizontal miss of B with force H; +inf when the line hangs free at this H (H too large).
  double reach_residual(double H) const {
    ++evaluations;
    const auto built = pieces(H, 0.0);
    if (!built) return kInfinity;
    return line_end_offset(built->pieces, H).x() - chord_m.x();
  }
};

// H of the contact solution (increasing reach in H), after bracketing it by doubling and halving
// from the line's weight; 0 when even H -> 0 reaches past B (a slack line).
double horizontal_force(const GeneralContact& system) {
  double hi = std::max(weight_scale(system.geometry.line), 1.0);
  for (int i = 0; i < 200 && !(system.reach_residual(hi) > 0.0); ++i) hi *= 2.0;
  if (!(system.reach_residual(hi) > 0.0)) {
    throw InvalidInput(fmt::format(
        "seabed: no equilibrium with seabed contact found: the line (L = {:.10g} m) does not reach "
        "end B at any horizontal force up to {:.6g} N (a configuration outside the model)",
        system.geometry.line.length_m(), hi));
  }
  double lo = hi;
  for (int i = 0; i < 120 && system.reach_residual(lo) >= 0.0; ++i) lo *= 0.5;
  if (system.reach_residual(lo) >= 0.0) return 0.0;
  return bisect(lo, hi, [&](double H) { return system.reach_residual(H) < 0.0; });
}

// The slack line (H = 0): its grounded length beyond the span lies in a heap at the foot of the
// part hanging from B.
ContactPieces slack_pieces(const GeneralContact& system) {
  if (!system.stretches.empty()) {
    throw InvalidInput(fmt::format(
        "seabed: a slack line (H = 0: longer than its span plus its hanging parts) with a buoy or "
        "a buoyant segment (at s = {:.6g} m) is not supported: with no horizontal force its lifted "
        "arc would fold on itself",
        system.stretches.front().s_begin_m));
  }
  const auto laid = system.pieces(0.0, 0.0);
  if (!laid) throw InvalidInput("seabed: a slack line that does not reach the seabed");
  const double excess = line_end_offset(laid->pieces, 0.0).x() - system.chord_m.x();
  return *system.pieces(0.0, std::max(excess, 0.0));
}

// The vertical force where a suspended piece meets a grounded one: 0 for a tangential contact.
double contact_vertical_force(const StaticPiece& before, const StaticPiece& after) {
  if (before.grounded && !after.grounded) return after.vertical_begin_n;
  if (!before.grounded && after.grounded) {
    return before.vertical_begin_n + before.section.weight_n_per_m * before.section.length_m;
  }
  return 0.0;
}

// The result's conditions: positive weight on the seabed, tangential contact, nothing below.
void check_contact(const StaticSolution& solution, const Line& line, double tolerance) {
  const std::vector<StaticPiece>& pieces = solution.pieces();
  const double force_tolerance = 1e-9 * std::max(weight_scale(line), 1.0);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const StaticPiece& piece = pieces[i];
    if (piece.grounded && !(piece.section.weight_n_per_m > 0.0)) {
      throw InvalidInput(fmt::format(
          "Invalid line.segments[{}]: seabed contact with a buoyant or weightless segment on the "
          "grounded part (weight {} N/m at s = {:.6g} m) is not supported",
          piece.segment, piece.section.weight_n_per_m, piece.s_begin_m));
    }
    if (i == 0) continue;
    const double V = contact_vertical_force(pieces[i - 1], piece);
    if (!(std::abs(V) <= force_tolerance)) {
      throw InvalidInput(fmt::format(
          "seabed: the line meets the seabed at s = {:.6g} m with a vertical force {:.6g} N, at an "
          "angle (a point weight at the touchdown or lift-off point): not supported",
          piece.s_begin_m, V));
    }
  }
  for (std::size_t i = 0; i < line.points.size(); ++i) {
    if (line.points[i].weight_n < 0.0 && solution.grounded_at(line.points[i].s_m)) {
      throw InvalidInput(fmt::format(
          "Invalid line.points[{}]: a buoy on the grounded part (s = {:.6g} m) is not supported", i,
          line.points[i].s_m));
    }
  }
  const double s_low = solution.lowest_point_s_m();
  const double below = solution.seabed().z_m - solution.position_m(s_low).y();
  if (below > tolerance) {
    throw InvalidInput(fmt::format(
        "seabed: the suspended line would pass {:.6g} m below the seabed at s = {:.6g} m: a "
        "configuration outside the model of tangential contact (not supported)",
        below, s_low));
  }
}

}  // namespace

StaticSolution solve_general_contact(const Problem& problem, const StaticsOptions& options) {
  const Line line = problem.as_line();
  const Seabed& seabed = *problem.seabed;
  const Vec2 a = problem.supports.a_m;
  const Vec2 chord = problem.supports.chord_m();
  const double tolerance = 1e-9 * std::max(1.0, std::abs(seabed.z_m));
  const bool anchor_on_seabed = std::abs(a.y() - seabed.z_m) <= tolerance;
  GeneralContact system{ContactGeometry{line, a.y() - seabed.z_m,
                                        problem.supports.b_m.y() - seabed.z_m, anchor_on_seabed},
                        buoyant_stretches(line), seabed.friction, seabed.z_m - a.y(), chord};
  const double H = horizontal_force(system);
  ContactPieces built;
  if (H > 0.0) {
    auto found = system.pieces(H, 0.0);
    if (!found) throw InvalidInput("seabed: no equilibrium with seabed contact found");
    built = std::move(*found);
  } else {
    built = slack_pieces(system);
  }
  StaticSolution solution(line, a, seabed, H, std::move(built.pieces));
  const double scale = std::max(line.length_m(), chord.norm());
  solution.iterations = system.evaluations;
  solution.closure_error_m =
      std::max((solution.offset_m(line.length_m()) - chord).norm(), built.touchdown_miss_m);
  check_contact(solution, line, 1e-9 * std::max(1.0, scale));
  const double accepted = std::max(options.relative_tolerance * scale, 1e-11 * scale);
  if (!(solution.closure_error_m <= accepted) || !std::isfinite(H)) {
    solution.converged = false;
    solution.message = fmt::format(
        "Statics on the seabed did not converge: closure error {:.3e} m > {:.3e} m (H = {:.6g} N, "
        "grounded length {:.6g} m)",
        solution.closure_error_m, accepted, H, solution.grounded_length_m());
  }
  return solution;
}

}  // namespace catena::internal
