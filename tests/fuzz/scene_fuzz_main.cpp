// SPDX-License-Identifier: MIT
// catena_scene_fuzz: a standalone mutational fuzzer for the scene reader
// (docs/contributing/testing.md, "Fuzzing"). GCC has no libFuzzer, so this driver makes its own
// mutants: deterministic from
// --seed, from the seed corpus of the suite's scenes, each fed to the reader, the statics and a
// cheap solver request in this process.
//
//   catena_scene_fuzz --corpus verification/scenes [--iterations 2000] [--seed 18]
//                     [--first K] [--time-limit 60] [--failures DIR]
//   catena_scene_fuzz --corpus verification/scenes --emit DIR ...   (write the mutants, run none)
//
// Exit 0 when every input ended as a result or a catena::Error; 1 when an input let another
// exception escape or produced a "converged" result with a non-finite or non-positive frequency
// or a silent non-finite forced response; 2 for bad arguments. A signal or a sanitizer report
// kills the process: --failures DIR always holds the input being run in last-input.toml and its
// iteration and recipe in last-input.txt; --first K resumes after it.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "scene_fuzz_target.hpp"
#include "scene_mutator.hpp"

namespace {

namespace fs = std::filesystem;
using catena::fuzz::FuzzStage;

struct Arguments {
  fs::path corpus;
  fs::path failures;
  fs::path emit;
  std::uint64_t first = 0;
  std::uint64_t iterations = 2000;
  std::uint64_t seed = 18;
  double time_limit_s = 0.0;  // 0: none
};

bool parse_arguments(int argc, char** argv, Arguments& arguments) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const std::string value = argv[i + 1];
    if (key == "--corpus")
      arguments.corpus = value;
    else if (key == "--failures")
      arguments.failures = value;
    else if (key == "--emit")
      arguments.emit = value;
    else if (key == "--iterations")
      arguments.iterations = std::strtoull(value.c_str(), nullptr, 10);
    else if (key == "--first")
      arguments.first = std::strtoull(value.c_str(), nullptr, 10);
    else if (key == "--seed")
      arguments.seed = std::strtoull(value.c_str(), nullptr, 10);
    else if (key == "--time-limit")
      arguments.time_limit_s = std::strtod(value.c_str(), nullptr);
    else
      return false;
  }
  return argc % 2 == 1 && !arguments.corpus.empty();
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

std::string mutant_name(std::uint64_t iteration) {
  char name[48];
  std::snprintf(name, sizeof name, "mutant-%06llu.toml",
                static_cast<unsigned long long>(iteration));
  return name;
}

/// --emit: the mutants as files plus recipes.tsv (file, seed scene, recipe), for the CLI campaign
/// (scripts/fuzz_campaign.py).
int emit_mutants(const Arguments& arguments, const std::vector<catena::fuzz::SeedScene>& corpus) {
  fs::create_directories(arguments.emit);
  std::ofstream recipes(arguments.emit / "recipes.tsv");
  for (std::uint64_t i = 0; i < arguments.iterations; ++i) {
    const auto mutant = catena::fuzz::mutate(corpus, arguments.seed, i);
    write_file(arguments.emit / mutant_name(i), mutant.text);
    recipes << mutant_name(i) << '\t' << corpus[mutant.seed_index].file.string() << '\t'
            << mutant.recipe << '\n';
  }
  std::cout << "wrote " << arguments.iterations << " mutants to " << arguments.emit.string()
            << '\n';
  return 0;
}

struct Totals {
  std::uint64_t run = 0, rejected = 0, statics_failed = 0, solved = 0, failures = 0;
};

void report_failure(const Arguments& arguments,
                    std::uint64_t iteration,
                    const catena::fuzz::Mutant& mutant,
                    const std::string& seed_file,
                    const std::string& what) {
  std::cerr << "FAIL iteration " << iteration << " (seed scene " << seed_file << "; "
            << mutant.recipe << "): " << what << '\n';
  if (!arguments.failures.empty())
    write_file(arguments.failures / mutant_name(iteration), mutant.text);
}

int run_fuzzer(const Arguments& arguments, const std::vector<catena::fuzz::SeedScene>& corpus) {
  if (!arguments.failures.empty()) fs::create_directories(arguments.failures);
  const catena::fuzz::FuzzLimits limits;
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed_s = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  Totals totals;
  for (std::uint64_t i = arguments.first; i < arguments.first + arguments.iterations; ++i) {
    if (arguments.time_limit_s > 0.0 && elapsed_s() > arguments.time_limit_s) break;
    const auto mutant = catena::fuzz::mutate(corpus, arguments.seed, i);
    const std::string seed_file = corpus[mutant.seed_index].file.filename().string();
    if (!arguments.failures.empty()) {
      write_file(arguments.failures / "last-input.toml", mutant.text);
      write_file(arguments.failures / "last-input.txt", "iteration " + std::to_string(i) +
                                                            " (seed scene " + seed_file +
                                                            "): " + mutant.recipe + "\n");
    }
    ++totals.run;
    try {
      const auto outcome = catena::fuzz::fuzz_scene_text(mutant.text, i, limits);
      totals.rejected += outcome.stage == FuzzStage::Rejected;
      totals.statics_failed += outcome.stage == FuzzStage::StaticsFailed;
      totals.solved += outcome.stage == FuzzStage::Solved;
      for (const auto& violation : outcome.violations)
        report_failure(arguments, i, mutant, seed_file, violation);
      totals.failures += !outcome.violations.empty();
    } catch (const std::exception& error) {
      report_failure(arguments, i, mutant, seed_file,
                     std::string("escaped exception: ") + error.what());
      ++totals.failures;
    }
  }
  if (!arguments.failures.empty()) {
    fs::remove(arguments.failures / "last-input.toml");
    fs::remove(arguments.failures / "last-input.txt");
  }
  std::printf(
      "scene fuzz: %llu inputs (seed %llu, %zu seed scenes): %llu rejected as bad input, %llu not "
      "solved, %llu solved; %llu failures; %.1f s\n",
      static_cast<unsigned long long>(totals.run), static_cast<unsigned long long>(arguments.seed),
      corpus.size(), static_cast<unsigned long long>(totals.rejected),
      static_cast<unsigned long long>(totals.statics_failed),
      static_cast<unsigned long long>(totals.solved),
      static_cast<unsigned long long>(totals.failures), elapsed_s());
  return totals.failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Arguments arguments;
  if (!parse_arguments(argc, argv, arguments)) {
    std::cerr << "usage: catena_scene_fuzz --corpus DIR [--iterations N] [--first K] [--seed S] "
                 "[--time-limit SECONDS]\n"
                 "                         [--failures DIR] [--emit DIR]\n";
    return 2;
  }
  const auto corpus = catena::fuzz::read_seed_corpus(arguments.corpus);
  if (corpus.empty()) {
    std::cerr << "catena_scene_fuzz: no *.toml under " << arguments.corpus.string() << '\n';
    return 2;
  }
  return arguments.emit.empty() ? run_fuzzer(arguments, corpus) : emit_mutants(arguments, corpus);
}
