// SPDX-License-Identifier: MIT
// A user of the harness (catena::verification): reads a scene file, runs it as `catena verify`
// does (its solvers, then the checks against the compiled-in tolerance and findings tables), and
// prints the statics, shooting's in-plane frequencies (in main.cpp's format) and the checks.
// Usage: catena_read_scene SCENE.toml   (exit 0 when every check passes)
#include <cstdio>
#include <exception>

#include "catena/io/findings_reader.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/io/tolerance_reader.hpp"
#include "catena/verification/scene_runner.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SCENE.toml\n", argv[0]);
    return 2;
  }
  try {
    catena::SceneRunOptions options;
    options.tolerances = catena::builtin_tolerance_table();
    options.findings = catena::builtin_findings_table();
    const catena::Scene scene = catena::read_scene_file(argv[1]).front();
    const catena::SceneResult result = catena::run_scene(scene, options);
    if (!result.statics) {
      std::fprintf(stderr, "scene %s: %s\n", scene.name.c_str(), result.error.c_str());
      return 3;
    }
    std::printf("statics: %s\n", result.statics->brief_report().c_str());
    for (const catena::SolverOutput& output : result.outputs) {
      if (output.solver != "shooting" || !output.inplane) continue;
      std::printf("shooting in-plane [Hz]:");
      for (const catena::Mode& mode : output.inplane->modes)
        std::printf(" %.9g", mode.frequency_hz);
      std::printf(" (%s)\n", catena::to_string(output.inplane->summary.termination).c_str());
    }
    std::printf("checks: %zu, failed: %d\n", result.checks.size(), result.failed_checks());
    return result.failed_checks() == 0 ? 0 : 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 2;
  }
}
