// SPDX-License-Identifier: MIT
// The progress line of `catena solve`: see terminal_progress.hpp.
#include "cli/terminal_progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

namespace catena::cli {

TerminalProgress::TerminalProgress(bool enabled, std::FILE* stream)
    : stream_(stream), active_(enabled && isatty(fileno(stream))) {}

void TerminalProgress::update(const std::string& solver,
                              const std::string& part,
                              long done,
                              long total) {
  if (!active_) return;
  const auto now = std::chrono::steady_clock::now();
  // Redrawing costs a write per call, and a forced sweep may call this a million times.
  if (shown_ && done < total && now - last_ < kRefresh) return;
  last_ = now;
  shown_ = true;
  fmt::print(stream_, "\r\033[K{}: {} {}/{}", solver, part, done, total);
  std::fflush(stream_);
}

void TerminalProgress::clear() {
  if (!shown_) return;
  fmt::print(stream_, "\r\033[K");
  std::fflush(stream_);
  shown_ = false;
}

}  // namespace catena::cli
