// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Brent's zero finder (Brent 1973, "zeroin") as the `shooting` solver uses it: a bracket that
/// closes to a relative width, not a point.

#include <functional>
#include <utility>

namespace catena::internal {

/// Inverse quadratic / secant steps safeguarded by bisection, one evaluation of `f` per
/// iteration (at most 300), every step at least the tolerance long so that the bracket closes.
/// Needs f(a) f(b) < 0 (fa = f(a), fb = f(b)); returns the final bracket (ascending), of width
/// <= ~relative_tolerance * |root|. An exact zero at an iterate is tested, not trusted: f is
/// probed at b (1 -+ relative_tolerance / 2); probes with the signs of their sides return that
/// bracket, a probe with the other side's sign continues the search in the strict bracket it
/// leaves (the zero was spurious). Only when the probes cannot decide (zero too, out to the ends)
/// is the bracket as it stands returned, wider than the tolerance.
std::pair<double, double> brent_zero(const std::function<double(double)>& f,
                                     double a,
                                     double b,
                                     double fa,
                                     double fb,
                                     double relative_tolerance);

}  // namespace catena::internal
