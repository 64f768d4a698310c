// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Modal identification from a free decay (docs/explanation/methods/identification.md): the
/// frequencies, damping ratios and amplitudes of the damped modes present in one or more sampled
/// signals that ring down, each with an uncertainty derived from the data (its length, sampling and
/// noise). Pure numerics: reading a MoorDyn or CSV file and comparing with Catena's damped modes
/// are elsewhere (include/catena/io, include/catena/verification).
///
/// Method: the matrix pencil method (Hua & Sarkar 1990) on the stacked Hankel matrices of all
/// channels (they share the poles), after removing the mean and low-pass decimating to the band of
/// interest; the model order from the singular values (gap above the noise floor); then a
/// variable-projection Gauss-Newton refinement of the poles with linear amplitudes (reaching the
/// Cramer-Rao bound for white noise), whose covariance sigma^2 (J^T J)^-1 gives the uncertainty.

#include <string>
#include <vector>

#include "catena/core/types.hpp"

namespace catena {

/// Options of identify_modes(). Validated by identify_modes() (InvalidInput naming the field).
struct IdentificationOptions {
  double min_frequency_hz = 0.0;   // modes below are not reported (0: none) [Hz], >= 0
  double max_frequency_hz = 0.0;   // band of interest (0: up to 0.8 Nyquist) [Hz], >= 0
  int max_model_order = 0;         // cap on the number of complex poles (0: automatic), >= 0
  double confidence_sigmas = 3.0;  // the uncertainty is this many standard deviations, > 0
};

/// One damped mode found in the decay: x(t) = A exp(-delta t) cos(2 pi f t + phi).
struct IdentifiedMode {
  double frequency_hz = 0.0;               // damped frequency Im(lambda)/2pi [Hz]
  double frequency_uncertainty_hz = 0.0;   // bound at confidence_sigmas, from the data [Hz]
  double damping_ratio = 0.0;              // zeta = -Re(lambda)/|lambda| [-]
  double damping_ratio_uncertainty = 0.0;  // bound at confidence_sigmas [-]
  double decay_rate_1_s = 0.0;             // delta = -Re(lambda) [1/s]
  double amplitude = 0.0;                  // largest amplitude over the channels, at the window
                                           //   start [channel units]
  double signal_to_noise = 0.0;            // this mode's energy / the residual's, over the window
  bool identifiable = true;                // false: found but its uncertainty exceeds its own
  std::string note;                        //   value, or it decays below the noise within a
                                           //   period; note says why
  /// Its frequency can be stood behind even when its damping ratio is not resolved from zero (an
  /// undamped or very lightly damped line): identifiable, or not only because the damping-ratio
  /// uncertainty exceeds the damping ratio.
  bool frequency_identifiable = true;
};

/// The modes of a free decay and how they were found.
struct Identification {
  std::vector<IdentifiedMode> modes;    // ascending frequency; only Im(lambda) > 0 poles
  int model_order = 0;                  // poles kept
  std::vector<double> singular_values;  // of the data matrix, descending (for the order choice)
  double noise_rms = 0.0;               // residual RMS after the fit, per channel averaged
  double sample_interval_s = 0.0;       // of the input [s]
  std::string method;                   // e.g. "matrix pencil (Hua & Sarkar 1990) + least squares"
  /// One line per pole found but not reported, and why (outside the band, growing, noise).
  std::vector<std::string> discarded;
  /// The pencil and the fit ran on every n-th low-passed sample (1: on the samples as given).
  int decimation_factor = 1;
};

/// Identifies the damped modes of a free decay.
/// time_s: strictly increasing, uniformly sampled (InvalidInput otherwise, naming the sample);
/// channels: one or more signals of the same length (several channels share the poles), finite.
/// Throws InvalidInput for bad input (non-uniform or non-increasing time, channels of different
/// length, too few samples, NaN or infinite samples, bad options), naming the field and sample.
Identification identify_modes(const Vector& time_s,
                              const std::vector<Vector>& channels,
                              const IdentificationOptions& options = {});

}  // namespace catena
