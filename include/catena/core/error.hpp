// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The exceptions Catena throws (docs/contributing/architecture.md, "Errors"). Only bad input
/// throws, before any work is done: InvalidInput for a value that violates a documented constraint
/// (including an output path that cannot be written), ParseError for a file that cannot be read or
/// parsed. Numerical outcomes are never exceptions: they are statuses (SolverSummary::termination,
/// StaticSolution::converged). Broken internal invariants are assert()s.

#include <stdexcept>
#include <string>

namespace catena {

/// Base of every exception Catena throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A value violates a documented constraint. The message names the field, its value and the
/// constraint, e.g. "Invalid CableProperties::length_m = -1: must be > 0 [m]".
class InvalidInput : public Error {
 public:
  using Error::Error;
};

/// A file cannot be read or parsed (bad TOML, unknown key, wrong type). The message names the
/// file, the table and the key.
class ParseError : public Error {
 public:
  using Error::Error;
};

}  // namespace catena
