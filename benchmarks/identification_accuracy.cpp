// SPDX-License-Identifier: MIT
// Accuracy and cost of modal identification from a free decay (issue 33): the error of the
// identified frequency and damping ratio against the noise level and the record length, over
// several noise seeds, next to the uncertainty identify_modes() states and how often the error is
// within it; then the time to identify a 10-minute record sampled at 20 Hz. Writes Markdown.
//
//   build/benchmarks/catena_identification_accuracy [--out
//   benchmarks/results/identification-accuracy.md]
//                                                  [--seeds 20] [--quick]
//
// Not a Google Benchmark: each row is a different record, and the error is the point.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "catena/verification/modal_identification.hpp"

namespace {

using namespace catena;

struct TrueMode {
  double frequency_hz, damping_ratio, amplitude, phase_rad;
};

// Two modes as a mooring line's fairlead tension might ring: the lowest at 0.1 Hz (zeta 1 %), the
// next at 0.27 Hz (zeta 2 %) with half its amplitude. The SNR is the lowest mode's.
const std::vector<TrueMode> kModes = {{0.1, 0.01, 1.0, 0.3}, {0.27, 0.02, 0.5, 1.1}};

std::vector<Vector> record(
    const Vector& t, const std::vector<TrueMode>& modes, double snr, int channels, unsigned seed) {
  std::mt19937_64 engine(seed);
  std::vector<Vector> out;
  for (int c = 0; c < channels; ++c) {
    Vector x = Vector::Constant(t.size(), 100.0 * (c + 1));
    Vector first;
    for (std::size_t k = 0; k < modes.size(); ++k) {
      const TrueMode& m = modes[k];
      const double omega = 2.0 * kPi * m.frequency_hz;
      const double delta =
          m.damping_ratio * omega / std::sqrt(1.0 - m.damping_ratio * m.damping_ratio);
      const double gain =
          1.0 + 0.5 * c * (k % 2 == 0 ? 1.0 : -0.5);  // channels see modes differently
      Vector s(t.size());
      for (Index i = 0; i < t.size(); ++i) {
        const double tau = t[i] - t[0];
        s[i] =
            gain * m.amplitude * std::exp(-delta * tau) * std::cos(omega * tau + m.phase_rad + c);
      }
      if (k == 0) first = s;
      x += s;
    }
    if (snr > 0.0) {
      std::normal_distribution<double> noise(0.0,
                                             std::sqrt(first.squaredNorm() / (t.size() * snr)));
      for (Index i = 0; i < t.size(); ++i) x[i] += noise(engine);
    }
    out.push_back(std::move(x));
  }
  return out;
}

Vector times(double rate_hz, double duration_s) {
  const auto n = static_cast<Index>(std::llround(rate_hz * duration_s)) + 1;
  return Vector::LinSpaced(n, 0.0, static_cast<double>(n - 1) / rate_hz);
}

struct Row {
  double rms_f = 0, rms_z = 0, bound_f = 0, bound_z = 0;
  int within = 0, checks = 0, missed = 0, seeds = 0;
};

Row accuracy_row(double snr, double periods, int seeds) {
  Row row;
  const Vector t = times(2.0, periods / kModes[0].frequency_hz);
  for (int seed = 0; seed < seeds; ++seed) {
    const Identification id = identify_modes(t, record(t, kModes, snr, 1, 1000u + seed));
    const IdentifiedMode* m = nullptr;
    for (const IdentifiedMode& candidate : id.modes) {
      if (std::abs(candidate.frequency_hz - 0.1) < 0.05 && candidate.identifiable) m = &candidate;
    }
    ++row.seeds;
    if (!m) {
      ++row.missed;
      continue;
    }
    const double ef = (m->frequency_hz - kModes[0].frequency_hz) / kModes[0].frequency_hz;
    const double ez = m->damping_ratio - kModes[0].damping_ratio;
    row.rms_f += ef * ef;
    row.rms_z += ez * ez;
    row.bound_f += m->frequency_uncertainty_hz / kModes[0].frequency_hz;
    row.bound_z += m->damping_ratio_uncertainty;
    row.within += (std::abs(ef) * kModes[0].frequency_hz <= m->frequency_uncertainty_hz) +
                  (std::abs(ez) <= m->damping_ratio_uncertainty);
    row.checks += 2;
  }
  const int found = row.seeds - row.missed;
  if (found > 0) {
    row.rms_f = std::sqrt(row.rms_f / found);
    row.rms_z = std::sqrt(row.rms_z / found);
    row.bound_f /= found;
    row.bound_z /= found;
  }
  return row;
}

double median_time_s(const Vector& t,
                     const std::vector<Vector>& channels,
                     const IdentificationOptions& options,
                     int repeats,
                     Identification& last) {
  std::vector<double> seconds;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    last = identify_modes(t, channels, options);
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one, five;
  in >> one >> five;
  return one.empty() ? "unknown" : one + " (1 min), " + five + " (5 min)";
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_path = "benchmarks/results/identification-accuracy.md";
  int seeds = 20;
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc)
      out_path = argv[++i];
    else if (arg == "--seeds" && i + 1 < argc)
      seeds = std::max(2, std::atoi(argv[++i]));
    else if (arg == "--quick")
      quick = true;
    else {
      std::cerr << "usage: catena_identification_accuracy [--out FILE.md] [--seeds N] [--quick]\n";
      return 2;
    }
  }
  if (quick) seeds = std::min(seeds, 4);
  std::string md = fmt::format(
      "# Modal identification: accuracy against noise and record length, and cost\n\n"
      "Written by `build/benchmarks/catena_identification_accuracy` "
      "([source](../identification_accuracy.cpp); `make bench`, then run it). Method: "
      "[docs/explanation/methods/identification.md](../../docs/explanation/methods/"
      "identification.md). "
      "Load during the run: {}, on 2 hardware threads.\n\n"
      "## Accuracy\n\n"
      "Two modes, 0.1 Hz (zeta 1 %, amplitude 1) and 0.27 Hz (zeta 2 %, amplitude 0.5), on an "
      "offset, sampled at 2 Hz, one channel, white noise; SNR = the 0.1 Hz mode's energy over the "
      "record / the noise's. Record length in periods of the 0.1 Hz mode. Over {} seeds: the RMS "
      "error of that mode's frequency (relative) and damping ratio (absolute), the mean stated "
      "uncertainty (3 sigma + floor), their ratio (3 when the stated uncertainty is 3 times the "
      "actual standard deviation; the tests require <= 10), how many of the errors were within "
      "the stated uncertainty (3 sigma: 99.7 % expected), and in how many seeds the mode was not "
      "reported as identifiable (not found, or its damping uncertainty above its damping ratio)."
      "\n\n"
      "| SNR | periods | RMS error f (rel.) | stated f (rel.) | ratio | RMS error zeta | "
      "stated zeta | ratio | within | not identifiable |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n",
      load_average(), seeds);
  const std::vector<double> snrs =
      quick ? std::vector<double>{1e4, 10.0} : std::vector<double>{1e6, 1e4, 1e2, 10.0, 1.0};
  const std::vector<double> lengths =
      quick ? std::vector<double>{10.0} : std::vector<double>{3.0, 5.0, 10.0, 20.0, 50.0};
  for (double snr : snrs) {
    for (double periods : lengths) {
      const Row r = accuracy_row(snr, periods, seeds);
      if (r.checks == 0) {
        md += fmt::format("| {:g} | {:g} | - | - | - | - | - | - | - | {}/{} |\n", snr, periods,
                          r.missed, r.seeds);
        continue;
      }
      md += fmt::format(
          "| {:g} | {:g} | {:.2e} | {:.2e} | {:.1f} | {:.2e} | {:.2e} | {:.1f} | {}/{} | {}/{} |\n",
          snr, periods, r.rms_f, r.bound_f, r.bound_f / r.rms_f, r.rms_z, r.bound_z,
          r.bound_z / r.rms_z, r.within, r.checks, r.missed, r.seeds);
      std::cout << "." << std::flush;
    }
  }
  // The cost figure: 10 minutes at 20 Hz, three channels, four modes, SNR 100.
  const std::vector<TrueMode> four = {{0.08, 0.005, 1.0, 0.0},
                                      {0.21, 0.01, 0.7, 1.0},
                                      {0.35, 0.02, 0.5, 2.0},
                                      {0.6, 0.01, 0.4, 3.0}};
  const Vector t = times(20.0, 600.0);
  const std::vector<Vector> channels = record(t, four, 100.0, 3, 7u);
  md +=
      "\n## Cost: a 10-minute record at 20 Hz (12,001 samples), 3 channels, 4 modes "
      "(0.08 to 0.6 Hz, zeta 0.5 to 2 %), SNR 100 on the 0.08 Hz mode\n\n"
      "| options | median of 3 [s] | decimation | model order | modes found (identifiable) "
      "|\n|---|---|---|---|---|\n";
  for (double band : {0.0, 2.0, 1.0}) {
    IdentificationOptions options;
    options.max_frequency_hz = band;
    Identification id;
    const double seconds = median_time_s(t, channels, options, quick ? 1 : 3, id);
    const auto identifiable = std::count_if(id.modes.begin(), id.modes.end(),
                                            [](const IdentifiedMode& m) { return m.identifiable; });
    md += fmt::format("| max_frequency_hz = {} | {:.2f} | {} | {} | {} ({}) |\n",
                      band == 0.0 ? std::string("0 (0.8 Nyquist)") : fmt::format("{:g}", band),
                      seconds, id.decimation_factor, id.model_order, id.modes.size(), identifiable);
  }
  md += fmt::format("\nLoad at the end of the run: {}.\n", load_average());
  std::ofstream(out_path) << md;
  std::cout << "\n" << md;
  return 0;
}
