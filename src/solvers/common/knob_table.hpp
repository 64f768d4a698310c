// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// A solver's knobs, declared once: name, the options field it sets, type, valid range, help.
/// The default is the options struct's own default member initializer. One table serves the
/// scene reader (read(): unknown knobs, wrong types and out-of-range values rejected, naming
/// `[solvers.<name>].<knob>`), the typed API (validate(): the same ranges on a filled-in options
/// struct), and `catena solvers` and the docs (specs()).
///
///   const KnobTable<FeSolverOptions>& fe_knobs() {
///     static const KnobTable<FeSolverOptions> table("fe", {
///         integer_knob("elements", &FeSolverOptions::elements, Range::at_least(2), "bar elements
///         N"), flag_knob("richardson", &FeSolverOptions::richardson, "solve N and 2N,
///         extrapolate")});
///     return table;
///   }

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "solvers/common/solver_driver.hpp"

namespace catena::internal {

/// A closed, open or half-open interval of valid numeric values.
struct Range {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  bool low_open = false;
  bool high_open = false;

  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range open_closed(double a, double b) { return {a, b, true, false}; }
  static Range at_least(double a) {
    return {a, std::numeric_limits<double>::infinity(), false, true};
  }
  static Range above(double a) { return {a, std::numeric_limits<double>::infinity(), true, true}; }

  bool contains(double x) const {
    if (!std::isfinite(x)) return false;
    const bool above_low = low_open ? x > low : x >= low;
    const bool below_high = high_open ? x < high : x <= high;
    return above_low && below_high;
  }
  /// "[2, inf)", "(0, 0.01]".
  std::string to_string() const {
    const auto bound = [](double v) {
      return std::isinf(v) ? std::string("inf") : fmt::format("{:g}", v);
    };
    return fmt::format("{}{}, {}{}", low_open ? "(" : "[", bound(low), bound(high),
                       high_open ? ")" : "]");
  }
};

/// "[solvers.fe].elements" for messages.
inline std::string knob_key(const std::string& solver, const std::string& knob) {
  return fmt::format("[solvers.{}].{}", solver, knob);
}

/// One knob bound to a field of `Options`.
template <class Options>
struct KnobBinding {
  KnobSpec spec;
  /// Sets the field from a scene value; throws InvalidInput (naming `key`) on a wrong type or
  /// value.
  std::function<void(Options&, const KnobValue&, const std::string& key)> assign;
  /// Throws InvalidInput (naming `key`) when the field holds a value outside the range.
  std::function<void(const Options&, const std::string& key)> check;
};

namespace knob_detail {

template <class Field>
void check_range(Field value, const Range& range, const std::string& key) {
  if (!range.contains(static_cast<double>(value))) {
    throw InvalidInput(fmt::format("{} = {}: must be in {}", key, value, range.to_string()));
  }
}

inline double as_real(const KnobValue& value, const std::string& key) {
  if (const auto* d = std::get_if<double>(&value)) return *d;
  if (const auto* i = std::get_if<long>(&value)) return static_cast<double>(*i);
  throw InvalidInput(fmt::format("{}: expected a number", key));
}

inline long as_integer(const KnobValue& value, const std::string& key) {
  if (const auto* i = std::get_if<long>(&value)) return *i;
  // 1e3 is accepted for 1000, but only where it is a whole number that fits without wrapping.
  if (const auto* d = std::get_if<double>(&value); d && std::floor(*d) == *d && std::abs(*d) < 1e15)
    return static_cast<long>(*d);
  throw InvalidInput(fmt::format("{}: expected an integer", key));
}

}  // namespace knob_detail

/// A real knob in `range`.
template <class Options>
KnobBinding<Options> real_knob(std::string name,
                               double Options::*field,
                               Range range,
                               std::string help) {
  KnobBinding<Options> b;
  b.spec = {std::move(name), std::move(help), "real", fmt::format("{:g}", Options{}.*field),
            range.to_string()};
  b.check = [field, range](const Options& o, const std::string& key) {
    knob_detail::check_range(o.*field, range, key);
  };
  b.assign = [field, check = b.check](Options& o, const KnobValue& v, const std::string& key) {
    o.*field = knob_detail::as_real(v, key);
    check(o, key);
  };
  return b;
}

/// An integer knob in `range` (range checked before narrowing, so nothing wraps).
template <class Options, class Int>
KnobBinding<Options> integer_knob(std::string name,
                                  Int Options::*field,
                                  Range range,
                                  std::string help) {
  KnobBinding<Options> b;
  b.spec = {std::move(name), std::move(help), "integer", fmt::format("{}", Options{}.*field),
            range.to_string()};
  b.check = [field, range](const Options& o, const std::string& key) {
    knob_detail::check_range(o.*field, range, key);
  };
  b.assign = [field, range](Options& o, const KnobValue& v, const std::string& key) {
    const long value = knob_detail::as_integer(v, key);
    knob_detail::check_range(value, range, key);
    o.*field = static_cast<Int>(value);
  };
  return b;
}

/// A true/false knob.
template <class Options>
KnobBinding<Options> flag_knob(std::string name, bool Options::*field, std::string help) {
  KnobBinding<Options> b;
  b.spec = {std::move(name), std::move(help), "flag", Options{}.*field ? "true" : "false", ""};
  b.check = [](const Options&, const std::string&) {};
  b.assign = [field](Options& o, const KnobValue& v, const std::string& key) {
    const auto* flag = std::get_if<bool>(&v);
    if (!flag) throw InvalidInput(fmt::format("{}: expected true or false", key));
    o.*field = *flag;
  };
  return b;
}

/// A knob that picks one of named values of a field (an enum, usually).
template <class Options, class Field>
KnobBinding<Options> choice_knob(std::string name,
                                 Field Options::*field,
                                 std::vector<std::pair<std::string, Field>> choices,
                                 std::string help) {
  std::string valid, default_name;
  for (const auto& [text, value] : choices) {
    valid += fmt::format("{}\"{}\"", valid.empty() ? "" : " or ", text);
    if (value == Options{}.*field) default_name = text;
  }
  KnobBinding<Options> b;
  b.spec = {std::move(name), std::move(help), "choice", fmt::format("\"{}\"", default_name), valid};
  b.check = [](const Options&, const std::string&) {};
  b.assign = [field, choices, valid](Options& o, const KnobValue& v, const std::string& key) {
    const auto* text = std::get_if<std::string>(&v);
    if (!text) throw InvalidInput(fmt::format("{}: expected a string ({})", key, valid));
    for (const auto& [choice, value] : choices) {
      if (choice == *text) {
        o.*field = value;
        return;
      }
    }
    throw InvalidInput(fmt::format("{} = \"{}\": must be {}", key, *text, valid));
  };
  return b;
}

/// Every knob of one solver.
template <class Options>
class KnobTable {
 public:
  KnobTable(std::string solver, std::vector<KnobBinding<Options>> bindings)
      : solver_(std::move(solver)), bindings_(std::move(bindings)) {}

