// SPDX-License-Identifier: MIT
// Modal identification from a free decay: the input checks, the order of the steps (decimation,
// matrix pencil, least-squares refinement) and the reading of the fit as modes with uncertainties
// (docs/explanation/methods/identification.md).
#include "catena/verification/modal_identification.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "catena/core/error.hpp"
#include "verification/internal/identification_decimation.hpp"
#include "verification/internal/identification_pencil.hpp"
#include "verification/internal/identification_refinement.hpp"

namespace catena {

namespace {

constexpr Index kMinSamples = 20;
// Largest departure of a sample time from the uniform grid, in steps: timing errors of 1 % of a
// step are within what printed times carry (MoorDyn writes a fixed number of decimals).
constexpr double kGridTolerance = 0.01;
// Floors of the uncertainty (docs, "Uncertainty"): relative on the frequency, absolute on the
// damping ratio; above the fit's step tolerance (1e-14) and rounding in the basis (~1e-13 here).
constexpr double kFrequencyFloor = 1e-10;
constexpr double kDampingFloor = 1e-10;

// The step of the uniform grid, or InvalidInput naming the first sample off it. Also returns the
// largest departure from the grid relative to the record length (a bound on the step's error).
double uniform_step(const Vector& time_s, double& grid_error) {
  const Index n = time_s.size();
  for (Index i = 0; i < n; ++i) {
    if (!std::isfinite(time_s[i])) {
      throw InvalidInput(fmt::format("Invalid time_s[{}] = {}: must be finite [s]", i, time_s[i]));
    }
    if (i > 0 && !(time_s[i] > time_s[i - 1])) {
      throw InvalidInput(fmt::format(
          "Invalid time_s[{}] = {}: must be after time_s[{}] = {} (strictly increasing) [s]", i,
          time_s[i], i - 1, time_s[i - 1]));
    }
  }
  const double span = time_s[n - 1] - time_s[0];
  const double step = span / static_cast<double>(n - 1);
  grid_error = 0.0;
  for (Index i = 0; i < n; ++i) {
    const double off = std::abs(time_s[i] - (time_s[0] + static_cast<double>(i) * step));
    if (off > kGridTolerance * step) {
      throw InvalidInput(fmt::format(
          "Invalid time_s[{}] = {}: off the uniform grid of step {} s by {} s (more than {} of a "
          "step); resample the record uniformly first",
          i, time_s[i], step, off, kGridTolerance));
    }
    grid_error = std::max(grid_error, off / span);
  }
  return step;
}

void validate(const Vector& time_s,
              const std::vector<Vector>& channels,
              const IdentificationOptions& options) {
  if (channels.empty()) throw InvalidInput("Invalid channels: none given; give one or more");
  if (time_s.size() < kMinSamples) {
    throw InvalidInput(fmt::format("Invalid time_s: {} samples; at least {} are needed",
                                   time_s.size(), kMinSamples));
  }
  for (std::size_t c = 0; c < channels.size(); ++c) {
    if (channels[c].size() != time_s.size()) {
      throw InvalidInput(fmt::format("Invalid channels[{}]: {} samples, time_s has {}", c,
                                     channels[c].size(), time_s.size()));
    }
    for (Index i = 0; i < channels[c].size(); ++i) {
      if (!std::isfinite(channels[c][i])) {
        throw InvalidInput(fmt::format("Invalid channels[{}][{}] = {} (time {} s): must be finite",
                                       c, i, channels[c][i], time_s[i]));
      }
    }
  }
  const auto check = [](bool ok, const char* field, double value, const char* rule) {
    if (!ok)
      throw InvalidInput(
          fmt::format("Invalid IdentificationOptions::{} = {}: {}", field, value, rule));
  };
  check(std::isfinite(options.min_frequency_hz) && options.min_frequency_hz >= 0.0,
        "min_frequency_hz", options.min_frequency_hz, "must be >= 0 [Hz]");
  check(std::isfinite(options.max_frequency_hz) && options.max_frequency_hz >= 0.0,
        "max_frequency_hz", options.max_frequency_hz, "must be >= 0 [Hz] (0: up to 0.8 Nyquist)");
  check(options.max_frequency_hz == 0.0 || options.max_frequency_hz > options.min_frequency_hz,
        "max_frequency_hz", options.max_frequency_hz, "must be above min_frequency_hz");
  check(options.max_model_order >= 0, "max_model_order", options.max_model_order,
        "must be >= 0 (0: automatic)");
  check(std::isfinite(options.confidence_sigmas) && options.confidence_sigmas > 0.0,
        "confidence_sigmas", options.confidence_sigmas, "must be > 0");
}

// What the fit says about one pole, in the input's units, before the band and noise tests.
struct PoleReading {
  IdentifiedMode mode;
  double information = 0.0;  // sum over channels of the mode's energy / the noise variance
  double decay_bound_1_s = 0.0;
  bool above_noise_after_one_period = false;  // in some channel
};

PoleReading read_pole(const internal::PoleFit& fit,
                      std::size_t k,
                      const internal::DecimatedRecord& record,
                      double dt,
                      const std::vector<double>& scale,
                      const std::vector<double>& noise_variance,
                      Index samples,
                      double sigmas,
                      double grid_error) {
  const std::complex<double> lambda = fit.poles_1_s[k];
  const double delta = -lambda.real(), omega = lambda.imag(), modulus = std::abs(lambda);
  const Eigen::Matrix2d& cov = fit.covariance[k];
  // zeta = delta / |lambda|: its gradient in (delta, omega) carries the covariance.
  const Eigen::Vector2d grad(omega * omega / std::pow(modulus, 3),
                             -delta * omega / std::pow(modulus, 3));
  PoleReading out;
  IdentifiedMode& m = out.mode;
  m.frequency_hz = omega / (2.0 * kPi);
  m.decay_rate_1_s = delta;
  m.damping_ratio = delta / modulus;
  m.frequency_uncertainty_hz =
      sigmas * std::sqrt(cov(1, 1)) / (2.0 * kPi) + m.frequency_hz * (kFrequencyFloor + grid_error);
  m.damping_ratio_uncertainty =
      sigmas * std::sqrt(std::max(0.0, grad.dot(cov * grad))) + kDampingFloor;
  out.decay_bound_1_s = sigmas * std::sqrt(cov(0, 0)) + kDampingFloor * modulus;
  // Energy over the window on the input's grid: |c|^2 / 2 sum exp(-2 delta t_n).
  const double ratio = std::exp(-2.0 * delta * dt);
  const double n = static_cast<double>(samples);
  const double envelope_sum =
      std::abs(1.0 - ratio) < 1e-12 ? n : (1.0 - std::pow(ratio, n)) / (1.0 - ratio);
  const double to_start =
      std::exp(delta * record.start_offset_s) / std::abs(internal::filter_gain(record, dt, lambda));
  for (std::size_t c = 0; c < scale.size(); ++c) {
    const double amplitude = std::abs(fit.amplitudes[c][k]) * scale[c] * to_start;
    m.amplitude = std::max(m.amplitude, amplitude);
    const double energy = 0.5 * amplitude * amplitude * envelope_sum;
    m.signal_to_noise = std::max(m.signal_to_noise, energy / (n * noise_variance[c]));
    out.information += energy / noise_variance[c];
    out.above_noise_after_one_period |=
        amplitude * std::exp(-delta / m.frequency_hz) >= std::sqrt(noise_variance[c]);
  }
  return out;
}

// The pencil's poles with Im > 0 below the Nyquist frequency: the oscillations the fit starts from.
// Real poles (the offset left by removing the mean, a drift) and poles at the Nyquist frequency
// are listed in `discarded`; conjugates are implied.
std::vector<std::complex<double>> oscillating_poles(const std::vector<std::complex<double>>& poles,
                                                    double dt,
                                                    std::vector<std::string>& discarded) {
  std::vector<std::complex<double>> out;
  const double nyquist_rad_s = kPi / dt;
  for (const std::complex<double>& lambda : poles) {
    if (lambda.imag() > 1e-9 * nyquist_rad_s && lambda.imag() < 0.98 * nyquist_rad_s) {
      out.push_back(lambda);
    } else if (std::abs(lambda.imag()) <= 1e-9 * nyquist_rad_s) {
      discarded.push_back(
          fmt::format("a real pole, lambda = {:.6g} 1/s: an offset or a drift, not an oscillation",
                      lambda.real()));
    } else if (lambda.imag() > 0.0) {
      discarded.push_back(
          fmt::format("a pole at the Nyquist frequency, lambda = {:.6g}{:+.6g}i 1/s: noise",
                      lambda.real(), lambda.imag()));
    }
  }
  return out;
}

// Whether a reported mode can be stood behind, and if not why (IdentifiedMode::identifiable).
void judge(PoleReading& pole, bool converged) {
  IdentifiedMode& m = pole.mode;
  m.identifiable = false;
  m.frequency_identifiable = false;
  if (!converged) {
    m.note = "the least-squares refinement did not converge";
  } else if (!std::isfinite(m.frequency_uncertainty_hz) ||
             !std::isfinite(m.damping_ratio_uncertainty)) {
    m.note = "the fit cannot separate this mode from another (singular covariance)";
  } else if (m.frequency_uncertainty_hz >= m.frequency_hz) {
    m.note = "its frequency uncertainty exceeds the frequency";
  } else if (!pole.above_noise_after_one_period) {
    m.note = "it decays below the noise within one period";
  } else if (m.damping_ratio_uncertainty >= std::abs(m.damping_ratio)) {
    m.note = "its damping-ratio uncertainty exceeds the damping ratio";
    m.frequency_identifiable = true;
  } else {
    m.identifiable = true;
    m.frequency_identifiable = true;
  }
}

}  // namespace

Identification identify_modes(const Vector& time_s,
                              const std::vector<Vector>& channels,
                              const IdentificationOptions& options) {
  validate(time_s, channels, options);
  double grid_error = 0.0;
  const double dt = uniform_step(time_s, grid_error);
  const double nyquist_hz = 0.5 / dt;
  if (options.max_frequency_hz > nyquist_hz) {
    throw InvalidInput(fmt::format(
        "Invalid IdentificationOptions::max_frequency_hz = {}: above the Nyquist frequency {} Hz "
        "of the record (step {} s)",
        options.max_frequency_hz, nyquist_hz, dt));
  }
  Identification out;
  out.sample_interval_s = dt;
  out.method = "matrix pencil (Hua & Sarkar 1990) + variable-projection least squares";
  const double band_hz =
      options.max_frequency_hz > 0.0 ? options.max_frequency_hz : 0.8 * nyquist_hz;
  // The static offset removed (and fitted again as a constant), each channel scaled to unit RMS
  // so that channels in different units weigh alike in the pencil.
  std::vector<Vector> scaled;
  std::vector<double> scale;
  for (const Vector& x : channels) {
    const Vector centred = (x.array() - x.mean()).matrix();
    const double rms = std::sqrt(centred.squaredNorm() / static_cast<double>(x.size()));
    scale.push_back(rms > 0.0 ? rms : 1.0);
    scaled.push_back(centred / scale.back());
  }
  const internal::DecimatedRecord record =
      internal::decimate_to_band(scaled, dt, options.max_frequency_hz);
  out.decimation_factor = record.factor;
  const internal::PencilPoles pencil = internal::matrix_pencil(
      record.channels, record.sample_interval_s, options.max_model_order, record.white_fraction);
  out.singular_values = pencil.singular_values;
  out.model_order = pencil.order;
  const std::vector<std::complex<double>> initial =
      oscillating_poles(pencil.poles_1_s, record.sample_interval_s, out.discarded);
  const Index n_fit = record.channels.front().size();
  const Vector tau =
      Vector::LinSpaced(n_fit, 0.0, static_cast<double>(n_fit - 1) * record.sample_interval_s);
  internal::PoleFit fit;
  if (initial.empty()) {
    for (const Vector& x : record.channels)
      fit.residual_variance.push_back(x.squaredNorm() / static_cast<double>(n_fit));
  } else {
    fit = internal::refine_poles(tau, record.channels, initial);
  }
  // White-noise variance on the input's grid per channel (input units): the decimated residual
  // variance is noise_gain / factor of it. The covariance is rescaled likewise (docs,
  // "Decimation").
  std::vector<double> noise_variance;
  for (std::size_t c = 0; c < scale.size(); ++c) {
    noise_variance.push_back(std::max(fit.residual_variance[c] * record.factor / record.noise_gain,
                                      std::numeric_limits<double>::min()) *
                             scale[c] * scale[c]);
    out.noise_rms += std::sqrt(noise_variance.back()) / static_cast<double>(scale.size());
  }
  for (Eigen::Matrix2d& cov : fit.covariance) cov /= record.noise_gain;
  const double log_samples = std::log(static_cast<double>(time_s.size()));
  for (std::size_t k = 0; k < fit.poles_1_s.size(); ++k) {
    PoleReading pole = read_pole(fit, k, record, dt, scale, noise_variance, time_s.size(),
                                 options.confidence_sigmas, grid_error);
    IdentifiedMode& m = pole.mode;
    const std::string where =
        fmt::format("f = {:.6g} Hz, zeta = {:.3g}", m.frequency_hz, m.damping_ratio);
    // A sinusoid fitted to white noise alone captures about 2 ln N noise variances at its best
    // frequency plus 2 per channel (docs, "Spurious poles"): twice that is the least a mode shows.
    if (pole.information < 4.0 * (static_cast<double>(channels.size()) + log_samples)) {
      out.discarded.push_back(where + ": indistinguishable from the noise (energy " +
                              fmt::format("{:.3g}", pole.information) + " noise variances)");
    } else if (m.decay_rate_1_s + pole.decay_bound_1_s < 0.0) {
      out.discarded.push_back(where + ": growing, not a free decay");
    } else if (m.frequency_hz < options.min_frequency_hz || m.frequency_hz > band_hz) {
      out.discarded.push_back(where + fmt::format(": outside the band {:.6g} to {:.6g} Hz",
                                                  options.min_frequency_hz, band_hz));
    } else {
      judge(pole, fit.converged);
      out.modes.push_back(std::move(m));
    }
  }
  std::sort(out.modes.begin(), out.modes.end(),
            [](const IdentifiedMode& a, const IdentifiedMode& b) {
              return a.frequency_hz < b.frequency_hz;
            });
  return out;
}

}  // namespace catena
