// SPDX-License-Identifier: MIT
#include "io/internal/dynamic_tension_text.hpp"

#include <fmt/format.h>

namespace catena::internal {
namespace {

std::string fixed_point_text(const DynamicTension& t) {
  if (t.converged) return "converged";
  return "NOT converged" + (t.diagnostic.empty() ? std::string() : ": " + t.diagnostic);
}

std::string regular_text(const std::vector<const DynamicTension*>& tensions,
                         const std::string& indent) {
  std::string out = fmt::format(
      "{}dynamic tension, regular motion (drag linearised to its fixed "
      "point; max = mean + amplitude):\n",
      indent);
  out += fmt::format("{}  {:>10} {:<9} {:>10} {:>14} {:>14} {:>11} {:>14} {:>6} {:>10}  {}\n",
                     indent, "T [s]", "end", "s [m]", "mean [N]", "amplitude [N]", "phase [deg]",
                     "max [N]", "iter", "residual", "fixed point");
  for (const DynamicTension* tension : tensions) {
    const DynamicTension& t = *tension;
    const std::pair<const char*, const DynamicTensionEnd*> ends[] = {{"fairlead", &t.fairlead},
                                                                     {"anchor", &t.anchor}};
    bool first = true;
    for (const auto& [name, end] : ends) {
      const std::string period = first ? fmt::format("{:.6g}", t.period_s) : std::string();
      const std::string fixed_point =
          first ? fmt::format("{:>6} {:>10.2e}  {}", t.iterations, t.residual, fixed_point_text(t))
                : std::string();
      out += fmt::format("{}  {:>10} {:<9} {:>10.6g} {:>14.8g} {:>14.8g} {:>11.2f} {:>14.8g} {}\n",
                         indent, period, name, end->s_m, end->mean_n, end->amplitude_n,
                         end->phase_deg, end->mean_n + end->amplitude_n, fixed_point);
      first = false;
    }
  }
  return out;
}

std::string irregular_text(const DynamicTension& t, double duration_s, const std::string& indent) {
  std::string out = fmt::format(
      "{}dynamic tension, irregular motion: fixed point {} after {} iterations, residual {:.2e}\n",
      indent, fixed_point_text(t), t.iterations, t.residual);
  out += fmt::format("{}  {:<9} {:>10} {:>14} {:>14} {:>10} {:>22}\n", indent, "end", "s [m]",
                     "mean [N]", "std [N]", "Tz [s]", fmt::format("max in {:g} s [N]", duration_s));
  const std::pair<const char*, const DynamicTensionEnd*> ends[] = {{"fairlead", &t.fairlead},
                                                                   {"anchor", &t.anchor}};
  for (const auto& [name, end] : ends) {
    out += fmt::format("{}  {:<9} {:>10.6g} {:>14.8g} {:>14.8g} {:>10.4g} {:>22.8g}\n", indent,
                       name, end->s_m, end->mean_n, end->std_n, end->zero_upcrossing_period_s,
                       end->most_probable_max_n);
  }
  return out + fmt::format(
                   "{}  (max: the most probable maximum, mean + std sqrt(2 ln N), N = "
                   "duration / Tz)\n",
                   indent);
}

}  // namespace

std::string dynamic_tension_text(const std::vector<DynamicTension>& tensions,
                                 double duration_s,
                                 const std::string& indent) {
  if (tensions.empty()) return {};
  std::string out;
  std::vector<const DynamicTension*> regular;
  for (const DynamicTension& t : tensions) {
    if (t.irregular)
      out += irregular_text(t, duration_s, indent);
    else
      regular.push_back(&t);
  }
  if (!regular.empty()) out = regular_text(regular, indent) + out;
  return out;
}

}  // namespace catena::internal
