// SPDX-License-Identifier: MIT
// The analytic models' actual error (the registry's models: asymptotic, airy) against the most
// accurate exact solver that ran, over the suite: by eps with lambda^2 and phi ranges, and the
// fitted order in eps.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>

#include "catena/io/csv_table.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "io/report/sections.hpp"

namespace catena::internal {
namespace {

// The reference of a scene is the first exact solver that ran, the most accurate at their default
// targets first (exact_solvers_by_accuracy(): frobenius 1e-11, shooting 1.1e-9, fe 1e-6); the
// models are the registry's SolverKind::Model solvers.

// The fit uses scenes with eps at most this: the models' own validity-warning threshold
// (their eps_warning_threshold knob, docs/reference/solver-knobs.md)...
constexpr double kAsymptoticRangeEps = 0.3;
// ...and errors this many times above the reference's own error estimate for that mode (below,
// the "error" measures the reference as much as the model, and the curve flattens).
constexpr double kMeasurableFactor = 100.0;
// An (lambda^2, phi) group gets its own fitted order when it has this many distinct eps.
constexpr std::size_t kMinDistinctEps = 3;

struct ErrorPoint {
  std::string model, plane, scene, reference;
  double eps = 0.0, lambda2 = 0.0, phi_deg = 0.0;
  int mode = 0;
  double error = 0.0;
  double reference_estimate = 0.0;

