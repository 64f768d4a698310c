// SPDX-License-Identifier: MIT
// The JSON of `catena check` on a tension file (include/catena/io/tension_check_json.hpp): a check
// of a hand-made Catena profile against three stations at four resolutions is written and read
// back; every number must be the comparison's own, absent values null, and the layout the one
// docs/how-to/check-dynamic-tension.md ("Output") documents.
#include "catena/io/tension_check_json.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace catena {
namespace {

TensionCheck sample_check() {
  TensionReference reference;
  reference.solver = "shooting";
  reference.reason = "test";
  DynamicTension& t = reference.tension;
  t.irregular = true;
  t.s_m = Vector::LinSpaced(11, 0.0, 100.0);
  t.std_n = (100.0 + t.s_m.array()).matrix();
  t.converged = true;
  t.relative_error_estimate = 1e-7;
  t.residual = 1e-10;
  t.iterations = 5;
  t.fairlead.s_m = 100.0;
  t.fairlead.std_n = 200.0;
  t.fairlead.most_probable_max_n = 900.0;
  ExternalTension other;
  for (int n : {10, 20, 40, 80}) {
    for (int i : {0, 1, 2}) {
      ExternalTensionStation station;
      station.node = i;
      station.nodes = 3;
      station.resolution = n;
      station.tension_n = (100.0 + 50.0 * i) * (1.0 + 1.0 / (n * n));
      station.origin = "row";
      other.stations.push_back(station);
    }
  }
  return check_external_tension(other, reference);
}

TEST(TensionCheckJson, HoldsEveryNumberOfTheComparison) {
  const TensionCheck check = sample_check();
  const auto document =
      nlohmann::json::parse(tension_check_to_json(check, {"scene", "scene.toml", "other.csv", ""}));
  EXPECT_EQ(document["quantity"], "tension_std_n");
  EXPECT_TRUE(document["period_s"].is_null());
  EXPECT_EQ(document["reference"]["solver"], "shooting");
  EXPECT_TRUE(document["reference"]["shooting_vs_fe_relative"].is_null());
  EXPECT_EQ(document["reference"]["fairlead"]["most_probable_max_n"], 900.0);
  EXPECT_TRUE(document["reference"]["fairlead"]["amplitude_n"].is_null());
  EXPECT_EQ(document["resolution"], 80.0);
  ASSERT_EQ(document["stations"].size(), check.stations.size());
  EXPECT_EQ(document["stations"][2]["difference_n"], check.stations[2].difference_n);
  EXPECT_EQ(document["fairlead"]["s_m"], 100.0);
  ASSERT_EQ(document["studies"].size(), 3u);
  EXPECT_EQ(document["studies"][0]["station"], "anchor");
  EXPECT_EQ(document["studies"][2]["station"], "fairlead");
  EXPECT_EQ(document["studies"][2]["observed_order"], *check.studies[2].study.observed_order);
  EXPECT_EQ(document["studies"][2]["limit_n"], *check.studies[2].study.limit_omega_rad_s);
  EXPECT_EQ(document["verdict"], to_string(check.verdict));
  EXPECT_EQ(document["failed"], check.any_failure());
}

}  // namespace
}  // namespace catena
