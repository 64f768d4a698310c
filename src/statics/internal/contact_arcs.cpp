// SPDX-License-Identifier: MIT
// The suspended arcs of a line in general seabed contact: see contact_arcs.hpp.
#include "statics/internal/contact_arcs.hpp"

#include <algorithm>
#include <cstddef>

#include "statics/internal/bisection.hpp"
#include "statics/internal/line_parts.hpp"
#include "statics/internal/line_pieces.hpp"

namespace catena::internal {
namespace {

// Samples of the scan for the first touchdown (and last lift-off) before the bisection: the
// height of an end arc is not monotone in its length when it holds a buoy, so the first sign
// change is looked for on a grid rather than assumed at one end.
constexpr int kScanSamples = 64;

// A candidate arc: which ends it holds and the buoyant stretches [first, first + count) it lifts.
struct Candidate {
  bool from_a = false;
  bool to_b = false;
  std::size_t first = 0;
  std::size_t count = 0;
};

enum class Fit { Ok, NeedsLeft, NeedsRight };

struct Solved {
  Fit fit = Fit::Ok;
  double s_begin = 0.0;
  double s_end = 0.0;
};

// r(b) - r(a) of the part [a, b] of the line started with the vertical force V_begin.
Vec2 arc_offset(const Line& line, double a, double b, double H, double V_begin) {
  if (!(b > a)) return Vec2::Zero();
  std::size_t first = 0;
  const Line part = line_between(line, a, b, first);
  return line_end_offset(build_line_pieces(part, H, V_begin), H);
}

struct ArcSolver {
  const ContactGeometry& geometry;
  const std::vector<BuoyantStretch>& stretches;
  double H;

  double length() const { return geometry.line.length_m(); }

  // Height above the seabed of the touchdown end of the arc [0, t] from A with V(t) = 0.
  double touchdown_height(double t) const {
    const double V_A = -weight_between(geometry.line, 0.0, t);
    const double height_a = geometry.anchor_on_seabed ? 0.0 : geometry.height_a_m;
    return height_a + arc_offset(geometry.line, 0.0, t, H, V_A).y();
  }
  // Height of B above the end of the arc [l, L] lifting off with V = 0, minus B's height.
  double reach_above_b(double l) const {
    return arc_offset(geometry.line, l, length(), H, 0.0).y() - geometry.height_b_m;
  }

  // The arc from A: the first t in (lo, hi] where it comes down to the seabed.
  Solved from_a(double lo, double hi) const {
    double previous = lo;
    for (int j = 1; j <= kScanSamples; ++j) {
      const double t = lo + (hi - lo) * j / kScanSamples;
      if (touchdown_height(t) <= 0.0) {
        const double touchdown =
            bisect(previous, t, [&](double s) { return touchdown_height(s) > 0.0; });
        return {Fit::Ok, 0.0, touchdown};
      }
      previous = t;
    }
    return {Fit::NeedsRight, 0.0, hi};
  }

  // The arc into B: the last l in [lo, hi) from which it reaches B's height.
  Solved to_b(double lo, double hi) const {
    double previous = hi;
    for (int j = 1; j <= kScanSamples; ++j) {
      const double l = hi - (hi - lo) * j / kScanSamples;
      if (reach_above_b(l) >= 0.0) {
        const double lift_off =
            bisect(l, previous, [&](double s) { return reach_above_b(s) >= 0.0; });
        return {Fit::Ok, lift_off, length()};
      }
      previous = l;
    }
    return {Fit::NeedsLeft, lo, length()};
  }

