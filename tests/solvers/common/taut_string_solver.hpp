// SPDX-License-Identifier: MIT
#pragma once
// What adding a solver costs: a complete sixth solver, the taut string (omega_n = n pi
// sqrt(T0/M)/L, both planes), written against the skeleton (src/solvers/common/solver_driver.hpp,
// knob_table.hpp): its numerics, its knob table and its registry entry, which is all a new solver
// writes besides its tests. tests/solvers/common/sixth_solver_test.cpp runs it through
// run_solver(); tests/verification/sixth_solver_harness_test.cpp adds it to the registry
// (register_solver) and runs a scene and the mutation score through the harness, which name no
// solver.
//
// Its roles, as data: an exact solver (SolverKind::Exact) on the cables it accepts, declared to
// reach the relative accuracy `max_eps` (it declines a cable with eps above it: out of plane, the
// sag and the static strain it ignores move the frequencies by about eps). Like fe without a
// `tolerance`, it is asked for no accuracy, so its summaries report none and its modes carry no
// estimate: the declared accuracy is its entry's alone. Not a certified reference (it ignores sag).

#include <memory>
#include <optional>
#include <string>

#include "catena/solvers/solver_registry.hpp"
#include "solvers/common/knob_table.hpp"
#include "solvers/common/mode_tools.hpp"
#include "solvers/common/solver_driver.hpp"

namespace catena::testing {

struct StringOptions {
  double max_eps = 1e-3;  // the string model ignores sag: decline above this eps
  void validate() const;
};

inline const internal::KnobTable<StringOptions>& string_knobs() {
  static const internal::KnobTable<StringOptions> table(
      "string",
      {internal::real_knob("max_eps", &StringOptions::max_eps, internal::Range::open_closed(0, 1),
                           "eps above which the string model declines")});
  return table;
}
inline void StringOptions::validate() const { string_knobs().validate(*this); }

class StringNumerics final : public internal::SolverNumerics {
 public:
  StringNumerics(const SolveContext& context, const StringOptions& options)
      : context_(context), options_(options) {}
  std::optional<std::string> not_applicable() const override {
    if (context_.groups.eps > options_.max_eps)
      return "sagging cable: the string model ignores sag";
    return std::nullopt;
  }
  ModalResult modes(Plane, int count) override {
    ModalResult result;
    for (int n = 1; n <= count; ++n) {
      Mode mode;
      mode.index = n;
      internal::set_mode_frequency(mode, context_.groups.omega_from_k_l_over_pi(n),
                                   context_.groups);
      result.modes.push_back(mode);
    }
    result.summary.termination = Termination::Converged;
    result.summary.message = "Converged: the taut string";
    return result;
  }

 private:
  const SolveContext& context_;
  StringOptions options_;
};

inline SolverEntry make_string_entry() {
  SolverEntry entry =
      internal::make_solver_entry("taut string, omega_n = n pi sqrt(T0/M) / L", string_knobs(),
                                  [](const SolveContext& context, const StringOptions& options) {
                                    return std::make_unique<StringNumerics>(context, options);
                                  });
  entry.kind = SolverKind::Exact;
  internal::set_accuracy_target(entry, string_knobs(),
                                [](const StringOptions& options) { return options.max_eps; });
  return entry;
}

}  // namespace catena::testing