  /// Options from scene knobs, defaults elsewhere; throws InvalidInput naming the knob.
  Options read(const SolverKnobs& knobs) const {
    Options options;
    for (const auto& [name, value] : knobs)
      binding(name).assign(options, value, knob_key(solver_, name));
    return options;
  }

  /// Throws InvalidInput naming the knob when a field of `options` is out of its range.
  void validate(const Options& options) const {
    for (const auto& b : bindings_) b.check(options, knob_key(solver_, b.spec.name));
  }

  std::vector<KnobSpec> specs() const {
    std::vector<KnobSpec> out;
    for (const auto& b : bindings_) out.push_back(b.spec);
    return out;
  }

  const std::string& solver() const { return solver_; }

 private:
  const KnobBinding<Options>& binding(const std::string& name) const {
    std::string known;
    for (const auto& b : bindings_) {
      if (b.spec.name == name) return b;
      known += (known.empty() ? "" : ", ") + b.spec.name;
    }
    throw InvalidInput(fmt::format("{}: unknown knob for solver '{}' (known: {})",
                                   knob_key(solver_, name), solver_,
                                   known.empty() ? "none" : known));
  }

  std::string solver_;
  std::vector<KnobBinding<Options>> bindings_;
};

/// The registry entry of a solver whose numerics are built from its options:
/// `make(context, options)` returns the solver's SolverNumerics (a std::unique_ptr).
/// `Options::validate()` must throw InvalidInput for values the table cannot judge alone.
template <class Options, class Make>
SolverEntry make_solver_entry(std::string description, const KnobTable<Options>& table, Make make) {
  SolverEntry entry;
  entry.name = table.solver();
  entry.description = std::move(description);
  entry.knobs = table.specs();
  // Options::validate() adds the constraints between knobs (and re-checks the ranges through the
  // same table: one declaration).
  entry.validate_knobs = [&table](const SolverKnobs& knobs) { table.read(knobs).validate(); };
  entry.make_numerics = [&table, make](const SolveContext& context, const SolverKnobs& knobs) {
    Options options = table.read(knobs);
    options.validate();
    return make(context, options);
  };
  return entry;
}

/// Sets entry.accuracy_target to `target(options)`, the options read from the knobs and validated:
/// pass the function the solver's summaries take their accuracy_target from, so that the harness
/// and the solver cannot disagree on it.
template <class Options, class Target>
void set_accuracy_target(SolverEntry& entry, const KnobTable<Options>& table, Target target) {
  entry.accuracy_target = [&table, target](const SolverKnobs& knobs) {
    Options options = table.read(knobs);
    options.validate();
    return target(options);
  };
}

}  // namespace catena::internal
