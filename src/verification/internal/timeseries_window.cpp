// SPDX-License-Identifier: MIT
#include "verification/internal/timeseries_window.hpp"

#include <fmt/format.h>

#include <cmath>

#include "catena/core/error.hpp"

namespace catena::internal {
namespace {

// MoorDyn writes the time with 4 decimals (setprecision(4), fixed): a uniform 0.05 s output can
// read 0.0500, 0.1000, ... exactly or off by up to half the last digit.
constexpr double kMoorDynTimeRounding = 0.5e-4;
// A CSV's times printed with enough digits are uniform to far better than this fraction of the
// step; a larger deviation is a variable step, not rounding.
constexpr double kCsvRelativeRounding = 1e-3;

std::string line_of(const TimeSeries& series, Index k) {
  const auto row = static_cast<std::size_t>(k);
  return row < series.line_numbers.size() ? fmt::format("line {}", series.line_numbers[row])
                                          : fmt::format("sample {}", k + 1);
}

}  // namespace

SampleWindow select_window(const TimeSeries& series,
                           std::optional<double> start_s,
                           std::optional<double> end_s) {
  const Vector& t = series.time_s;
  const Index n = t.size();
  if (n < 3) {
    throw InvalidInput(
        fmt::format("{}: {} samples; the identification needs many more", series.source, n));
  }
  const double record_step = (t[n - 1] - t[0]) / static_cast<double>(n - 1);
  const double start = start_s.value_or(t[0]);
  const double end = end_s.value_or(t[n - 1]);
  const double slack = 0.5 * record_step;
  if (start < t[0] - slack || end > t[n - 1] + slack || !(start < end)) {
    throw InvalidInput(fmt::format(
        "{}: --window {}:{} s is not within the record, {}:{} s (start < end, both inside)",
        series.source, start, end, t[0], t[n - 1]));
  }
  SampleWindow window;
  while (window.first < n && t[window.first] < start - 1e-9 * std::abs(start) - 1e-12)
    ++window.first;
  Index last = n - 1;
  while (last > window.first && t[last] > end + 1e-9 * std::abs(end) + 1e-12) --last;
  window.count = last - window.first + 1;
  if (window.count < 3) {
    throw InvalidInput(fmt::format("{}: the window {}:{} s holds {} samples", series.source, start,
                                   end, window.count));
  }
  const Vector times = t.segment(window.first, window.count);
  window.step_s = (times[window.count - 1] - times[0]) / static_cast<double>(window.count - 1);
  const double allowed = series.format == "moordyn"
                             ? kMoorDynTimeRounding + 1e-12 * std::abs(times[window.count - 1])
                             : kCsvRelativeRounding * window.step_s;
  window.time_s.resize(window.count);
  for (Index k = 0; k < window.count; ++k) {
    window.time_s[k] = times[0] + static_cast<double>(k) * window.step_s;
    const double off = std::abs(times[k] - window.time_s[k]);
    if (off > allowed) {
      throw InvalidInput(fmt::format(
          "{} {} (time {} s): the sampling is not uniform: this sample is {:.3g} s off the grid of "
          "step {:.6g} s (allowed {:.2g} s, the rounding of the printed times). The identification "
          "needs uniform samples; catena does not resample, since interpolating would bias the "
          "damping. In MoorDyn, set dtOut to a multiple of dtM; or window a uniform part",
          series.source, line_of(series, window.first + k), times[k], off, window.step_s, allowed));
    }
  }
  return window;
}

}  // namespace catena::internal
