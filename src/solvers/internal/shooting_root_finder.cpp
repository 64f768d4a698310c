// Counting brackets and Brent refinement of the shooting solver's frequencies: see
// shooting_root_finder.hpp.
#include "solvers/internal/shooting_root_finder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "solvers/internal/shooting_brent.hpp"
#include "solvers/internal/shooting_conjugate_count.hpp"

namespace catena::internal {

ShootingRootFinder::ShootingRootFinder(ShotFunction shoot, const RootFinderSettings& settings,
                                       double first_guess_rad_s, bool scalar)
    : shoot_(std::move(shoot)), settings_(settings), first_guess_(first_guess_rad_s), scalar_(scalar) {}

double ShootingRootFinder::count_function(const Sample& sample, int n) {
  return internal::count_function(sample.count, sample.angle_min, sample.angle_max, n);
}

std::vector<Root> ShootingRootFinder::find(int num_modes, std::vector<std::string>& warnings,
                                           WorkMeter* meter) {
  auto stop_after = [meter](int found) { return meter && meter->stop_after(found); };
  std::vector<Root> roots;
  const Sample& zero = evaluate(0.0);
  if (zero.count != 0) {
    warnings.push_back(fmt::format("count at omega = 0 is {} (expected 0)", zero.count));
  }
  double top = first_guess_;
  raise_to_count(top, num_modes);
  int n = 1;
  while (n <= num_modes && scalar_) {
    // Out of plane the continuous count c = N + (abar - pi)/(2 pi) (Pruefer's angle) is smooth
    // and monotone in omega, and c = n exactly at the n-th eigenvalue: any two samples with
    // counts < n and >= n bracket it, and Brent converges on the nearly linear c - n at once.
    const auto [lo, hi] = bracket(n);
    roots.push_back(refine_scalar(n, lo, hi));
    ++n;
    if (stop_after(n - 1)) return finish(roots);
  }
  while (n <= num_modes) {
    const auto [lo, hi] = bracket(n);
    const Sample& a = samples_.at(lo);
    const Sample& b = samples_.at(hi);
    if (a.count == n - 1 && b.count == n && a.determinant * b.determinant < 0.0) {
      roots.push_back(refine(lo, hi));
      ++n;
      if (stop_after(n - 1)) break;
    } else if (hi - lo <= settings_.root_tolerance * hi) {
      roots.push_back(multiple_root(n, lo, hi, warnings));
      n += roots.back().multiplicity;
      if (stop_after(n - 1)) break;
    } else {
      evaluate(trial_point(n, lo, hi));
    }
  }
  return finish(roots);
}

// The roots found, with the count proved at the smallest sample above the top one.
std::vector<Root> ShootingRootFinder::finish(std::vector<Root>& roots) {
  const auto above = roots.empty() ? samples_.end() : samples_.upper_bound(roots.back().omega);
  proved_count_ = above == samples_.end() ? -1 : above->second.count;
  return std::move(roots);
}

const ShootingRootFinder::Sample& ShootingRootFinder::evaluate(double omega) {
  auto it = samples_.find(omega);
  if (it != samples_.end()) return it->second;
  if (shots_ >= kMaxShots) throw ShootingFailure(fmt::format("more than {} shots", kMaxShots));
  Shot shot = shoot_(omega, 1.0);
  ++shots_;
  if (shot.phase_defect > kMaxPhaseDefect) {
    // The integrated phase fixes the winding, so it must be right to well within pi: re-shoot
    // at 100x tighter tolerances (never seen in the tests; a safety net).
    shot = shoot_(omega, 0.01);
    ++shots_;
    ++phase_retries_;
  }
  max_phase_defect_ = std::max(max_phase_defect_, shot.phase_defect);
  const Sample sample{shot.count, shot.angle_min, shot.angle_max, shot.determinant};
  return samples_.emplace(omega, sample).first->second;
}

// An upper bound: `top` enlarged until the count reaches num_modes.
void ShootingRootFinder::raise_to_count(double& top, int num_modes) {
  for (int attempt = 0; evaluate(top).count < num_modes; ++attempt) {
    if (attempt > 200) throw ShootingFailure("no upper bound found for the requested modes");
    top *= 1.5;
  }
}

// Largest sampled omega with count < n, and the smallest sample above it with count >= n.
std::pair<double, double> ShootingRootFinder::bracket(int n) const {
  double lo = 0.0;
  for (const auto& [omega, sample] : samples_) {
    if (sample.count < n) lo = std::max(lo, omega);
  }
  double hi = samples_.rbegin()->first;
  for (auto it = samples_.upper_bound(lo); it != samples_.end(); ++it) {
    if (it->second.count >= n) {
      hi = it->first;
      break;
    }
  }
  return {lo, hi};
}

// Next trial inside a count bracket: where the leading eigen-angle of the lower end is predicted
// to reach its crossing (linear in omega through the origin of h_n, which is nearly linear for
// string-like modes), kept within the middle 80% of the bracket; bisection otherwise.
double ShootingRootFinder::trial_point(int n, double lo, double hi) const {
  const Sample& a = samples_.at(lo);
  const double mid = 0.5 * (lo + hi);
  if (a.count != n - 1 || lo <= 0.0) return mid;
  const double h_lo = count_function(a, n);  // in (-1, 0]
  auto below = samples_.find(lo);
  if (below == samples_.begin()) return mid;
  --below;
  if (below->second.count != n - 1) return mid;
  const double h_below = count_function(below->second, n);
  if (!(h_lo > h_below)) return mid;
  // Aim a little beyond the predicted crossing, so that the new point is likely the upper end.
  const double predicted = lo - h_lo * (lo - below->first) / (h_lo - h_below);
  const double aim = predicted + 0.02 * (predicted - lo) + 1e-9 * predicted;
  return std::clamp(aim, lo + 0.1 * (hi - lo), hi - 0.1 * (hi - lo));
}

// Several eigenvalues inside a bracket narrower than the tolerance: a multiple root (e.g.
// Irvine's cross-over), returned as that many modes.
Root ShootingRootFinder::multiple_root(int n, double lo, double hi,
                                       std::vector<std::string>& warnings) const {
  const Sample& a = samples_.at(lo);
  const Sample& b = samples_.at(hi);
  Root root;
  root.omega = 0.5 * (lo + hi);
  root.multiplicity = std::max(1, b.count - std::max(a.count, n - 1));
  if (a.count != n - 1) {
    warnings.push_back(
        fmt::format("mode {}: count {} just below the root (expected {})", n, a.count, n - 1));
  }
  if (b.count - a.count == 1) {
    warnings.push_back(fmt::format(
        "mode {}: the end determinant does not change sign across the count bracket "
        "[{:.17g}, {:.17g}] rad/s; located by bisection on the count",
        n, lo, hi));
  }
  root.relative_error = 0.5 * (hi - lo) / root.omega + 10.0 * settings_.relative_tolerance;
  root.residual = std::min(std::abs(a.determinant), std::abs(b.determinant));
  return root;
}

// Brent on the continuous count h_n; the error estimate re-evaluates h_n at 10x tighter
// tolerances and moves the root by one secant step with the slope of the final bracket.
Root ShootingRootFinder::refine_scalar(int n, double lo, double hi) {
  auto g = [this, n](double omega) { return count_function(evaluate(omega), n); };
  const auto [a, b] = brent_zero(g, lo, hi, count_function(samples_.at(lo), n),
                                 count_function(samples_.at(hi), n), settings_.root_tolerance);
  const Sample& sa = evaluate(a);
  const Sample& sb = evaluate(b);
  Root root;
  root.omega = 0.5 * (a + b);
  root.residual = std::min(std::abs(sa.determinant), std::abs(sb.determinant));
  const double ga = count_function(sa, n), gb = count_function(sb, n);
  const double slope = (b > a) ? (gb - ga) / (b - a) : 0.0;
  double integration_error = 10.0 * settings_.relative_tolerance * root.omega;
  if (settings_.error_estimate && slope > 0.0) {
    const Shot tight = shoot_(root.omega, 0.1);
    ++shots_;
    const Sample st{tight.count, tight.angle_min, tight.angle_max, tight.determinant};
    const double here = ga + slope * (root.omega - a);
    integration_error = std::abs((count_function(st, n) - here) / slope);
  }
  root.relative_error = (0.5 * (b - a) + integration_error) / root.omega;
  return root;
}

// Brent on the normalised end determinant (one sign change in a count bracket n - 1 .. n); the
// error estimate is the root of the determinant at 10x tighter tolerances, one secant step away.
Root ShootingRootFinder::refine(double lo, double hi) {
  auto f = [this](double omega) { return evaluate(omega).determinant; };
  const auto [a, b] = brent_zero(f, lo, hi, samples_.at(lo).determinant,
                                 samples_.at(hi).determinant, settings_.root_tolerance);
  const Sample& sa = evaluate(a);
  const Sample& sb = evaluate(b);
  Root root;
  root.omega = 0.5 * (a + b);
  root.residual = std::min(std::abs(sa.determinant), std::abs(sb.determinant));
  const double slope = (b > a) ? (sb.determinant - sa.determinant) / (b - a) : 0.0;
  double integration_error = 10.0 * settings_.relative_tolerance * root.omega;
  if (settings_.error_estimate && slope != 0.0) {
    const Shot tight = shoot_(root.omega, 0.1);
    ++shots_;
    const double here = sa.determinant + slope * (root.omega - a);
    integration_error = std::abs((tight.determinant - here) / slope);
  }
  root.relative_error = (0.5 * (b - a) + integration_error) / root.omega;
  return root;
}

}  // namespace catena::internal
