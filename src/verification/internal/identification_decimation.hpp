// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Low-pass filtering and decimation of a free decay to the band of interest, before the matrix
/// pencil and the fit (docs/explanation/methods/identification.md, "Decimation").

#include <complex>
#include <vector>

#include "catena/core/types.hpp"

namespace catena::internal {

/// The channels filtered by a symmetric FIR low-pass and kept every `factor`-th sample.
struct DecimatedRecord {
  std::vector<Vector> channels;
  double sample_interval_s = 0.0;  // factor times the input's [s]
  double start_offset_s = 0.0;     // time of the first output sample after the input's first [s]
  int factor = 1;                  // 1: the input unchanged (no filter)
  Vector taps;                     // the FIR, odd length, centred; {1} when factor is 1
  /// factor * sum(taps^2): the decimated noise variance is noise_gain / factor times the input's
  /// white-noise variance; 1 for an ideal low-pass at the new Nyquist frequency.
  double noise_gain = 1.0;
  /// The share of the decimated band, from 0, where white input noise stays white: 1 without a
  /// filter, the pass band over the new Nyquist frequency with one.
  double white_fraction = 1.0;
};

/// Decimates to the lowest rate that keeps 4 samples per period of `band_hz` (no decimation when
/// band_hz is 0 or the factor would be 1). The filter passes [0, band_hz] flat and stops above the
/// new Nyquist frequency; only the outputs the whole filter covers are kept, so that each damped
/// exponential c exp(lambda t) leaves as c H(lambda) exp(lambda t): the poles are unchanged.
DecimatedRecord decimate_to_band(const std::vector<Vector>& channels,
                                 double sample_interval_s,
                                 double band_hz);

/// H(lambda) = sum_k taps[k] exp(lambda (k - m) dt), m the centre: the filter's factor on
/// exp(lambda t) (1 without a filter).
std::complex<double> filter_gain(const DecimatedRecord& record,
                                 double input_interval_s,
                                 std::complex<double> lambda_1_s);

}  // namespace catena::internal
