// SPDX-License-Identifier: MIT
// `catena check` as one library call: reference scene, run, certified references, comparison
// (docs/how-to/check.md).
#include "catena/verification/scene_check.hpp"

#include <algorithm>
#include <map>

#include "catena/core/error.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "catena/verification/certified_reference.hpp"
#include "catena/verification/scene_runner.hpp"

namespace catena {
namespace {

// Catena computes this many modes beyond the other program's highest in each plane, so that a
// mode the other program skipped or misnumbered still finds its partner.
constexpr int kExtraReferenceModes = 3;
// Stations of Catena's shapes when shapes are compared (linear interpolation to the other
// program's stations; error ~ (L/2000)^2 curvature, far below any MAC of interest).
constexpr int kReferenceShapePoints = 2001;

bool uses_plane(const std::vector<ExternalMode>& results, Plane plane) {
  return std::any_of(results.begin(), results.end(),
                     [&](const ExternalMode& r) { return r.plane == plane; });
}

}  // namespace

Scene reference_scene(Scene scene, const std::vector<ExternalMode>& results) {
  int inplane = 0, outofplane = 0;
  bool shapes = false, tension = false;
  for (const auto& row : results) {
    int& highest = row.plane == Plane::InPlane ? inplane : outofplane;
    highest = std::max(highest, row.mode + kExtraReferenceModes);
    shapes = shapes || row.shape.has_value();
    tension = tension || (row.shape && row.shape->tension_n.size() > 0);
  }
  SolveRequest& request = scene.request;
  request.inplane_modes = std::min(inplane, kMaxRequestModes);
  request.outofplane_modes = std::min(outofplane, kMaxRequestModes);
  request.shapes = shapes;
  request.tension = tension;
  request.forced.reset();
  const long modes = request.inplane_modes + request.outofplane_modes;
  request.points = static_cast<int>(
      std::min<long>(kReferenceShapePoints, kMaxShapeValues / std::max(modes, 1L)));
  std::map<std::string, SolverKnobs> solvers;
  for (const std::string& name : reference_solvers())  // the certified reference's candidates
    solvers[name] = scene.solvers.count(name) ? scene.solvers.at(name) : SolverKnobs{};
  scene.solvers = solvers;
  return scene;
}

SceneCheck check_scene(const std::vector<ExternalMode>& results,
                       const Scene& scene,
                       const ExternalCheckOptions& options) {
  options.validate();
  if (results.empty()) throw InvalidInput("no results to check");
  validate_external_results(results);
  SceneRunOptions run;
  run.checks = false;
  const SceneResult solved = run_scene(reference_scene(scene, results), run);
  if (solved.error_kind == SceneError::BadInput) throw InvalidInput(solved.error);
  if (!solved.error.empty()) return {std::nullopt, solved.error};
  std::vector<CertifiedReference> references;
  for (const Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    if (!uses_plane(results, plane)) continue;
    std::string why;
    auto reference = certified_reference(solved.outputs, plane, why);
    if (!reference) return {std::nullopt, "no certified reference: " + why};
    references.push_back(std::move(*reference));
  }
  return {check_external_results(results, references, options), ""};
}

}  // namespace catena
