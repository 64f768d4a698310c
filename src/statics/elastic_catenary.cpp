// SPDX-License-Identifier: MIT
#include "catena/statics/elastic_catenary.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "catena/core/error.hpp"
#include "catena/statics/line_statics.hpp"
#include "catena/statics/seabed_statics.hpp"
#include "statics/internal/catenary_segment.hpp"
#include "statics/internal/line_pieces.hpp"
#include "statics/internal/seabed_pieces.hpp"

namespace catena {
namespace {

using internal::asinh_difference;
using internal::inverse_stiffness;
using internal::offset;
using internal::offset_jacobian;

StaticSolution solve_vertical(const Problem& problem) {
  const CableProperties& cable = problem.cable;
  const double L = cable.length_m;
  const double W0 = cable.weight_n_per_m;
  const double dz = problem.supports.chord_m().y();
  const double direction = dz > 0.0 ? 1.0 : -1.0;
  const double compliance = inverse_stiffness(cable);
  // Straight vertical cable: z(L) = direction L + (V_A L + W0 L^2/2)/EA.
  const double mismatch = dz - direction * L;
  if (compliance == 0.0) {
    throw InvalidInput(fmt::format(
        "No static equilibrium for an inextensible cable on a vertical chord: |dz| = {} m, "
        "L = {} m (it hangs straight only when |dz| = L, and then its tension is indeterminate); "
        "give a finite EA or a horizontal offset between the supports",
        std::abs(dz), L));
  }
  const double V_A = mismatch / (L * compliance) - 0.5 * W0 * L;
  const double V_B = V_A + W0 * L;
  const bool taut = direction > 0.0 ? V_A > 0.0 : V_B < 0.0;
  if (!taut) {
    throw InvalidInput(fmt::format(
        "No straight equilibrium for a vertical chord: |dz| = {} m with L = {} m, EA = {} N leaves "
        "the cable slack (it would fold on itself); vertical cables must be taut along their "
        "whole length",
        std::abs(dz), L, cable.axial_stiffness_n));
  }
  StaticSolution solution(cable, problem.supports.a_m, 0.0, V_A);
  solution.iterations = 1;
  solution.closure_error_m = (solution.offset_m(L) - problem.supports.chord_m()).norm();
  return solution;
}

// Tension-specified: the state is given; the closure error against support b is checked.
StaticSolution solve_prescribed(const Problem& problem) {
  const EndForces& forces = *problem.prescribed_forces;
  if (!std::isfinite(forces.horizontal_n) || forces.horizontal_n < 0.0 ||
      !std::isfinite(forces.vertical_a_n)) {
    throw InvalidInput(fmt::format(
        "Invalid Problem::prescribed_forces = (H = {}, V_A = {}): H must be finite and >= 0, "
        "V_A finite [N]",
        forces.horizontal_n, forces.vertical_a_n));
  }
  const double L = problem.cable.length_m;
  const Vec2 chord = problem.supports.chord_m();
  StaticSolution solution(problem.cable, problem.supports.a_m, forces.horizontal_n,
                          forces.vertical_a_n);
  solution.iterations = 0;
  solution.closure_error_m = (solution.offset_m(L) - chord).norm();
  if (!(solution.closure_error_m <= 1e-9 * std::max(L, chord.norm()))) {
    throw InvalidInput(fmt::format(
        "Invalid Problem::prescribed_forces: the forces (H = {}, V_A = {}) put the end of the "
        "cable {:.3e} m away from support b",
        forces.horizontal_n, forces.vertical_a_n, solution.closure_error_m));
  }
  return solution;
}

// Initial guess (after Peyrot & Goulois 1979): parabolic sag for a slack cable; a straight
// stretched estimate when the chord exceeds L (possible only when EA is finite). Returns (H, V_A).
Vec2 initial_end_forces(const CableProperties& cable, const Vec2& chord) {
  const double L = cable.length_m;
  const double W0 = cable.weight_n_per_m;
  const double dx = chord.x();
  const double dz = chord.y();
  const double d = chord.norm();
  const double slack_ratio = (L * L - dz * dz) / (dx * dx) - 1.0;
  const double lambda0 = slack_ratio > 0.0 ? std::sqrt(3.0 * slack_ratio) : 0.2;
  double H = std::abs(W0 * dx / (2.0 * std::max(lambda0, 1e-6)));
  if (!cable.is_inextensible() && d > L) {
    const double stretched_tension = cable.axial_stiffness_n * (d / L - 1.0);
    H = std::max(H, stretched_tension * dx / d);
  }
  return {H, H * dz / dx - 0.5 * W0 * L};
}

// Newton on (H, V_A) with the analytic Jacobian and a backtracking line search that keeps H > 0.
// A stall is reported in the solution (converged = false), never thrown.
StaticSolution solve_newton(const Problem& problem, const StaticsOptions& options) {
  const CableProperties& cable = problem.cable;
  const double L = cable.length_m;
  const Vec2 chord = problem.supports.chord_m();
  const double d = chord.norm();
  Vec2 forces = initial_end_forces(cable, chord);
  double& H = forces.x();
  double& V_A = forces.y();

  const double tolerance = options.relative_tolerance * std::max(L, d);
  auto residual = [&](double h, double v) { return (offset(cable, h, v, L) - chord).eval(); };
  Vec2 r = residual(H, V_A);
  int iteration = 0;
  for (; iteration < options.max_iterations && r.norm() > tolerance; ++iteration) {
    const Eigen::Matrix2d J = offset_jacobian(cable, H, V_A);
    const Vec2 step = J.fullPivLu().solve(-r);
    if (!step.allFinite()) break;
    // Backtracking: keep H > 0 (the catenary is undefined otherwise) and decrease |r|.
    double alpha = 1.0;
    bool accepted = false;
    for (int halving = 0; halving < 60; ++halving, alpha *= 0.5) {
      const double H_trial = H + alpha * step.x();
      if (!(H_trial > 0.0)) continue;
      const double V_trial = V_A + alpha * step.y();
      const Vec2 r_trial = residual(H_trial, V_trial);
      if (r_trial.allFinite() && r_trial.norm() < (1.0 - 1e-4 * alpha) * r.norm()) {
        H = H_trial;
        V_A = V_trial;
        r = r_trial;
        accepted = true;
        break;
      }
    }
    if (!accepted) break;
  }
  StaticSolution solution(cable, problem.supports.a_m, H, V_A);
  solution.iterations = iteration;
  solution.closure_error_m = r.norm();
  // Newton can stall a few ulps above a very tight tolerance: the closure is then at the rounding
  // floor of evaluating r(L), which is accepted (and reported as the closure error).
  const double rounding_floor = 1e-11 * std::max(L, d);
  if (!(r.norm() <= std::max(tolerance, rounding_floor)) || !std::isfinite(H) ||
      !std::isfinite(V_A)) {
    solution.converged = false;
    solution.message = fmt::format(
        "Statics did not converge: closure error {:.3e} m > {:.3e} m after {} Newton iterations "
        "(H = {:.6g} N, V_A = {:.6g} N)",
        r.norm(), tolerance, iteration, H, V_A);
  }
  return solution;
}

}  // namespace

void StaticsOptions::validate() const {
  if (!(relative_tolerance > 0.0 && relative_tolerance <= 1e-3)) {
    throw InvalidInput(
        fmt::format("Invalid StaticsOptions::relative_tolerance = {}: must be in (0, 1e-3]",
                    relative_tolerance));
  }
  if (max_iterations < 1) {
    throw InvalidInput(
        fmt::format("Invalid StaticsOptions::max_iterations = {}: must be >= 1", max_iterations));
  }
}

StaticSolution::StaticSolution(const CableProperties& cable, const Vec2& a_m, double H, double V_A)
    : cable_(cable), a_m_(a_m), H_(H), V_A_(V_A) {}

StaticSolution::StaticSolution(const Line& line, const Vec2& a_m, double H, double V_A)
    : line_(line), pieces_(internal::build_line_pieces(line, H, V_A)), a_m_(a_m), H_(H), V_A_(V_A) {
  // cable() of a general line carries its total length; the sections are per piece.
  cable_ = pieces_.front().section;
  cable_.length_m = line.length_m();
}

StaticSolution::StaticSolution(
    const Line& line, const Vec2& a_m, const Seabed& seabed, double H, double grounded_length_m)
    : line_(line),
      pieces_(internal::build_seabed_pieces(
          line, seabed.friction, seabed.z_m - a_m.y(), H, grounded_length_m)),
      a_m_(a_m),
      H_(H),
      V_A_(grounded_length_m > 0.0 ? 0.0 : pieces_.front().vertical_begin_n),
      seabed_(seabed),
      grounded_length_m_(grounded_length_m) {
  cable_ = pieces_.front().section;
  cable_.length_m = line.length_m();
}

StaticSolution::StaticSolution(const Line& line,
                               const Vec2& a_m,
                               const Seabed& seabed,
                               double H,
                               std::vector<StaticPiece> pieces)
    : line_(line), pieces_(std::move(pieces)), a_m_(a_m), H_(H), seabed_(seabed) {
  cable_ = pieces_.front().section;
  cable_.length_m = line.length_m();
  V_A_ = pieces_.front().grounded ? 0.0 : pieces_.front().vertical_begin_n;
  for (const StaticPiece& piece : pieces_)
    if (piece.grounded) grounded_length_m_ += piece.section.length_m;
}

std::vector<ContactInterval> StaticSolution::contact_intervals() const {
  std::vector<ContactInterval> intervals;
  bool previous_grounded = false;
  for (const StaticPiece& piece : pieces_) {
    const double end = piece.s_begin_m + piece.section.length_m;
    if (piece.grounded && previous_grounded) intervals.back().s_end_m = end;
    if (piece.grounded && !previous_grounded) intervals.push_back({piece.s_begin_m, end});
    previous_grounded = piece.grounded;
  }
  return intervals;
}

double StaticSolution::slack_length_m() const {
  double length = 0.0;
  for (const StaticPiece& piece : pieces_)
    if (piece.slack_heap) length += piece.section.length_m;
  return length;
}

double StaticSolution::anchor_horizontal_force_n() const {
  if (!anchor_grounded()) return H_;
  return internal::grounded_tension(pieces_.front(), 0.0);
}

const StaticPiece& StaticSolution::piece_at(double s) const {
  auto after = std::upper_bound(
      pieces_.begin(), pieces_.end(), s,
      [](double value, const StaticPiece& piece) { return value < piece.s_begin_m; });
  return after == pieces_.begin() ? pieces_.front() : *(after - 1);
}

LineSegment StaticSolution::segment_at(double s) const {
  if (!is_line()) return line_of_cable(cable_).segments.front();
  return line_.segments[piece_at(s).segment];
}

double StaticSolution::vertical_force_n(double s) const {
  if (!is_line()) return V_A_ + cable_.weight_n_per_m * s;
  const StaticPiece& piece = piece_at(s);
  if (piece.grounded) return 0.0;
  return piece.vertical_begin_n + piece.section.weight_n_per_m * (s - piece.s_begin_m);
}

double StaticSolution::vertical_force_before_n(double s) const {
  if (!is_line()) return vertical_force_n(s);
  auto at = std::lower_bound(
      pieces_.begin(), pieces_.end(), s,
      [](const StaticPiece& piece, double value) { return piece.s_begin_m < value; });
  const StaticPiece& piece = at == pieces_.begin() ? pieces_.front() : *(at - 1);
  if (piece.grounded) return 0.0;
  return piece.vertical_begin_n + piece.section.weight_n_per_m * (s - piece.s_begin_m);
}

double StaticSolution::lowest_point_s_m() const {
  // Candidates: the ends of every piece and, inside a sagging piece, where V changes sign.
  const double L = cable_.length_m;
  double best_s = 0.0;
  double best_z = position_m(0.0).y();
  auto consider = [&](double s) {
    const double z = position_m(s).y();
    if (z < best_z) best_z = z, best_s = s;
  };
  consider(L);
  const std::vector<StaticPiece> whole{StaticPiece{cable_, 0, 0.0, V_A_, Vec2::Zero(), 0.0}};
  for (const StaticPiece& piece : is_line() ? pieces_ : whole) {
    consider(piece.s_begin_m);
    const double W = piece.section.weight_n_per_m;
    if (W <= 0.0 || piece.vertical_begin_n >= 0.0) continue;
    const double apex = piece.s_begin_m - piece.vertical_begin_n / W;
    if (apex < piece.s_begin_m + piece.section.length_m) consider(apex);
  }
  return best_s;
}

double StaticSolution::tension_n(double s) const {
  if (has_contact()) {
    const StaticPiece& piece = piece_at(s);
    if (piece.grounded) return internal::grounded_tension(piece, s - piece.s_begin_m);
  }
  return std::hypot(H_, vertical_force_n(s));
}

double StaticSolution::strain(double s) const {
  if (is_line()) return tension_n(s) * inverse_stiffness(piece_at(s).section);
  return tension_n(s) * inverse_stiffness(cable_);
}

double StaticSolution::angle_rad(double s) const {
  const double V = vertical_force_n(s);
  if (std::hypot(H_, V) > 0.0) return std::atan2(V, H_);
  const Vec2 t = tangent(s);
  return std::atan2(t.y(), t.x());
}

Vec2 StaticSolution::tangent(double s) const {
  if (has_contact() && piece_at(s).grounded) return {1.0, 0.0};
  const double T = std::hypot(H_, vertical_force_n(s));
  if (!(T > 0.0)) {
    // Zero tension on a suspended piece: only at V = 0 on a vertical part (H = 0), which leaves
    // upward when it weighs (V grows along it) and downward when it floats.
    const double W = is_line() ? piece_at(s).section.weight_n_per_m : cable_.weight_n_per_m;
    return {0.0, W < 0.0 ? -1.0 : 1.0};
  }
  return {H_ / T, vertical_force_n(s) / T};
}

Vec2 StaticSolution::normal(double s) const {
  const Vec2 t = tangent(s);
  return {-t.y(), t.x()};
}

Vec2 StaticSolution::offset_m(double s) const {
  if (!is_line()) return offset(cable_, H_, V_A_, s);
  const StaticPiece& piece = piece_at(s);
  if (piece.grounded) {
    if (piece.slack_heap) return piece.offset_begin_m;
    const double ds = s - piece.s_begin_m;
    return piece.offset_begin_m + Vec2(internal::grounded_stretched_increment(piece, ds), 0.0);
  }
  return piece.offset_begin_m +
         offset(piece.section, H_, piece.vertical_begin_n, s - piece.s_begin_m);
}

double StaticSolution::stretched_length_m(double s) const {
  if (!is_line()) return internal::stretched_increment(cable_, H_, V_A_, s);
  const StaticPiece& piece = piece_at(s);
  if (piece.grounded) {
    return piece.stretched_begin_m +
           internal::grounded_stretched_increment(piece, s - piece.s_begin_m);
  }
  return piece.stretched_begin_m + internal::stretched_increment(piece.section, H_,
                                                                 piece.vertical_begin_n,
                                                                 s - piece.s_begin_m);
}

std::string StaticSolution::brief_report() const {
  const double L = cable_.length_m;
  std::string text = fmt::format(
      "H = {:.10g} N, V_A = {:.10g} N, T_A = {:.10g} N, T_B = {:.10g} N, {} Newton iterations, "
      "closure error {:.2e} m",
      H_, V_A_, tension_n(0.0), tension_n(L), iterations, closure_error_m);
  if (has_seabed()) text += fmt::format(", grounded length {:.10g} m", grounded_length_m_);
  return text;
}

Vec2 catenary_end_offset(const CableProperties& cable, double H, double V_A) {
  return offset(cable, H, V_A, cable.length_m);
}

StaticSolution solve_statics(const Problem& problem, const StaticsOptions& options) {
  problem.validate();
  options.validate();
  if (problem.seabed) return solve_seabed_statics(problem, options);
  if (!problem.is_uniform()) return solve_line_statics(problem, options);
  const CableProperties& cable = problem.cable;
  const Vec2 chord = problem.supports.chord_m();
  const double d = chord.norm();
  if (problem.prescribed_forces) return solve_prescribed(problem);
  if (chord.x() <= 1e-14 * d) return solve_vertical(problem);
  if (cable.is_inextensible() && cable.length_m <= d * (1.0 + 1e-14)) {
    throw InvalidInput(fmt::format(
        "No static equilibrium: the chord |b - a| = {:.10g} m is {} the inextensible cable length "
        "L = {:.10g} m (the ends are farther apart than the cable can reach)",
        d, cable.length_m < d ? "longer than" : "equal to", cable.length_m));
  }
  return solve_newton(problem, options);
}

}  // namespace catena
