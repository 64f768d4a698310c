// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Reviewed findings about published tables (verification/findings.toml): entries where a
/// published value disagrees with ours and only one of our solvers computes what the column
/// tabulates (so the two-agreeing-solvers rule cannot decide). A listed entry is reported as a
/// source discrepancy with its diagnosis; an unlisted disagreement fails.
///
///     [[finding]]
///     scene = "grinfogel-eps0.18-phi23.46[lambda2=19]"
///     quantity = "inplane_frequency"
///     mode = 1
///     solver = "asymptotic"
///     printed = 1.5352
///     ours = 1.53xx              # our value when the finding was reviewed (a stale entry fails)
///     diagnosis = "..."

#include <optional>
#include <string>
#include <vector>

namespace catena {

struct Finding {
  std::string scene;
  std::string quantity;
  int mode = 0;
  std::string solver;
  double printed = 0.0;
  double ours = 0.0;
  std::string diagnosis;
};

/// The reviewed findings. Plain data with one lookup; reading it from TOML is io's job
/// (catena/io/findings_reader.hpp), and a run receives it in SceneRunOptions.
class FindingsTable {
 public:
  FindingsTable() = default;
  explicit FindingsTable(std::vector<Finding> findings) : findings_(std::move(findings)) {}

  /// The finding for this scene, quantity, mode and solver, or nullptr.
  const Finding* find(const std::string& scene,
                      const std::string& quantity,
                      int mode,
                      const std::string& solver) const;
  const std::vector<Finding>& findings() const { return findings_; }

 private:
  std::vector<Finding> findings_;
};

}  // namespace catena
