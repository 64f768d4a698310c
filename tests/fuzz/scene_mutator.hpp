// SPDX-License-Identifier: MIT
#pragma once
// Deterministic mutations of scene text for the scene-reader fuzzer (docs/contributing/testing.md,
// "Fuzzing"). The same corpus, seed and iteration always give the same mutant, on every platform:
// the random numbers come from our own SplitMix64, not from <random>'s implementation-defined
// distributions.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace catena::fuzz {

/// SplitMix64 (Steele, Lea & Flood 2014): tiny, fast, and identical everywhere.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  /// Uniform in [0, bound) (bound > 0; the modulo bias is irrelevant for fuzzing).
  std::size_t below(std::size_t bound) { return static_cast<std::size_t>(next() % bound); }
  bool one_in(std::size_t n) { return below(n) == 0; }

 private:
  std::uint64_t state_;
};

/// One seed scene: where it came from and its text.
struct SeedScene {
  std::filesystem::path file;
  std::string text;
};

/// Every *.toml under `directory` (recursively), sorted by path so that the order is the same on
/// every machine.
std::vector<SeedScene> read_seed_corpus(const std::filesystem::path& directory);

/// A mutant and how it was made (for the failure report).
struct Mutant {
  std::size_t seed_index = 0;
  std::string text;
  /// e.g. "number 400 -> 1e308; delete line 12".
  std::string recipe;
};

/// Mutates corpus[i] into mutant number `iteration` of the run with `seed`: 1 to 4 stacked
/// mutations (numbers swapped for edge values or rescaled, bytes flipped, lines deleted,
/// duplicated, swapped or spliced from another seed, strings swapped for other strings of the
/// corpus, brackets inserted, deep nesting, truncation).
Mutant mutate(const std::vector<SeedScene>& corpus, std::uint64_t seed, std::uint64_t iteration);

}  // namespace catena::fuzz
