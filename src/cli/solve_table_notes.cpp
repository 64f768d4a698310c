// SPDX-License-Identifier: MIT
#include "cli/solve_table_notes.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <vector>

namespace catena::cli {
namespace {

constexpr std::size_t kWidth = 120;  // the terminal width the lines fit (solve-output.md)

std::string termination_text(Termination termination) {
  std::string text = to_string(termination);
  std::replace(text.begin(), text.end(), '-', ' ');
  return text;
}

std::string check_line(const CheckResult& check) {
  return fmt::format("  {} {} / {}{}{}: measured {:.3e}, tolerance {:.3e}{}\n",
                     to_string(check.verdict), check.check, check.compare,
                     check.plane.empty() ? "" : " / " + check.plane,
                     check.mode ? fmt::format(" mode {}", check.mode) : "", check.measured,
                     check.tolerance, check.detail.empty() ? "" : ": " + check.detail);
}

// Appends `line` to `lines` unless it is there already (each message said once).
void add_once(std::vector<std::string>& lines, const std::string& line) {
  if (std::find(lines.begin(), lines.end(), line) == lines.end()) lines.push_back(line);
}

std::string overdamped_note(const SolverOutput& output) {
  std::string text;
  for (const auto* modes : {&output.inplane, &output.outofplane}) {
    if (!*modes || (*modes)->overdamped.empty()) continue;
    text +=
        fmt::format("  {} {} overdamped roots (real, no oscillation), delta [1/s]:", output.solver,
                    to_string((*modes)->plane));
    for (const auto& mode : (*modes)->overdamped)
      text += fmt::format(" {:.10g}", mode.decay_rate_1_s);
    text += "\n";
  }
  return text;
}

}  // namespace

std::string short_message(const std::string& message, bool decline, std::size_t width) {
  std::string text = message;
  // The termination is said before the message: drop its echo.
  for (const char* echo : {"No convergence: ", "Converged: "})
    if (text.rfind(echo, 0) == 0) text = text.substr(std::string(echo).size());
  // Clauses end at "; " or ": " outside parentheses. A decline states its reason first; a
  // failure often states what it found first and why later: the first clause that says what went
  // wrong, else the first.
  std::vector<std::string> clauses;
  int depth = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i + 1 < text.size(); ++i) {
    depth += text[i] == '(' ? 1 : text[i] == ')' ? -1 : 0;
    if (depth == 0 && i - start >= 20 && (text[i] == ';' || text[i] == ':') && text[i + 1] == ' ') {
      clauses.push_back(text.substr(start, i - start));
      start = i + 2;
    }
  }
  clauses.push_back(text.substr(start));
  const auto says_why = [](const std::string& clause) {
    for (const char* word : {" not ", "miss", "fail", "exceed", "limit", "lost", "cannot", "no "})
      if (clause.find(word) != std::string::npos) return true;
    return false;
  };
  const auto why =
      decline ? clauses.begin() : std::find_if(clauses.begin(), clauses.end(), says_why);
  text = why != clauses.end() ? *why : clauses.front();
  // Too long: up to its first aside, else its last comma that fits, else cut.
  const std::size_t aside = text.find(" (");
  if (text.size() > width && aside != std::string::npos) text = text.substr(0, aside);
  const std::size_t comma = text.size() > width ? text.rfind(", ", width) : std::string::npos;
  if (comma != std::string::npos && comma >= 20) text = text.substr(0, comma);
  if (text.size() > width) text = text.substr(0, width - 3) + "...";
  return text;
}