  bool measurable() const { return error > 0.0 && error >= kMeasurableFactor * reference_estimate; }
};

bool usable(const json& output) {
  const std::string t = output[key::summary].value(key::termination, "");
  return t == "converged" || t == "no-convergence";
}

// index -> (omega, relative error estimate, 0 when none).
std::map<int, std::pair<double, double>> omegas(const json& output, const char* plane) {
  std::map<int, std::pair<double, double>> out;
  if (!output.contains(plane)) return out;
  for (const auto& m : list_or_empty(output[plane], key::modes)) {
    if (!m[key::omega_rad_s].is_number()) continue;
    const json& estimate = m.value(key::relative_error_estimate, json(nullptr));
    out[m.value(key::index, 0)] = {
        m[key::omega_rad_s].get<double>(),
        estimate.is_number() ? std::max(0.0, estimate.get<double>()) : 0.0};
  }
  return out;
}

void collect_scene(const json& scene,
                   const std::vector<std::string>& reference_order,
                   const std::vector<std::string>& models,
                   std::vector<ErrorPoint>& points) {
  // The fit is of the models' undamped frequency error in eps; on a damped scene omega_d also
  // carries the models' light-damping perturbation (held by the decay-rate check instead), which
  // would blur it.
  if (!scene.contains(key::groups) || is_damped_scene(scene)) return;
  const json& g = scene[key::groups];
  const json& solvers = scene[key::solvers];
  for (const char* plane : {key::inplane, key::outofplane}) {
    std::string reference;
    for (const std::string& r : reference_order) {
      if (reference.empty() && solvers.contains(r) && usable(solvers[r]) &&
          !omegas(solvers[r], plane).empty())
        reference = r;
    }
    if (reference.empty()) continue;
    const auto exact = omegas(solvers[reference], plane);
    for (const std::string& model : models) {
      if (!solvers.contains(model) || !usable(solvers[model])) continue;
      for (const auto& [index, value] : omegas(solvers[model], plane)) {
        if (!exact.count(index)) continue;
        const auto [truth, truth_estimate] = exact.at(index);
        points.push_back({model, plane, scene.value(key::name, ""), reference,
                          g.value(key::eps, 0.0),
                          g[key::lambda2].is_number() ? g[key::lambda2].get<double>() : INFINITY,
                          g.value(key::chord_angle_deg, 0.0), index,
                          std::abs(value.first - truth) / std::abs(truth), truth_estimate});
      }
    }
  }
}

// Least squares of ln(error) on ln(eps): the order p and constant C of error ~ C eps^p.
struct Fit {
  int scenes = 0;
  double order = NAN, constant = NAN;
};

Fit fit_order(const std::vector<std::pair<double, double>>& eps_error) {
  Fit fit;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& [eps, error] : eps_error) {
    const double x = std::log(eps), y = std::log(error);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
    ++fit.scenes;
  }
  const double n = fit.scenes, det = n * sxx - sx * sx;
  if (fit.scenes < 2 || !(std::abs(det) > 1e-12 * n * sxx)) return fit;
  fit.order = (n * sxy - sx * sy) / det;
  fit.constant = std::exp((sy - fit.order * sx) / n);
  return fit;
}

std::string range_text(double lo, double hi) {
  return lo == hi ? fmt::format("{:.4g}", lo) : fmt::format("{:.4g} - {:.4g}", lo, hi);
}

using PointGroup = std::map<std::pair<std::string, std::string>, std::vector<const ErrorPoint*>>;

// One point per scene in the asymptotic range: (eps, median error over its modes), when that
// median is measurable against the reference.
std::vector<std::pair<double, double>> scene_points(const std::vector<const ErrorPoint*>& points) {
  std::map<std::string, std::vector<const ErrorPoint*>> by_scene;
  for (const ErrorPoint* p : points) {
    if (p->eps > 0.0 && p->eps <= kAsymptoticRangeEps) by_scene[p->scene].push_back(p);
  }
  std::vector<std::pair<double, double>> out;
  for (auto& [scene, list] : by_scene) {
    std::sort(list.begin(), list.end(), [](auto* a, auto* b) { return a->error < b->error; });
    const ErrorPoint* median = list[list.size() / 2];
    if (median->measurable()) out.push_back({median->eps, median->error});
  }
  return out;
}

std::vector<std::string> fit_row(const std::string& model,
                                 const std::string& plane,
                                 const std::string& lambda2,
                                 const std::string& phi,
                                 const std::vector<std::pair<double, double>>& eps_error) {
  double lo = INFINITY, hi = 0.0;
  for (const auto& [eps, error] : eps_error) lo = std::min(lo, eps), hi = std::max(hi, eps);
  const Fit fit = fit_order(eps_error);
  return {model,
          plane,
          lambda2,
          phi,
          std::to_string(fit.scenes),
          fit.scenes ? range_text(lo, hi) : "-",
          number_text(fit.order, "{:.2f}"),
          number_text(fit.constant, "{:.3g}")};
}

void add_fit_table(Document& out, const PointGroup& groups) {
  Table t{{"model", "plane", "lambda^2", "phi [deg]", "scenes fitted", "eps range",
           "fitted order p", "constant C"},
          {},
          "model-error"};
  for (const auto& [what, points] : groups) {
    t.rows.push_back(fit_row(what.first, what.second, "all", "all", scene_points(points)));
    std::map<std::pair<std::string, std::string>, std::vector<const ErrorPoint*>> by_group;
    for (const ErrorPoint* p : points) {
      by_group[{fmt::format("{:.4g}", p->lambda2), fmt::format("{:.4g}", p->phi_deg)}].push_back(p);
    }
    for (const auto& [group, list] : by_group) {
      const auto eps_error = scene_points(list);
      std::vector<double> distinct;
      for (const auto& e : eps_error) {
        if (std::find(distinct.begin(), distinct.end(), e.first) == distinct.end())
          distinct.push_back(e.first);
      }
      if (distinct.size() >= kMinDistinctEps)
        t.rows.push_back(fit_row(what.first, what.second, group.first, group.second, eps_error));
    }
  }
  add_table_or_none(out, std::move(t));
}

void add_by_eps_table(Document& out, const PointGroup& groups) {
  Table t{{"model", "plane", "eps", "scenes", "lambda^2", "phi [deg]", "modes", "median error",
           "max error"},
          {},
          "model-error"};
  for (const auto& [what, points] : groups) {
    std::map<double, std::vector<const ErrorPoint*>> by_eps;
    for (const ErrorPoint* p : points)
      // strtod, not stod: a subnormal eps (a results file may hold 1e-308) is a value, not an
      // out_of_range exception (found by the report fuzz target).
      by_eps[std::strtod(fmt::format("{:.3g}", p->eps).c_str(), nullptr)].push_back(p);
    for (const auto& [eps, list] : by_eps) {
      std::vector<double> errors;
      std::map<std::string, int> scenes;
      double l_lo = INFINITY, l_hi = 0, p_lo = INFINITY, p_hi = 0;
      for (const ErrorPoint* p : list) {
        errors.push_back(p->error);
        ++scenes[p->scene];
        l_lo = std::min(l_lo, p->lambda2), l_hi = std::max(l_hi, p->lambda2);
        p_lo = std::min(p_lo, p->phi_deg), p_hi = std::max(p_hi, p->phi_deg);
      }
      std::sort(errors.begin(), errors.end());
      t.rows.push_back(
          {what.first, what.second, fmt::format("{:.3g}", eps), std::to_string(scenes.size()),
           range_text(l_lo, l_hi), range_text(p_lo, p_hi), std::to_string(errors.size()),
           fmt::format("{:.2e}", errors[errors.size() / 2]), fmt::format("{:.2e}", errors.back())});
    }
  }
  add_table_or_none(out, std::move(t));
}

void write_points(const std::vector<ErrorPoint>& points, const std::filesystem::path& data_dir) {
  CsvTable csv{{"Actual relative error of the analytic models against the most accurate exact "
                "solver that ran "
                "(reference). Written by catena report from report.json."},
               {"model", "plane", "scene", "eps", "lambda2", "phi_deg", "mode", "relative_error",
                "reference"},
               {}};
  for (const auto& p : points) {
    csv.rows.push_back({p.model, p.plane, p.scene, fmt::format("{:.17g}", p.eps),
                        fmt::format("{:.17g}", p.lambda2), fmt::format("{:.17g}", p.phi_deg),
                        std::to_string(p.mode), fmt::format("{:.6e}", p.error), p.reference});
  }
  std::filesystem::create_directories(data_dir);
  write_csv_table(data_dir / "model-error.csv", csv);
}

}  // namespace

