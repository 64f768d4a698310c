// SPDX-License-Identifier: MIT
#include "verification/internal/identification_decimation.hpp"

#include <algorithm>
#include <cmath>

namespace catena::internal {

namespace {

// A Blackman-windowed sinc, written by hand: Eigen has no filter design and the design needs none
// of a DSP library's generality. The Blackman window's stop band is below -74 dB and its
// transition about 5.5 / taps of the sampling rate wide (Oppenheim & Schafer, Table 7.2). An FIR
// rather than an IIR filter: an FIR's output of a damped exponential is the same exponential (no
// transient of the filter's own poles), so the identified poles are not biased by the filter.
Vector blackman_low_pass(double cutoff_cycles_per_sample, double transition_cycles_per_sample) {
  int length = static_cast<int>(std::ceil(5.5 / transition_cycles_per_sample));
  length += (length % 2 == 0) ? 1 : 0;
  const int m = (length - 1) / 2;
  Vector taps(length);
  for (int k = 0; k < length; ++k) {
    const double x = k - m;
    const double sinc = x == 0.0 ? 2.0 * cutoff_cycles_per_sample
                                 : std::sin(2.0 * kPi * cutoff_cycles_per_sample * x) / (kPi * x);
    const double phase = 2.0 * kPi * k / (length - 1);
    taps[k] = sinc * (0.42 - 0.5 * std::cos(phase) + 0.08 * std::cos(2.0 * phase));
  }
  return taps / taps.sum();  // unit gain at zero frequency
}

}  // namespace

DecimatedRecord decimate_to_band(const std::vector<Vector>& channels,
                                 double sample_interval_s,
                                 double band_hz) {
  DecimatedRecord out;
  out.sample_interval_s = sample_interval_s;
  out.taps = Vector::Ones(1);
  const double rate_hz = 1.0 / sample_interval_s;
  const int factor = band_hz > 0.0 ? static_cast<int>(std::floor(rate_hz / (4.0 * band_hz))) : 1;
  const Index n = channels.front().size();
  if (factor < 2) {
    out.channels = channels;
    return out;
  }
  // New rate >= 4 band_hz: pass up to band_hz, stop from the new Nyquist frequency (>= 2 band_hz),
  // so that nothing aliases into the decimated record and the band keeps unit gain.
  const double new_nyquist = 0.5 / factor;  // cycles per input sample
  const double pass = band_hz * sample_interval_s;
  Vector taps = blackman_low_pass(0.5 * (pass + new_nyquist), new_nyquist - pass);
  const Index length = taps.size();
  if (n < length + 8 * factor) {  // too short to filter and keep enough samples: leave as is
    out.channels = channels;
    return out;
  }
  const Index outputs = (n - length) / factor + 1;
  for (const Vector& x : channels) {
    Vector y(outputs);
    for (Index j = 0; j < outputs; ++j) y[j] = taps.dot(x.segment(j * factor, length));
    out.channels.push_back(std::move(y));
  }
  out.factor = factor;
  out.sample_interval_s = factor * sample_interval_s;
  out.start_offset_s = static_cast<double>((length - 1) / 2) * sample_interval_s;
  out.noise_gain = factor * taps.squaredNorm();
  out.white_fraction = pass / new_nyquist;
  out.taps = std::move(taps);
  return out;
}

std::complex<double> filter_gain(const DecimatedRecord& record,
                                 double input_interval_s,
                                 std::complex<double> lambda_1_s) {
  const Index m = (record.taps.size() - 1) / 2;
  std::complex<double> gain = 0.0;
  for (Index k = 0; k < record.taps.size(); ++k) {
    gain += record.taps[k] * std::exp(lambda_1_s * (static_cast<double>(k - m) * input_interval_s));
  }
  return gain;
}

}  // namespace catena::internal
