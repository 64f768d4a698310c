#pragma once
/// \file
/// Reads a solver's knobs (scene `[solvers.<name>]` values) into its options struct, rejecting
/// unknown knobs and wrong types with a message naming `[solvers.<name>].<knob>`.

#include <set>
#include <string>

#include "catena/solvers/solver_registry.hpp"

namespace catena::internal {

class KnobReader {
 public:
  KnobReader(std::string solver, const SolverKnobs& knobs) : solver_(std::move(solver)), knobs_(knobs) {}

  /// The value of `name` if present (ints are accepted for doubles), else `fallback`.
  double get_double(const std::string& name, double fallback);
  long get_integer(const std::string& name, long fallback);
  bool get_bool(const std::string& name, bool fallback);
  std::string get_string(const std::string& name, const std::string& fallback);

  /// Throws InvalidInput when a knob was given that none of the get_* calls asked for.
  void reject_unknown() const;

  /// "[solvers.fe].elements" for messages.
  std::string key(const std::string& name) const;

 private:
  const KnobValue* find(const std::string& name);
  std::string solver_;
  const SolverKnobs& knobs_;
  std::set<std::string> known_;
};

}  // namespace catena::internal
