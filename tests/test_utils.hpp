// SPDX-License-Identifier: MIT
#pragma once
// Shared test helpers: relative errors measured the same way everywhere, the location of the
// reference tables, and the check that bad input names its field.

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/special_functions/relative_difference.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/models/cable.hpp"

namespace catena::testing {

/// `uniform`'s cable written as a line of `pieces` identical segments (same ends): the anchor that
/// a split line reproduces the one-segment result (docs/explanation/physics.md, "General lines").
inline Problem split_into_segments(const Problem& uniform, int pieces) {
  Problem p = uniform;
  const CableProperties& c = uniform.cable;
  for (int i = 0; i < pieces; ++i) {
    p.line.segments.push_back({c.length_m / pieces, c.weight_n_per_m, c.axial_stiffness_n,
                               c.mass_kg_per_m, c.added_mass_kg_per_m});
  }
  return p;
}

/// Symmetric relative difference (Boost.Math); infinite when one value is non-finite.
// The seabed tests' chain (tests/statics/seabed_statics_test.cpp): 1000 m in 200 m of water with
// 40 % of its length on the seabed, Coulomb friction `friction` and vertical foundation `k_s`.
inline Problem forty_percent_grounded_chain(double friction, double k_s) {
  Problem p;
  p.cable = {1000.0, 1200.0, 8e8, 150.0, 20.0};
  p.supports.a_m = Vec2(0.0, -200.0);
  p.supports.b_m = Vec2(955.85, 0.0);
  p.seabed = Seabed{-200.0, friction, k_s, 0.0};
  return p;
}

inline double relative_error(double a, double b) { return boost::math::relative_difference(a, b); }

/// -log10(relative error), capped at 16.
inline double digits_of_agreement(double a, double b) {
  const double error = relative_error(a, b);
  return error == 0.0 ? 16.0 : std::min(16.0, -std::log10(error));
}

/// verification/reference/published/<name>
inline std::string published_table(const std::string& name) {
  return std::string(CATENA_REFERENCE_DIR) + "/published/" + name;
}

/// Expects `action` to throw InvalidInput whose message contains `word` (the field it names).
inline void expect_invalid(const std::function<void()>& action, const std::string& word) {
  try {
    action();
    ADD_FAILURE() << "no InvalidInput; expected a message with '" << word << "'";
  } catch (const InvalidInput& error) {
    EXPECT_NE(std::string(error.what()).find(word), std::string::npos) << error.what();
  }
}

/// The first `count` roots of a continuous `f` on (0, top]: sign changes on a grid of `steps`
/// intervals, each bisected to rounding. The caller checks the count it got, so a root pair that
/// the grid cannot separate shows as a missing root, not as a wrong one.
inline std::vector<double> roots_by_bisection(const std::function<double(double)>& f,
                                              double top,
                                              int count,
                                              int steps = 200000) {
  std::vector<double> out;
  double a = top / steps, fa = f(a);
  for (int i = 2; i <= steps && static_cast<int>(out.size()) < count; ++i) {
    const double b = top * i / steps, fb = f(b);
    if ((fa < 0.0) != (fb < 0.0)) {
      double lo = a, hi = b;
      const bool lo_negative = fa < 0.0;
      for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        ((f(mid) < 0.0) == lo_negative ? lo : hi) = mid;
      }
      out.push_back(0.5 * (lo + hi));
    }
    a = b;
    fa = fb;
  }
  return out;
}

}  // namespace catena::testing