void add_model_error(Document& out, const json& document, const std::filesystem::path& data_dir) {
  std::vector<ErrorPoint> points;
  const std::vector<std::string> reference_order = exact_solvers_by_accuracy();
  const std::vector<std::string> models = solver_names(SolverKind::Model);
  for (const auto& scene : document[key::scenes])
    collect_scene(scene, reference_order, models, points);
  write_points(points, data_dir);
  out.push_back(Heading{2, "Model error of the analytic solvers", "model-error"});
  out.push_back(
      Paragraph{fmt::format("{} against the most accurate exact solver that ran "
                            "on the scene ({}), relative error of each mode's frequency. Fitted "
                            "order: least squares of ln(error) on ln(eps), "
                            "error ~ C eps^p, one point per scene (the median over its modes) over "
                            "the models' range: eps <= {:g} "
                            "(the models' validity-warning threshold) and a median error at least "
                            "{:g} x the reference's own estimate "
                            "(below, the reference's error shows). First over every scene ('all': "
                            "lambda^2 and phi vary too), then for each "
                            "(lambda^2, phi) with at least {} distinct eps. The in-plane error "
                            "also carries the strain term T0/(2 EA), "
                            "which does not scale with eps. Every point: data/model-error.csv.",
                            fmt::join(models, " and "), fmt::join(reference_order, ", else "),
                            kAsymptoticRangeEps, kMeasurableFactor, kMinDistinctEps)});
  PointGroup groups;
  for (const auto& p : points) groups[{p.model, p.plane}].push_back(&p);
  add_fit_table(out, groups);
  add_by_eps_table(out, groups);
}

}  // namespace catena::internal
