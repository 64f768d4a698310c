#pragma once
/// \file
/// Expected agreement, held as reviewed data (verification/tolerances.toml, after Boost.Math's
/// expected_results()): each rule says which check and which pair of solvers (or a solver and the
/// published value) it governs, the tolerance, and why.
///
///     [[tolerance]]
///     check = "frequency"               # frequency, published, mac, shape, tension, forced,
///                                       # orthogonality, mode-count
///     compare = ["fe", "shooting"]      # solver names, "*" (any solver) or "published"
///     scene = "*"                       # optional glob on the scene name
///     tag = "gale"                      # optional: only scenes with this tag
///     max = 1e-8                        # the tolerance (a floor when estimate_factor is set)
///     estimate_factor = 3.0             # optional: tolerance = max(max, factor * (est_a + est_b))
///     beyond = "warn"                   # optional: a model's known limit, WARN (not FAIL) when
///                                       # exceeded; the measured value is still reported
///     reason = "..."                    # required
///
/// The first rule that matches wins: put specific rules before general ones.

#include <string>
#include <vector>

namespace catena {

struct ToleranceRule {
  std::string check;
  /// Two entries: solver names, "*" or "published". Order does not matter.
  std::vector<std::string> compare;
  std::string scene_pattern = "*";
  std::string tag;
  double max = 0.0;
  double estimate_factor = 0.0;
  /// True for `beyond = "warn"`: exceeding the tolerance is a documented model limit.
  bool warn_only = false;
  std::string reason;
};

/// The rules in order. Plain data with one lookup; reading it from TOML is io's job
/// (catena/io/tolerance_reader.hpp), and a run receives it in SceneRunOptions.
class ToleranceTable {
 public:
  ToleranceTable() = default;
  explicit ToleranceTable(std::vector<ToleranceRule> rules) : rules_(std::move(rules)) {}

  /// The first rule for `check` comparing `a` with `b` in `scene` (with `tags`), or nullptr.
  const ToleranceRule* find(const std::string& check,
                            const std::string& a,
                            const std::string& b,
                            const std::string& scene,
                            const std::vector<std::string>& tags) const;

  const std::vector<ToleranceRule>& rules() const { return rules_; }

 private:
  std::vector<ToleranceRule> rules_;
};

}  // namespace catena
