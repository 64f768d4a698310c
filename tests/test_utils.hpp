#pragma once
// Shared test helpers: relative errors measured the same way everywhere, the location of the
// reference tables, and the check that bad input names its field.

#include <algorithm>
#include <boost/math/special_functions/relative_difference.hpp>
#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <limits>
#include <string>

#include "catena/core/error.hpp"
#include "catena/models/cable.hpp"

namespace catena::testing {

/// `uniform`'s cable written as a line of `pieces` identical segments (same ends): the anchor that a
/// split line reproduces the one-segment result (docs/physics.md, "General lines").
inline Problem split_into_segments(const Problem& uniform, int pieces) {
  Problem p = uniform;
  const CableProperties& c = uniform.cable;
  for (int i = 0; i < pieces; ++i) {
    p.line.segments.push_back({c.length_m / pieces, c.weight_n_per_m, c.axial_stiffness_n, c.mass_kg_per_m,
                               c.added_mass_kg_per_m});
  }
  return p;
}

/// Symmetric relative difference (Boost.Math); infinite when one value is non-finite.
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

}  // namespace catena::testing