std::string solver_notes(const SceneResult& result, bool verbose) {
  std::string text;
  for (const auto& output : result.outputs) {
    const SolverSummary& summary = output.summary;
    // Under --verbose the whole messages follow (solver_details): said once, not twice. A plane
    // that did not converge is named, with its own message; otherwise the solver's.
    std::string planes;
    for (const auto* modes : {&output.inplane, &output.outofplane}) {
      if (!*modes || verbose || summary.termination == Termination::NotApplicable) continue;
      const SolverSummary& part = (*modes)->summary;
      if (part.termination == Termination::Converged) continue;
      const std::string head =
          fmt::format("  {} {}: {}: ", output.solver, to_string((*modes)->plane),
                      termination_text(part.termination));
      planes += head +
                short_message(part.message, part.termination == Termination::NotApplicable,
                              kWidth - head.size()) +
                "\n";
    }
    text += planes;
    if (planes.empty() && summary.termination != Termination::Converged && !verbose) {
      const std::string head =
          fmt::format("  {}: {}: ", output.solver, termination_text(summary.termination));
      text += head +
              short_message(summary.message, summary.termination == Termination::NotApplicable,
                            kWidth - head.size()) +
              "\n";
    }
    for (const auto& response : output.forced)
      if (!response.diagnostic.empty() && !verbose)
        text += fmt::format("  {} at {:.6g} rad/s: {}\n", output.solver, response.omega_rad_s,
                            short_message(response.diagnostic, false));
    for (const auto& tension : output.dynamic_tension)
      if (!tension.converged && !verbose)
        text += fmt::format(
            "  {}: dynamic tension fixed point NOT converged{}\n", output.solver,
            tension.diagnostic.empty() ? "" : ": " + short_message(tension.diagnostic, false));
    text += overdamped_note(output);
  }
  return text;
}

std::string check_notes(const SceneResult& result, bool verbose) {
  std::string text;
  int source = 0, warn = 0;
  for (const auto& check : result.checks) {
    source += check.verdict == Verdict::SourceDiscrepancy;
    warn += check.verdict == Verdict::Warn;
    const bool listed = check.verdict == Verdict::Fail ||
                        (verbose && (check.verdict == Verdict::SourceDiscrepancy ||
                                     check.verdict == Verdict::Warn));
    if (listed) text += check_line(check);
  }
  if (!verbose && source + warn > 0) {
    std::vector<std::string> counts;
    if (source > 0)
      counts.push_back(
          fmt::format("{} SOURCE (a published value our agreeing solvers contradict)", source));
    if (warn > 0) counts.push_back(fmt::format("{} WARN (outside tolerance, explained)", warn));
    text += fmt::format("  {}: --verbose lists them\n", fmt::join(counts, ", "));
  }
  return text;
}

std::string solver_details(const SceneResult& result) {
  std::string text;
  for (const auto& output : result.outputs) {
    const SolverSummary& summary = output.summary;
    if (summary.termination == Termination::NotApplicable) {
      text += fmt::format("  {}: not applicable: {}\n", output.solver, summary.message);
      continue;
    }
    std::vector<std::string> lines;
    for (const auto* modes : {&output.inplane, &output.outofplane}) {
      if (!*modes) continue;
      add_once(lines, fmt::format("{}: {}", to_string((*modes)->plane), (*modes)->summary.message));
      if ((*modes)->proved_count_below_top >= 0)
        add_once(lines, fmt::format("{}: modes proved below the top frequency: {}",
                                    to_string((*modes)->plane), (*modes)->proved_count_below_top));
    }
    if (lines.empty()) add_once(lines, summary.message);
    for (const auto& tension : output.dynamic_tension)
      add_once(lines,
               fmt::format("dynamic tension fixed point {}: {} iterations, residual {:.2e}{}",
                           tension.converged ? "converged" : "NOT converged", tension.iterations,
                           tension.residual,
                           tension.diagnostic.empty() ? "" : "; " + tension.diagnostic));
    for (const auto& response : output.forced)
      if (!response.diagnostic.empty())
        add_once(lines,
                 fmt::format("at {:.6g} rad/s: {}", response.omega_rad_s, response.diagnostic));
    for (const auto& missed : summary.missed_modes) add_once(lines, "missed: " + missed);
    for (const auto& warning : summary.warnings) add_once(lines, "warning: " + warning);
    for (const auto& note : summary.notes) add_once(lines, "note: " + note);
    text += fmt::format(
        "  {}: {}, {}{:.3g} ms\n", output.solver, termination_text(summary.termination),
        summary.resolution.empty() ? "" : summary.resolution + ", ", summary.wall_time_s * 1e3);
    for (const auto& line : lines) text += "    " + line + "\n";
  }
  return text;
}

}  // namespace catena::cli
