// SPDX-License-Identifier: MIT
// catena_input_fuzz: the mutational fuzzer of the readers of other programs' files (issue 32;
// docs/contributing/testing.md, "Fuzzing"): MoorDyn decks, `catena check` results, `catena report
// --from` documents. The mutants are the scene fuzzer's (scene_mutator.hpp: numbers swapped for
// edge values, bytes flipped, lines deleted, duplicated, swapped or spliced, strings swapped,
// brackets and deep nesting inserted, truncation), deterministic from --seed.
//
//   catena_input_fuzz --target moordyn|check|report [--corpus DIR] [--iterations 2000] [--seed 18]
//                     [--first K] [--time-limit 60] [--failures DIR] [--work DIR]
//   catena_input_fuzz --target ... --emit DIR    (write the mutants and recipes.tsv, run none)
//
// Exit 0 when every input ended accepted or as a catena::Error, 1 when one let another exception
// escape or broke a rule of input_fuzz_target.hpp, 2 for bad arguments. A signal kills the
// process: --failures DIR holds the input being run in last-input and its recipe in
// last-input.txt.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "input_fuzz_target.hpp"

namespace {

namespace fs = std::filesystem;
using catena::fuzz::InputTarget;

struct Arguments {
  std::string target_name;
  InputTarget target = InputTarget::MoorDyn;
  fs::path corpus, failures, emit, work;
  std::uint64_t first = 0, iterations = 2000, seed = 18;
  double time_limit_s = 0.0;  // 0: none
};

bool parse_arguments(int argc, char** argv, Arguments& a) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const std::string value = argv[i + 1];
    if (key == "--target")
      a.target_name = value;
    else if (key == "--corpus")
      a.corpus = value;
    else if (key == "--failures")
      a.failures = value;
    else if (key == "--emit")
      a.emit = value;
    else if (key == "--work")
      a.work = value;
    else if (key == "--iterations")
      a.iterations = std::strtoull(value.c_str(), nullptr, 10);
    else if (key == "--first")
      a.first = std::strtoull(value.c_str(), nullptr, 10);
    else if (key == "--seed")
      a.seed = std::strtoull(value.c_str(), nullptr, 10);
    else if (key == "--time-limit")
      a.time_limit_s = std::strtod(value.c_str(), nullptr);
    else
      return false;
  }
  return argc % 2 == 1 && catena::fuzz::parse_input_target(a.target_name, a.target) &&
         (a.target == InputTarget::Report || !a.corpus.empty());
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

// mutant-000012.txt, keeping the seed's extension (the check target reads .json as JSON).
std::string mutant_name(std::uint64_t iteration, const fs::path& seed_file) {
  char name[48];
  std::snprintf(name, sizeof name, "mutant-%06llu", static_cast<unsigned long long>(iteration));
  return name + seed_file.extension().string();
}

int emit_mutants(const Arguments& a, const std::vector<catena::fuzz::SeedScene>& corpus) {
  fs::create_directories(a.emit);
  std::ofstream recipes(a.emit / "recipes.tsv");
  for (std::uint64_t i = a.first; i < a.first + a.iterations; ++i) {
    const auto mutant = catena::fuzz::mutate(corpus, a.seed, i);
    const fs::path& seed_file = corpus[mutant.seed_index].file;
    write_file(a.emit / mutant_name(i, seed_file), mutant.text);
    recipes << mutant_name(i, seed_file) << '\t' << seed_file.filename().string() << '\t'
            << mutant.recipe << '\n';
  }
  std::cout << "wrote " << a.iterations << " mutants to " << a.emit.string() << '\n';
  return 0;
}

int run_fuzzer(const Arguments& a, const std::vector<catena::fuzz::SeedScene>& corpus) {
  if (!a.failures.empty()) fs::create_directories(a.failures);
  const fs::path work =
      a.work.empty() ? fs::temp_directory_path() / ("catena_input_fuzz_" + a.target_name) : a.work;
  const auto context = catena::fuzz::make_context(a.target, a.corpus, work);
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed_s = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  std::uint64_t run = 0, accepted = 0, failures = 0;
  for (std::uint64_t i = a.first; i < a.first + a.iterations; ++i) {
    if (a.time_limit_s > 0.0 && elapsed_s() > a.time_limit_s) break;
    const auto mutant = catena::fuzz::mutate(corpus, a.seed, i);
    const auto& seed = corpus[mutant.seed_index];
    const std::string where = "iteration " + std::to_string(i) + " (seed " +
                              seed.file.filename().string() + "; " + mutant.recipe + ")";
    if (!a.failures.empty()) {
      write_file(a.failures / ("last-input" + seed.file.extension().string()), mutant.text);
      write_file(a.failures / "last-input.txt", where + "\n");
    }
    ++run;
    std::vector<std::string> violations;
    try {
      accepted += catena::fuzz::fuzz_input(context, seed, mutant.text, violations);
    } catch (const std::exception& error) {
      violations.push_back(std::string("escaped exception: ") + error.what());
    }
    for (const auto& violation : violations)
      std::cerr << "FAIL " << where << ": " << violation << '\n';
    if (!violations.empty()) {
      ++failures;
      if (!a.failures.empty()) write_file(a.failures / mutant_name(i, seed.file), mutant.text);
    }
  }
  if (!a.failures.empty()) {
    for (const auto& entry : fs::directory_iterator(a.failures))
      if (entry.path().stem() == "last-input") fs::remove(entry.path());
  }
  std::printf(
      "%s fuzz: %llu inputs (seed %llu, %zu seeds): %llu accepted, %llu refused as bad "
      "input; %llu failures; %.1f s\n",
      a.target_name.c_str(), static_cast<unsigned long long>(run),
      static_cast<unsigned long long>(a.seed), corpus.size(),
      static_cast<unsigned long long>(accepted), static_cast<unsigned long long>(run - accepted),
      static_cast<unsigned long long>(failures), elapsed_s());
  return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Arguments arguments;
  if (!parse_arguments(argc, argv, arguments)) {
    std::cerr << "usage: catena_input_fuzz --target moordyn|check|report [--corpus DIR] "
                 "[--iterations N] [--first K]\n"
                 "                         [--seed S] [--time-limit SECONDS] [--failures DIR] "
                 "[--work DIR] [--emit DIR]\n"
                 "(--corpus is required for moordyn and check)\n";
    return 2;
  }
  const auto corpus = catena::fuzz::input_seed_corpus(arguments.target, arguments.corpus);
  if (corpus.empty()) {
    std::cerr << "catena_input_fuzz: no seed files under " << arguments.corpus.string() << '\n';
    return 2;
  }
  return arguments.emit.empty() ? run_fuzzer(arguments, corpus) : emit_mutants(arguments, corpus);
}
