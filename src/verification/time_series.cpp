// SPDX-License-Identifier: MIT
// A time series: finding a channel by name, refusing one with NaN or infinite samples, and building
// one from samples in memory (docs/how-to/check-time-series.md, "Channels and planes").
#include "catena/verification/time_series.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numeric>

#include "catena/core/error.hpp"
#include "core/internal/ascii_lower.hpp"

namespace catena {
namespace {

// Levenshtein distance ignoring case: a MoorDyn file may spell a channel FAIRTEN1, FairTen1 or
// Fair1Ten, and a user may type any of them.
std::size_t distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
    }
  }
  return row[b.size()];
}

// The names closest to `name` (at most five), for the message of a missing channel.
std::string close_names(const std::vector<std::string>& names, const std::string& name) {
  const std::string key = internal::ascii_lower(name);
  std::vector<std::pair<std::size_t, std::size_t>> ranked;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string candidate = internal::ascii_lower(names[i]);
    // A name containing the query (or contained in it) ranks first.
    const bool contains = !key.empty() && (candidate.find(key) != std::string::npos ||
                                           key.find(candidate) != std::string::npos);
    ranked.push_back({contains ? 0 : 1 + distance(key, candidate), i});
  }
  std::stable_sort(ranked.begin(), ranked.end());
  std::string text;
  for (std::size_t k = 0; k < std::min<std::size_t>(5, ranked.size()); ++k)
    text += (k ? ", " : "") + names[ranked[k].second];
  return text;
}

}  // namespace

std::size_t TimeSeries::channel_index(const std::string& name) const {
  const auto exact = std::find(names.begin(), names.end(), name);
  if (exact != names.end()) return static_cast<std::size_t>(exact - names.begin());
  std::vector<std::size_t> matches;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (internal::ascii_lower(names[i]) == internal::ascii_lower(name)) matches.push_back(i);
  if (matches.size() == 1) return matches.front();
  if (matches.size() > 1) {
    throw InvalidInput(
        fmt::format("{}: channel '{}' matches {} columns ignoring case ({}, ...): "
                    "give its exact spelling",
                    source, name, matches.size(), names[matches[0]]));
  }
  throw InvalidInput(fmt::format("{}: no channel '{}' ({} channels; closest: {})", source, name,
                                 names.size(), close_names(names, name)));
}

const Vector& TimeSeries::channel(const std::string& name) const {
  const std::size_t index = channel_index(name);
  const Vector& samples = columns.at(index);
  for (Index k = 0; k < samples.size(); ++k) {
    if (!std::isfinite(samples[k])) {
      const auto row = static_cast<std::size_t>(k);
      // Samples from memory have no file lines: their index (1-based) instead.
      const std::string where = row < line_numbers.size()
                                    ? fmt::format("line {}", line_numbers[row])
                                    : fmt::format("sample {}", row + 1);
      throw InvalidInput(fmt::format(
          "{} {} (time {:.10g} s), channel '{}': the sample is {}: the run went unstable or the "
          "output is corrupt",
          source, where, time_s[k], names[index], samples[k]));
    }
  }
  return samples;
}

TimeSeries time_series_from_samples(const Vector& time_s,
                                    const std::vector<std::string>& names,
                                    const std::vector<Vector>& columns,
                                    const std::string& source) {
  if (time_s.size() == 0) throw InvalidInput(source + ": no samples (time_s is empty)");
  if (names.size() != columns.size() || names.empty())
    throw InvalidInput(
        fmt::format("{}: {} names for {} channels", source, names.size(), columns.size()));
  for (std::size_t j = 0; j < names.size(); ++j) {
    if (names[j].empty()) throw InvalidInput(source + ": a channel with an empty name");
    if (std::count(names.begin(), names.end(), names[j]) > 1)
      throw InvalidInput(fmt::format("{}: channel '{}' given twice", source, names[j]));
    if (columns[j].size() != time_s.size()) {
      throw InvalidInput(fmt::format("{}: channel '{}' has {} samples, time_s {}", source, names[j],
                                     columns[j].size(), time_s.size()));
    }
  }
  for (Index k = 0; k < time_s.size(); ++k) {
    if (!std::isfinite(time_s[k]) || (k > 0 && !(time_s[k] > time_s[k - 1]))) {
      throw InvalidInput(fmt::format(
          "{}: time_s[{}] = {} s is not finite or not after time_s[{}]: the time must increase "
          "strictly",
          source, k, time_s[k], k > 0 ? k - 1 : 0));
    }
  }
  TimeSeries series;
  series.source = source;
  series.format = "csv";
  series.names = names;
  series.units.assign(names.size(), "");
  series.time_s = time_s;
  series.columns = columns;
  return series;
}

}  // namespace catena
