// SPDX-License-Identifier: MIT
#include "verification/internal/mode_mix.hpp"

#include <cmath>

namespace catena::internal {

Vector stacked_shape(const Mode& mode, Plane plane) {
  if (plane == Plane::OutOfPlane) return mode.v;
  Vector out(mode.u.size() + mode.w.size());
  out << mode.u, mode.w;
  return out;
}

bool has_stacked_shape(const Mode& mode, Plane plane) {
  return plane == Plane::OutOfPlane ? mode.v.size() > 0 : (mode.u.size() > 0 && mode.w.size() > 0);
}

double one_minus_mac(const Vector& p, const Vector& q) {
  return 1.0 - std::pow(p.dot(q), 2) / (p.squaredNorm() * q.squaredNorm());
}

std::optional<double> mix_for_mac_drop(const Vector& p, const Vector& r, double drop) {
  if (p.size() != r.size() || p.size() == 0 || !(drop > 0.0)) return std::nullopt;
  auto drop_at = [&](double delta) { return one_minus_mac(p, Vector(p + delta * r)); };
  // The limit of large delta, less a margin: beyond it the drop is not reachable.
  const double reachable = 1.0 - std::pow(p.dot(r), 2) / (p.squaredNorm() * r.squaredNorm());
  if (!(drop < 0.5 * reachable)) return std::nullopt;
  double lo = 0.0, hi = 1.0;
  while (drop_at(hi) < drop) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (drop_at(mid) < drop ? lo : hi) = mid;
  }
  return hi;
}

namespace {

// The signed value of `x` at its first station of largest magnitude (0 for an empty vector).
double signed_peak(const Vector& x) {
  Index at = 0;
  for (Index i = 0; i < x.size(); ++i) {
    if (std::abs(x[i]) > std::abs(x[at])) at = i;
  }
  return x.size() ? x[at] : 0.0;
}

void add_scaled(Vector& x, const Vector& y, double delta) {
  if (x.size() && x.size() == y.size()) x += delta * y;
}

}  // namespace

void mix_modes(Mode& mode, const Mode& neighbour, double delta) {
  add_scaled(mode.u, neighbour.u, delta);
  add_scaled(mode.w, neighbour.w, delta);
  add_scaled(mode.v, neighbour.v, delta);
  add_scaled(mode.tension_n, neighbour.tension_n, delta);
  const bool by_v = mode.normalised_by == "v" || (mode.normalised_by.empty() && mode.v.size());
  const Vector& by = mode.normalised_by == "u" ? mode.u : by_v ? mode.v : mode.w;
  const double peak = signed_peak(by);
  if (peak == 0.0) return;
  for (Vector* x : {&mode.u, &mode.w, &mode.v, &mode.tension_n}) *x /= peak;
  if (mode.tension_n.size() && mode.max_abs_tension_n >= 0.0)
    mode.max_abs_tension_n = mode.tension_n.cwiseAbs().maxCoeff();
}

}  // namespace catena::internal
