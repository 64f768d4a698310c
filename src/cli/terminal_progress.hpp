// SPDX-License-Identifier: MIT
#pragma once
// A one-line progress display on stderr for long solves ("shooting: in-plane modes 37/600"),
// shown only when stderr is a terminal, so that pipes, tests and CI logs stay clean.

#include <chrono>
#include <cstdio>
#include <string>

namespace catena::cli {

class TerminalProgress {
 public:
  /// Shows nothing unless `enabled` and `stream` is a terminal.
  explicit TerminalProgress(bool enabled, std::FILE* stream = stderr);
  ~TerminalProgress() { clear(); }
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  /// A ProgressCallback (catena/solvers/run_limits.hpp): redraws the line at most every
  /// kRefresh, and always when a part completes.
  void update(const std::string& solver, const std::string& part, long done, long total);
  /// Erases the line (before other output).
  void clear();

  static constexpr std::chrono::milliseconds kRefresh{200};

 private:
  std::FILE* stream_;
  bool active_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace catena::cli
