// SPDX-License-Identifier: MIT
// Statics given to a solver must be the problem's: see catena/statics/statics_match.hpp. Statics of
// another geometry gave "converged" frequencies 30 % off through Python's statics= (issue 32).
#include "catena/statics/statics_match.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <string>

#include "catena/core/error.hpp"

namespace catena {
namespace {

// The first differing field as "<name> = <problem's> here, <statics'> in the statics", and what
// it belongs to ("another cable", "another line", "another seabed", "other supports").
class Differences {
 public:
  explicit Differences(std::string part) : part_(std::move(part)) {}
  void set_part(std::string part) { part_ = std::move(part); }
  void compare(const std::string& name, double here, double there) {
    // Equal values (validated finite or +inf): the statics copied the problem's value.
    if (first_ || here == there) return;
    mismatch(fmt::format("{} = {} here, {} in the statics", name, here, there));
  }
  void mismatch(std::string text) {
    if (first_) return;
    first_ = std::move(text);
    first_part_ = part_;
  }
  const std::optional<std::string>& first() const { return first_; }
  const std::string& first_part() const { return first_part_; }

 private:
  std::string part_;
  std::string first_part_;
  std::optional<std::string> first_;
};

void compare_segment(Differences& d,
                     const std::string& at,
                     const LineSegment& a,
                     const LineSegment& b) {
  d.compare(at + "length_m", a.length_m, b.length_m);
  d.compare(at + "weight_n_per_m", a.weight_n_per_m, b.weight_n_per_m);
  d.compare(at + "axial_stiffness_n", a.axial_stiffness_n, b.axial_stiffness_n);
  d.compare(at + "mass_kg_per_m", a.mass_kg_per_m, b.mass_kg_per_m);
  d.compare(at + "added_mass_kg_per_m", a.added_mass_kg_per_m, b.added_mass_kg_per_m);
  d.compare(at + "added_mass_tangential_kg_per_m", a.added_mass_tangential_kg_per_m,
            b.added_mass_tangential_kg_per_m);
  // Damping does not change the equilibrium, but a solver may take the line's dynamic
  // coefficients from the copy the statics holds (shooting does).
  d.compare(at + "damping.tangential_n_s_per_m2", a.damping.tangential_n_s_per_m2,
            b.damping.tangential_n_s_per_m2);
  d.compare(at + "damping.normal_n_s_per_m2", a.damping.normal_n_s_per_m2,
            b.damping.normal_n_s_per_m2);
  d.compare(at + "damping.axial_n_s", a.damping.axial_n_s, b.damping.axial_n_s);
  d.compare(at + "drag.diameter_m", a.drag.diameter_m, b.drag.diameter_m);
  d.compare(at + "drag.normal", a.drag.normal, b.drag.normal);
  d.compare(at + "drag.tangential", a.drag.tangential, b.drag.tangential);
}

void compare_point(Differences& d,
                   const std::string& at,
                   const PointAttachment& a,
                   const PointAttachment& b) {
  d.compare(at + "s_m", a.s_m, b.s_m);
  d.compare(at + "mass_kg", a.mass_kg, b.mass_kg);
  d.compare(at + "weight_n", a.weight_n, b.weight_n);
  d.compare(at + "added_mass_tangential_kg", a.tangential_added_mass_kg(),
            b.tangential_added_mass_kg());
  d.compare(at + "added_mass_normal_kg", a.normal_added_mass_kg(), b.normal_added_mass_kg());
  d.compare(at + "added_mass_outofplane_kg", a.outofplane_added_mass_kg(),
            b.outofplane_added_mass_kg());
}

void compare_line(Differences& d, const Problem& problem, const Line& there) {
  const Line here = problem.as_line();
  const bool uniform = problem.is_uniform();
  if (here.segments.size() != there.segments.size()) {
    d.mismatch(fmt::format("{} segment(s) here, {} in the statics", here.segments.size(),
                           there.segments.size()));
  }
  for (std::size_t i = 0; i < std::min(here.segments.size(), there.segments.size()); ++i) {
    compare_segment(d, uniform ? "cable." : fmt::format("line.segments[{}].", i), here.segments[i],
                    there.segments[i]);
  }
  if (here.points.size() != there.points.size()) {
    d.mismatch(fmt::format("{} point attachment(s) here, {} in the statics", here.points.size(),
                           there.points.size()));
  }
  for (std::size_t i = 0; i < std::min(here.points.size(), there.points.size()); ++i)
    compare_point(d, fmt::format("line.points[{}].", i), here.points[i], there.points[i]);
}

void compare_seabed(Differences& d, const Problem& problem, const StaticSolution& statics) {
  d.set_part("another seabed");
  if (problem.seabed.has_value() != statics.has_seabed()) {
    d.mismatch(fmt::format("seabed {} here, {} in the statics",
                           problem.seabed ? "present" : "absent",
                           statics.has_seabed() ? "present" : "absent"));
    return;
  }
  if (!problem.seabed) return;
  const Seabed &a = *problem.seabed, &b = statics.seabed();
  d.compare("seabed.z_m", a.z_m, b.z_m);
  d.compare("seabed.friction", a.friction, b.friction);
  d.compare("seabed.stiffness_n_per_m2", a.stiffness_n_per_m2, b.stiffness_n_per_m2);
  d.compare("seabed.tangential_stiffness_n_per_m2", a.tangential_stiffness_n_per_m2,
            b.tangential_stiffness_n_per_m2);
  d.compare("seabed.damping_n_s_per_m2", a.damping_n_s_per_m2, b.damping_n_s_per_m2);
}

// The supports: a is where the statics starts (copied, exact); b is where it ends, within its own
// closure error (a taut cable's tension is fixed by the chord only to about rounding / strain, so
// two chords within the closure have the same statics, and any farther apart do not).
void compare_supports(Differences& d, const Problem& problem, const StaticSolution& statics) {
  d.set_part("other supports");
  const double L = problem.length_m();
  const Vec2 chord = problem.supports.chord_m();
  constexpr double kRoundings = 64.0 * std::numeric_limits<double>::epsilon();
  const double rounding = kRoundings * std::max({L, chord.norm(), problem.supports.a_m.norm()});
  // r(0) is a plus the offset at s = 0, which a statics built from pieces may round to 1e-14.
  const Vec2 a = statics.position_m(0.0);
  if (!((a - problem.supports.a_m).norm() <= rounding)) {
    d.mismatch(fmt::format("supports.a_m = ({}, {}) m here, ({}, {}) m in the statics",
                           problem.supports.a_m.x(), problem.supports.a_m.y(), a.x(), a.y()));
  }
  const Vec2 end = statics.offset_m(L);
  const double tolerance = 2.0 * statics.closure_error_m + rounding;
  if (!((end - chord).norm() <= tolerance)) {
    const Vec2 b = problem.supports.a_m + end;
    d.mismatch(fmt::format(
        "supports.b_m = ({}, {}) m here, but the statics ends at ({}, {}) m ({:.3g} m apart, "
        "tolerance {:.3g} m: twice its closure error plus rounding)",
        problem.supports.b_m.x(), problem.supports.b_m.y(), b.x(), b.y(), (end - chord).norm(),
        tolerance));
  }
  if (problem.prescribed_forces) {
    d.set_part("other end forces");
    d.compare("prescribed_forces.horizontal_n", problem.prescribed_forces->horizontal_n,
              statics.horizontal_force_n());
    d.compare("prescribed_forces.vertical_a_n", problem.prescribed_forces->vertical_a_n,
              statics.vertical_force_a_n());
  }
}

}  // namespace

void check_statics_match(const Problem& problem, const StaticSolution& statics) {
  Differences d(problem.is_uniform() ? "another cable" : "another line");
  compare_line(d, problem, statics.line());
  compare_seabed(d, problem, statics);
  if (!d.first()) compare_supports(d, problem, statics);  // r(L) needs the same line
  if (d.first()) {
    throw InvalidInput(fmt::format(
        "statics: solved for {} than this problem's: {}; solve the statics of "
        "this problem (solve_statics(problem); in Python catena.solve_statics(problem))",
        d.first_part(), *d.first()));
  }
}

}  // namespace catena
