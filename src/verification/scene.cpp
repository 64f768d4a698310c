// SPDX-License-Identifier: MIT
#include "catena/verification/scene.hpp"

#include "catena/core/error.hpp"

namespace catena {

std::string to_string(PublishedQuantity quantity) {
  switch (quantity) {
    case PublishedQuantity::InPlaneFrequency:
      return "inplane_frequency";
    case PublishedQuantity::OutOfPlaneFrequency:
      return "outofplane_frequency";
    case PublishedQuantity::ForcedMaxTension:
      return "forced_max_tension";
  }
  return "?";
}

std::optional<PublishedQuantity> parse_published_quantity(const std::string& text) {
  if (text == "inplane_frequency") return PublishedQuantity::InPlaneFrequency;
  if (text == "outofplane_frequency") return PublishedQuantity::OutOfPlaneFrequency;
  if (text == "forced_max_tension") return PublishedQuantity::ForcedMaxTension;
  return std::nullopt;
}

std::vector<std::string> Scene::solver_names() const {
  std::vector<std::string> names;
  for (const auto& entry : solver_registry()) {
    if (solvers.empty() || solvers.count(entry.name)) names.push_back(entry.name);
  }
  return names;
}

SolveRequest resolve_request(const Scene& scene, const DimensionlessGroups& groups) {
  SolveRequest request = scene.request;
  if (request.forced) {
    for (double& omega : request.forced->omegas_rad_s) {
      omega = to_rad_per_second(omega, scene.forcing_frequency_unit, groups);
    }
    if (scene.forcing_amplitude_in_a) {
      if (!groups.has_apex_parameterization) {
        throw InvalidInput(scene.file.string() +
                           ": [request.forced].amplitude_unit = \"a\": Gale's a = H/W0 is "
                           "undefined for a vertical cable");
      }
      request.forced->amplitude_m *= groups.catenary_parameter_m;
    }
  }
  request.validate();
  return request;
}

}  // namespace catena
