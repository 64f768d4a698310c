// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The precision ladder of the frobenius solver: double, then long double, then 113-bit quad,
/// chosen at run time when cancellation in the series sums leaves too few digits
/// (docs/explanation/methods/frobenius.md). with_precision() runs one generic computation in the
/// chosen type, so that each caller writes its dispatch once.

#include <boost/multiprecision/cpp_bin_float.hpp>

namespace catena::internal {

using QuadFloat = boost::multiprecision::cpp_bin_float_quad;

/// Ordered: a larger value is more precise (std::max picks the more precise of two).
enum class Precision { Double = 0, LongDouble = 1, Quad = 2 };

/// "double", "long double", "quad (113-bit)".
inline const char* precision_name(Precision p) {
  return p == Precision::Double ? "double"
                                : (p == Precision::LongDouble ? "long double" : "quad (113-bit)");
}

/// f(Real{}) with Real the floating-point type of `p`; f is generic in its argument's type.
template <class F>
decltype(auto) with_precision(Precision p, F&& f) {
  switch (p) {
    case Precision::Double:
      return f(double{});
    case Precision::LongDouble:
      return f(static_cast<long double>(0));
    default:
      return f(QuadFloat{});
  }
}

}  // namespace catena::internal