  Solved lifted(double lo, double hi, double f_begin, double f_end) const;
};

// An arc lifted by the buoyant stretches on [f_begin, f_end], with room [lo, hi] between its
// neighbours' buoyancy: it lifts off at l with V = 0 and touches down at t(l) where the weight of
// [l, t] is zero (V = 0 again); l is where t(l) is back on the seabed.
Solved ArcSolver::lifted(double lo, double hi, double f_begin, double f_end) const {
  const Line& line = geometry.line;
  // Weights are taken from just before f_begin and to just past f_end, so that a buoy at either
  // end of the buoyant stretch counts (weight_between leaves out points at its ends).
  const double margin = 2.0 * merge_distance(line);
  const double before = std::max(f_begin - margin, lo);
  const double past = std::min(f_end + margin, hi);
  // Largest l <= f_begin with weight(l, s_end) >= 0 (chain before the buoyancy balances it).
  auto balancing_start = [&](double s_end) {
    if (weight_between(line, before, s_end) >= 0.0) return before;
    return bisect(lo, before, [&](double l) { return weight_between(line, l, s_end) >= 0.0; });
  };
  // Not enough weight before the buoyancy to hold it down: it lifts the arc before it too.
  if (weight_between(line, lo, past) < 0.0) return {Fit::NeedsLeft, lo, f_end};
  const double l_lo = balancing_start(past);
  const double l_hi = balancing_start(hi);
  auto touchdown = [&](double l) {
    if (weight_between(line, l, past) >= 0.0) return past;
    return bisect(past, hi, [&](double s) { return weight_between(line, l, s) < 0.0; });
  };
  auto end_height = [&](double l) { return arc_offset(line, l, touchdown(l), H, 0.0).y(); };
  if (end_height(l_hi) > 0.0) return {Fit::NeedsRight, l_hi, hi};
  if (!(end_height(l_lo) > 0.0)) return {Fit::NeedsLeft, lo, f_end};
  const double l = bisect(l_lo, l_hi, [&](double s) { return end_height(s) > 0.0; });
  return {Fit::Ok, l, touchdown(l)};
}

// Solves candidate i of `candidates` between its neighbours' buoyancy.
Solved solve_candidate(const ArcSolver& solver,
                       const std::vector<Candidate>& candidates,
                       std::size_t i) {
  const Candidate& c = candidates[i];
  const auto& stretches = solver.stretches;
  // The neighbours' buoyant stretches bound the room of this arc.
  double lo = 0.0;
  for (std::size_t j = i; j-- > 0;) {
    if (candidates[j].count > 0) {
      lo = stretches[candidates[j].first + candidates[j].count - 1].s_end_m;
      break;
    }
  }
  double hi = solver.length();
  for (std::size_t j = i + 1; j < candidates.size(); ++j) {
    if (candidates[j].count > 0) {
      hi = stretches[candidates[j].first].s_begin_m;
      break;
    }
  }
  const double f_begin = c.count > 0 ? stretches[c.first].s_begin_m : hi;
  const double f_end = c.count > 0 ? stretches[c.first + c.count - 1].s_end_m : lo;
  if (c.from_a) return solver.from_a(f_end, hi * (1.0 - 1e-12));
  if (c.to_b) return solver.to_b(lo, f_begin);
  return solver.lifted(lo, hi, f_begin, f_end);
}

// Merges candidates i and i + 1; false when the merged arc runs from A to B (no contact).
bool merge(std::vector<Candidate>& candidates, std::size_t i) {
  Candidate& left = candidates[i];
  const Candidate& right = candidates[i + 1];
  left.from_a = left.from_a || right.from_a;
  left.to_b = left.to_b || right.to_b;
  if (left.count == 0) left.first = right.first;
  left.count += right.count;
  candidates.erase(candidates.begin() + static_cast<std::ptrdiff_t>(i) + 1);
  return !(left.from_a && left.to_b);
}

}  // namespace

std::vector<BuoyantStretch> buoyant_stretches(const Line& line) {
  std::vector<BuoyantStretch> found;
  for (std::size_t k = 0; k < line.segments.size(); ++k) {
    if (line.segments[k].weight_n_per_m < 0.0) {
      found.push_back({line.segment_start_m(k), line.segment_start_m(k + 1)});
    }
  }
  for (const PointAttachment& point : line.points) {
    if (point.weight_n < 0.0) found.push_back({point.s_m, point.s_m});
  }
  std::sort(found.begin(), found.end(), [](const BuoyantStretch& a, const BuoyantStretch& b) {
    return a.s_begin_m < b.s_begin_m;
  });
  std::vector<BuoyantStretch> merged;
  const double touch = merge_distance(line);
  for (const BuoyantStretch& stretch : found) {
    if (!merged.empty() && stretch.s_begin_m <= merged.back().s_end_m + touch) {
      merged.back().s_end_m = std::max(merged.back().s_end_m, stretch.s_end_m);
    } else {
      merged.push_back(stretch);
    }
  }
  return merged;
}

std::optional<std::vector<ContactArc>> contact_arcs(const ContactGeometry& geometry,
                                                    const std::vector<BuoyantStretch>& stretches,
                                                    double H) {
  std::vector<Candidate> candidates;
  if (!geometry.anchor_on_seabed) candidates.push_back({true, false, 0, 0});
  for (std::size_t i = 0; i < stretches.size(); ++i) candidates.push_back({false, false, i, 1});
  candidates.push_back({false, true, 0, 0});
  const ArcSolver solver{geometry, stretches, H};
  // Each pass solves every arc in its room, then merges the first pair that does not fit (an arc
  // that needs the room of its neighbour, or two that overlap); merges only shrink the list.
  for (;;) {
    std::vector<Solved> solved;
    for (std::size_t i = 0; i < candidates.size(); ++i)
      solved.push_back(solve_candidate(solver, candidates, i));
    bool changed = false;
    for (std::size_t i = 0; i < candidates.size() && !changed; ++i) {
      const bool overlaps = i + 1 < candidates.size() && solved[i].fit == Fit::Ok &&
                            solved[i + 1].fit == Fit::Ok &&
                            solved[i].s_end >= solved[i + 1].s_begin;
      if (solved[i].fit == Fit::NeedsLeft && i == 0) {
        // Only a lifted arc (or the arc into B) can need room before the first arc: it lifts the
        // anchor off the seabed.
        candidates[0].from_a = true;
        if (candidates[0].to_b) return std::nullopt;
        changed = true;
      } else if (solved[i].fit == Fit::NeedsLeft) {
        if (!merge(candidates, i - 1)) return std::nullopt;
        changed = true;
      } else if (solved[i].fit == Fit::NeedsRight || overlaps) {
        if (!merge(candidates, i)) return std::nullopt;
        changed = true;
      }
    }
    if (changed) continue;
    std::vector<ContactArc> arcs;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      arcs.push_back(
          {solved[i].s_begin, solved[i].s_end, candidates[i].from_a, candidates[i].to_b});
    }
    return arcs;
  }
}

}  // namespace catena::internal
