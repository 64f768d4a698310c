// SPDX-License-Identifier: MIT
#pragma once
// Fuzz targets for the readers of other programs' files (issue 32, "What it must show";
// docs/contributing/testing.md, "Fuzzing"): a MoorDyn deck through the importer (and each scene it
// writes back through the scene reader), another program's results through `catena check`'s
// readers and comparison, and a results JSON through `catena report --from`. Bad input must end as
// catena::Error; anything else that escapes (another exception, a signal, a sanitizer report) is a
// defect, and so is a scene the importer writes that Catena's own reader refuses.

#include <filesystem>
#include <string>
#include <vector>

#include "catena/verification/certified_reference.hpp"
#include "scene_mutator.hpp"

namespace catena::fuzz {

enum class InputTarget { MoorDyn, Check, Report };

/// "moordyn", "check", "report"; false for another name.
bool parse_input_target(const std::string& name, InputTarget& target);

/// What one run of a target shares between its inputs.
struct InputFuzzContext {
  InputTarget target = InputTarget::MoorDyn;
  /// Scratch directory: the CSV and report readers read files, the report writes one.
  std::filesystem::path work_dir;
  /// `catena check`'s references, computed once (see make_context) for the check target.
  std::vector<CertifiedReference> references;
};

/// The context for `target` (for check: the references of the scene the check corpus was written
/// for, `corpus`/scene.toml, which `catena check --scene` gets in the CLI campaign too).
InputFuzzContext make_context(InputTarget target,
                              const std::filesystem::path& corpus,
                              const std::filesystem::path& work_dir);

/// The seed corpus of `target`: the files under `directory` (moordyn: *.txt, check: *.csv and
/// *.json) sorted by path; for report, results documents written by Catena itself for two small
/// scenes, plus the hand-written document of the report's tests.
std::vector<SeedScene> input_seed_corpus(InputTarget target,
                                         const std::filesystem::path& directory);

/// One input: true when it was accepted, false when refused as bad input (catena::Error).
/// `violations` gets what must not happen while accepting it. Throws what is not a catena::Error.
bool fuzz_input(const InputFuzzContext& context,
                const SeedScene& seed,
                const std::string& text,
                std::vector<std::string>& violations);

}  // namespace catena::fuzz
