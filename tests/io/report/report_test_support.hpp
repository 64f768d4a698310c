// SPDX-License-Identifier: MIT
#pragma once
// A small results document in the layout of report.json (docs/reference/json-layout.md), written by
// hand so that the report's tables can be checked cell by cell: two scenes, four solvers, every
// verdict.
//
//   gale-a    tags gale; fe (2 in-plane modes, 2 forcing frequencies, one at a resonance),
//             frobenius (1 mode), airy declined; published Gale 1976 modes 1 and 3;
//             checks: SOURCE, FAIL, PASS, WARN.
//   stress-1  tags stress, taut-inclined; a scene error; fe numerical failure (long message),
//             shooting converged; one FAIL check comparing shooting with fe.

#include <nlohmann/json.hpp>
#include <string>

namespace catena::testing {

inline std::string long_failure_message() { return "Numerical failure: " + std::string(200, 'x'); }

inline nlohmann::json synthetic_results() {
  nlohmann::json document = nlohmann::json::parse(R"({
    "catena": {"version": "1.2.3", "git": "abc1234", "compiler": "gcc 12", "build_type": "Release",
               "generated_utc": "2024-05-01T12:00:00Z"},
    "scenes": [
      {"name": "gale-a", "description": "Gale's sagging cable", "tags": ["gale"], "error": null,
       "groups": {"eps": 0.5, "chord_angle_deg": 10.0, "lambda2": null, "mass_ratio": 1.0,
                  "gale": {"xi1": -0.5, "xi2": 1.0}},
       "statics": {"horizontal_force_n": 2.0},
       "solvers": {
         "fe": {"summary": {"termination": "converged", "message": "ok", "wall_time_s": 0.002,
                            "max_error_estimate": 1e-9},
                "inplane": {"modes": [
                  {"index": 1, "omega_rad_s": 1.0, "frequency_hz": 0.15915494309189535,
                   "k_l_over_pi": 0.3, "gale_ratio": 1.1, "relative_error_estimate": 1e-10},
                  {"index": 2, "omega_rad_s": 2.0, "frequency_hz": 0.3183098861837907,
                   "k_l_over_pi": 0.6, "gale_ratio": 2.2, "relative_error_estimate": 2e-10}]},
                "forced": [{"omega_rad_s": 0.5, "max_abs_tension_n": 3.0, "diagnostic": ""},
                           {"omega_rad_s": 1.0, "max_abs_tension_n": 0.0, "diagnostic": "resonance"}]},
         "frobenius": {"summary": {"termination": "converged", "message": "ok", "wall_time_s": 0.004,
                                   "max_error_estimate": 1e-12},
                       "inplane": {"modes": [
                         {"index": 1, "omega_rad_s": 1.0000001, "frequency_hz": 0.15915495,
                          "k_l_over_pi": 0.3, "gale_ratio": 1.1000001, "relative_error_estimate": null}]}},
         "airy": {"summary": {"termination": "not-applicable", "message": "H = 0", "wall_time_s": 0.0,
                              "max_error_estimate": null}}},
       "published": [{"source": "Gale 1976", "quantity": "inplane_frequency", "unit": "gale",
                      "modes": [1, 3], "values": [1.1, 3.3]}],
       "checks": [
         {"check": "published", "compare": "fe vs Gale 1976", "plane": "inplane", "mode": 1,
          "value_a": 1.1, "value_b": 1.2, "measured": 0.09, "tolerance": 0.01, "verdict": "SOURCE",
          "detail": "misprint"},
         {"check": "agreement", "compare": "fe vs frobenius", "plane": "inplane", "mode": 2,
          "value_a": 2.2, "value_b": 2.3, "measured": 0.0434, "tolerance": 1e-6, "verdict": "FAIL",
          "detail": "too far"},
         {"check": "published", "compare": "frobenius vs Gale 1976", "plane": "inplane", "mode": 1,
          "value_a": 1.1000001, "value_b": 1.1, "measured": 1e-7, "tolerance": 0.01, "verdict": "PASS",
          "detail": ""},
         {"check": "error_estimate", "compare": "fe", "plane": "inplane", "mode": 1,
          "value_a": null, "value_b": null, "measured": 2e-5, "tolerance": 1e-5, "verdict": "WARN",
          "detail": "estimate large"}]},
      {"name": "stress-1", "description": "", "tags": ["stress", "taut-inclined"],
       "error": "statics did not converge",
       "solvers": {
         "fe": {"summary": {"termination": "numerical-failure", "message": "", "wall_time_s": 0.01,
                            "max_error_estimate": null}},
         "shooting": {"summary": {"termination": "converged", "message": "ok", "wall_time_s": 0.001,
                                  "max_error_estimate": null}}},
       "published": [],
       "checks": [
         {"check": "agreement", "compare": "shooting vs fe", "plane": "inplane", "mode": 1,
          "value_a": 1.0, "value_b": 1.5, "measured": 0.4, "tolerance": 1e-8, "verdict": "FAIL",
          "detail": "disagree"}]}
    ]})");
  document["scenes"][1]["solvers"]["fe"]["summary"]["message"] = long_failure_message();
  return document;
}

}  // namespace catena::testing
