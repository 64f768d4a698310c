// SPDX-License-Identifier: MIT
// Modal identification from a free decay (src/verification/modal_identification.cpp): synthetic
// sums of damped sinusoids, written here from their definition, with white noise from a fixed
// seed. Each mode must be found within its stated uncertainty, and the uncertainty must not be
// wildly pessimistic: within 10x of the root-mean-square actual error over the seeds.
#include "catena/verification/modal_identification.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "test_utils.hpp"

namespace catena {
namespace {

struct TrueMode {
  double frequency_hz;  // damped frequency
  double damping_ratio;
  double amplitude;
  double phase_rad;
};

struct Decay {
  std::vector<TrueMode> modes;
  double rate_hz;
  double duration_s;
  double weakest_snr;  // energy of the weakest mode / noise energy over the record; 0: no noise
};

double decay_rate(const TrueMode& m) {
  // zeta = delta / |lambda| with Im(lambda) = omega_d: delta = zeta omega_d / sqrt(1 - zeta^2).
  return m.damping_ratio * 2.0 * kPi * m.frequency_hz /
         std::sqrt(1.0 - m.damping_ratio * m.damping_ratio);
}

Vector sample_times(const Decay& d) {
  const auto n = static_cast<Index>(std::llround(d.duration_s * d.rate_hz)) + 1;
  Vector t(n);
  for (Index i = 0; i < n; ++i) t[i] = 3.0 + static_cast<double>(i) / d.rate_hz;  // window at 3 s
  return t;
}

Vector mode_signal(const Vector& t, const TrueMode& m) {
  Vector x(t.size());
  for (Index i = 0; i < t.size(); ++i) {
    const double tau = t[i] - t[0];
    x[i] = m.amplitude * std::exp(-decay_rate(m) * tau) *
           std::cos(2.0 * kPi * m.frequency_hz * tau + m.phase_rad);
  }
  return x;
}

// The channel: an offset, the modes, white noise of the level that gives the weakest mode its SNR.
Vector channel(const Vector& t, const Decay& d, double offset, unsigned seed) {
  Vector x = Vector::Constant(t.size(), offset);
  double weakest_energy = std::numeric_limits<double>::infinity();
  for (const TrueMode& m : d.modes) {
    const Vector s = mode_signal(t, m);
    x += s;
    weakest_energy = std::min(weakest_energy, s.squaredNorm());
  }
  if (d.weakest_snr > 0.0) {
    const double sigma =
        std::sqrt(weakest_energy / (static_cast<double>(t.size()) * d.weakest_snr));
    std::mt19937_64 engine(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    for (Index i = 0; i < x.size(); ++i) x[i] += noise(engine);
  }
  return x;
}

const IdentifiedMode* nearest(const Identification& id, double frequency_hz) {
  const IdentifiedMode* best = nullptr;
  for (const IdentifiedMode& m : id.modes) {
    if (!best ||
        std::abs(m.frequency_hz - frequency_hz) < std::abs(best->frequency_hz - frequency_hz))
      best = &m;
  }
  return best;
}

// Identifies `d` over `seeds` noise draws: each true mode found, identifiable, within its bounds;
// the bounds within 10x of the RMS error over the seeds (noisy records only).
void check_decay(const Decay& d, int seeds, const IdentificationOptions& options = {}) {
  const Vector t = sample_times(d);
  const std::size_t count = d.modes.size();
  std::vector<double> f_error2(count), z_error2(count), f_bound(count), z_bound(count);
  for (int seed = 0; seed < seeds; ++seed) {
    const Identification id =
        identify_modes(t, {channel(t, d, 1234.5, 17u + static_cast<unsigned>(seed))}, options);
    ASSERT_EQ(id.modes.size(), count) << "seed " << seed << ", order " << id.model_order;
    for (std::size_t k = 0; k < count; ++k) {
      const TrueMode& truth = d.modes[k];
      const IdentifiedMode* m = nearest(id, truth.frequency_hz);
      SCOPED_TRACE(::testing::Message() << "mode " << truth.frequency_hz << " Hz, zeta "
                                        << truth.damping_ratio << ", seed " << seed);
      ASSERT_NE(m, nullptr);
      EXPECT_TRUE(m->identifiable) << m->note;
      const double f_error = m->frequency_hz - truth.frequency_hz;
      const double z_error = m->damping_ratio - truth.damping_ratio;
      EXPECT_LE(std::abs(f_error), m->frequency_uncertainty_hz);
      EXPECT_LE(std::abs(z_error), m->damping_ratio_uncertainty);
      f_error2[k] += f_error * f_error / seeds;
      z_error2[k] += z_error * z_error / seeds;
      f_bound[k] += m->frequency_uncertainty_hz / seeds;
      z_bound[k] += m->damping_ratio_uncertainty / seeds;
    }
  }
  if (d.weakest_snr == 0.0) return;
  for (std::size_t k = 0; k < count; ++k) {
    SCOPED_TRACE(::testing::Message() << "mode " << d.modes[k].frequency_hz << " Hz");
    EXPECT_LE(f_bound[k], 10.0 * std::sqrt(f_error2[k]));
    EXPECT_LE(z_bound[k], 10.0 * std::sqrt(z_error2[k]));
  }
}

TEST(ModalIdentification, OneModeAtSeveralNoiseLevels) {
  for (double snr : {1e6, 1e3, 10.0}) {
    SCOPED_TRACE(snr);
    check_decay({{{0.2, 0.01, 2.0, 0.3}}, 10.0, 100.0, snr}, 8);
  }
}

TEST(ModalIdentification, NoiseFreeRecordIsWithinTheFloor) {
  check_decay({{{0.2, 0.01, 2.0, 0.3}, {0.55, 0.001, 0.5, 1.0}}, 10.0, 60.0, 0.0}, 1);
}

TEST(ModalIdentification, FourModesFromLightToHeavyDamping) {
  const std::vector<TrueMode> modes = {
      {0.1, 0.001, 1.0, 0.0}, {0.25, 0.01, 0.6, 1.0}, {0.4, 0.03, 0.8, 2.0}, {0.7, 0.1, 1.5, 3.0}};
  for (double rate : {5.0, 20.0}) {
    SCOPED_TRACE(rate);
    check_decay({modes, rate, 200.0, 100.0}, 6);
  }
}

TEST(ModalIdentification, CloseModes) {
  // 0.02 Hz apart: two beats in the 100 s record.
  check_decay({{{0.30, 0.005, 1.0, 0.0}, {0.32, 0.005, 0.7, 1.0}}, 4.0, 100.0, 1e3}, 6);
}

TEST(ModalIdentification, ChannelsInDifferentUnitsShareThePoles) {
  // A tension in N (large offset and amplitude) and a position in m, each with its own noise:
  // the modes are the same, and the pair identifies them at least as well as the tension alone.
  const Decay tension{{{0.15, 0.008, 2e4, 0.2}, {0.42, 0.02, 8e3, 1.0}}, 10.0, 120.0, 300.0};
  const Decay position{{{0.15, 0.008, 0.8, 2.0}, {0.42, 0.02, 0.1, 0.5}}, 10.0, 120.0, 30.0};
  const Vector t = sample_times(tension);
  double alone = 0.0, both = 0.0, error2 = 0.0;
  const int seeds = 6;
  for (int seed = 0; seed < seeds; ++seed) {
    const Vector x = channel(t, tension, 2.5e6, 100u + static_cast<unsigned>(seed));
    const Vector y = channel(t, position, -3.0, 200u + static_cast<unsigned>(seed));
    const Identification single = identify_modes(t, {x});
    const Identification pair = identify_modes(t, {x, y});
    ASSERT_EQ(pair.modes.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
      const TrueMode& truth = tension.modes[k];
      const IdentifiedMode& m = pair.modes[k];
      SCOPED_TRACE(::testing::Message() << "mode " << truth.frequency_hz << " Hz, seed " << seed);
      EXPECT_TRUE(m.identifiable) << m.note;
      EXPECT_LE(std::abs(m.frequency_hz - truth.frequency_hz), m.frequency_uncertainty_hz);
      EXPECT_LE(std::abs(m.damping_ratio - truth.damping_ratio), m.damping_ratio_uncertainty);
      // The amplitude is the largest over the channels, in its channel's units: the tension's.
      EXPECT_NEAR(m.amplitude, truth.amplitude, 0.05 * truth.amplitude);
    }
    const IdentifiedMode* first = nearest(single, 0.15);
    ASSERT_NE(first, nullptr);
    alone += first->frequency_uncertainty_hz / seeds;
    both += pair.modes[0].frequency_uncertainty_hz / seeds;
    error2 += std::pow(pair.modes[0].frequency_hz - 0.15, 2) / seeds;
  }
  EXPECT_LT(both, alone);  // the position channel adds information
  EXPECT_LE(both, 10.0 * std::sqrt(error2));
}

TEST(ModalIdentification, BandOfInterestDecimatesWithoutBias) {
  // 50 Hz sampling, modes below 1 Hz and one at 8 Hz outside the band: decimated by 12, the
  // in-band modes are within their uncertainty and the 8 Hz mode is not reported.
  const Decay d{
      {{0.25, 0.01, 1.0, 0.0}, {0.6, 0.02, 0.5, 1.0}, {8.0, 0.01, 0.5, 2.0}}, 50.0, 80.0, 1e3};
  const Vector t = sample_times(d);
  IdentificationOptions options;
  options.max_frequency_hz = 1.0;
  double error2 = 0.0, bound = 0.0;
  const int seeds = 6;
  for (int seed = 0; seed < seeds; ++seed) {
    const Identification id =
        identify_modes(t, {channel(t, d, 0.0, 300u + static_cast<unsigned>(seed))}, options);
    EXPECT_GT(id.decimation_factor, 1);
    ASSERT_EQ(id.modes.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
      const TrueMode& truth = d.modes[k];
      const IdentifiedMode& m = id.modes[k];
      SCOPED_TRACE(::testing::Message() << "mode " << truth.frequency_hz << " Hz, seed " << seed);
      EXPECT_LE(std::abs(m.frequency_hz - truth.frequency_hz), m.frequency_uncertainty_hz);
      EXPECT_LE(std::abs(m.damping_ratio - truth.damping_ratio), m.damping_ratio_uncertainty);
      EXPECT_NEAR(m.amplitude, truth.amplitude, 0.05 * truth.amplitude);
    }
    error2 += std::pow(id.modes[0].frequency_hz - 0.25, 2) / seeds;
    bound += id.modes[0].frequency_uncertainty_hz / seeds;
  }
  EXPECT_LE(bound, 10.0 * std::sqrt(error2));
}

TEST(ModalIdentification, NoiseAloneYieldsNoIdentifiableMode) {
  const Decay d{{{0.2, 0.01, 0.0, 0.0}}, 10.0, 100.0, 0.0};
  const Vector t = sample_times(d);
  std::mt19937_64 engine(5);
  std::normal_distribution<double> noise(0.0, 1.0);
  Vector x(t.size());
  for (Index i = 0; i < x.size(); ++i) x[i] = noise(engine);
  const Identification id = identify_modes(t, {x});
  for (const IdentifiedMode& m : id.modes) EXPECT_FALSE(m.identifiable) << m.frequency_hz;
}

TEST(ModalIdentification, BadInputNamesTheProblem) {
  const Decay d{{{0.2, 0.01, 1.0, 0.0}}, 10.0, 20.0, 0.0};
  const Vector t = sample_times(d);
  const Vector x = channel(t, d, 0.0, 1u);
  Vector jittered = t;
  jittered[17] += 0.3 / d.rate_hz;
  testing::expect_invalid([&] { identify_modes(jittered, {x}); }, "time_s[17]");
  Vector backwards = t;
  backwards[40] = backwards[39];
  testing::expect_invalid([&] { identify_modes(backwards, {x}); }, "time_s[40]");
  testing::expect_invalid([&] { identify_modes(t, {x, x.head(50)}); }, "channels[1]");
  testing::expect_invalid([&] { identify_modes(t.head(10), {x.head(10)}); }, "at least 20");
  testing::expect_invalid([&] { identify_modes(t, {}); }, "channels");
  Vector with_nan = x;
  with_nan[33] = std::numeric_limits<double>::quiet_NaN();
  testing::expect_invalid([&] { identify_modes(t, {x, with_nan}); }, "channels[1][33]");
  IdentificationOptions options;
  options.max_frequency_hz = 6.0;  // above the 5 Hz Nyquist frequency
  testing::expect_invalid([&] { identify_modes(t, {x}, options); }, "max_frequency_hz");
  options = {};
  options.confidence_sigmas = 0.0;
  testing::expect_invalid([&] { identify_modes(t, {x}, options); }, "confidence_sigmas");
  options = {};
  options.min_frequency_hz = -1.0;
  testing::expect_invalid([&] { identify_modes(t, {x}, options); }, "min_frequency_hz");
}

}  // namespace
}  // namespace catena
