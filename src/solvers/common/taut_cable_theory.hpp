// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// What the two analytic solvers (asymptotic and airy) share about a taut, slightly stretched
/// cable (docs/explanation/methods/asymptotic.md, docs/explanation/methods/airy.md): the
/// small-strain limit both linearise about and the knobs both declare. Static quantities only:
/// neither solver's frequencies or shapes are computed here (asymptotic's out-of-plane WKB string
/// is in asymptotic_wkb_string.hpp, airy's Bessel string in airy_tension_string.hpp), so the two
/// stay independent witnesses.

#include <string>
#include <vector>

#include "catena/models/cable.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "solvers/common/knob_table.hpp"

namespace catena::internal {

/// Static strain e0 = T0/EA at the point of chord angle (0 when inextensible). Both analytic
/// models linearise about a slightly stretched string: they neglect e0 in k = omega/sqrt(T0/M)
/// (model error e0/2) and do not apply above kMaxStaticStrain.
double static_strain(const Problem& problem, const DimensionlessGroups& groups);
inline constexpr double kMaxStaticStrain = 0.1;

/// The knobs both analytic solvers declare alike: the eps of a validity warning, the eps above
/// which they decline, and the Gauss-Legendre panels of a travel-time integral (`what`).
template <class Options>
std::vector<KnobBinding<Options>> taut_theory_knobs(const std::string& what) {
  return {real_knob("eps_warning_threshold", &Options::eps_warning_threshold,
                    Range::open_closed(0.0, 10.0),
                    "eps above which a validity warning is given (at most max_eps)"),
          real_knob("max_eps", &Options::max_eps, Range::open_closed(0.0, 10.0),
                    "eps above which the solver declines"),
          integer_knob("quadrature_panels", &Options::quadrature_panels, Range::closed(1, 1000),
                       "panels of 20-point Gauss-Legendre for " + what)};
}

/// Throws InvalidInput naming `[solvers.<solver>].eps_warning_threshold` unless it is <= max_eps.
void require_warning_below_max_eps(const std::string& solver,
                                   double eps_warning_threshold,
                                   double max_eps);

}  // namespace catena::internal
