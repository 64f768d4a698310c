// SPDX-License-Identifier: MIT
// The results JSON of issue 30 (docs/reference/json-layout.md, "Dynamic tension in waves"): the
// problem's drag and water, the request's motion and each solver's `dynamic_tension`, with the
// issue's key names. The solvers on this branch decline the dynamic tension, so the records are
// filled by hand here and must come back value for value; a problem without drag is written as
// before.
#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>

#include "catena/core/types.hpp"
#include "catena/io/json_writer.hpp"
#include "catena/io/scene_reader.hpp"

namespace catena {
namespace {

using nlohmann::json;

const std::string kCable =
    "[cable]\nlength = 1000.0\nweight = 1000.0\nEA = 5.0e8\nmass = 120.0\nadded_mass = 80.0\n"
    "a = [0.0, 0.0]\nb = [900.0, 300.0]\n";

DynamicTensionEnd end_at(double s, double mean, double amplitude, double phase) {
  DynamicTensionEnd end;
  end.s_m = s;
  end.mean_n = mean;
  end.amplitude_n = amplitude;
  end.phase_deg = phase;
  return end;
}

DynamicTension regular_tension(double period) {
  DynamicTension t;
  t.period_s = period;
  t.omega_rad_s = 2.0 * kPi / period;
  t.s_m = Vector::LinSpaced(3, 0.0, 1000.0);
  t.mean_n = (Vector(3) << 6.0e5, 7.0e5, 8.0e5).finished();
  t.amplitude_n = (Vector(3) << 1.0e4, 2.0e4, 3.0e4).finished();
  t.phase_deg = (Vector(3) << -10.0, -5.0, 0.0).finished();
  t.motion_m = (Vector(3) << 0.0, 1.1, 2.0).finished();
  t.normal_damping_n_s_per_m2 = (Vector(3) << 0.0, 50.0, 80.0).finished();
  t.tangential_damping_n_s_per_m2 = (Vector(3) << 1.0, 2.0, 3.0).finished();
  t.anchor = end_at(0.0, 6.0e5, 1.0e4, -10.0);
  t.fairlead = end_at(1000.0, 8.0e5, 3.0e4, 0.0);
  t.iterations = 7;
  t.residual = 3.0e-9;
  t.converged = true;
  t.relative_error_estimate = 2.0e-8;
  return t;
}

DynamicTension irregular_tension() {
  DynamicTension t;
  t.irregular = true;
  t.s_m = Vector::LinSpaced(2, 0.0, 1000.0);
  t.mean_n = (Vector(2) << 6.0e5, 8.0e5).finished();
  t.std_n = (Vector(2) << 4.0e3, 9.0e3).finished();
  t.motion_m = (Vector(2) << 0.0, 1.5).finished();
  t.normal_damping_n_s_per_m2 = (Vector(2) << 0.0, 70.0).finished();
  t.tangential_damping_n_s_per_m2 = (Vector(2) << 0.0, 4.0).finished();
  t.fairlead.s_m = 1000.0;
  t.fairlead.mean_n = 8.0e5;
  t.fairlead.std_n = 9.0e3;
  t.fairlead.zero_upcrossing_period_s = 9.5;
  t.fairlead.most_probable_max_n = 8.0e5 + 9.0e3 * 4.0;
  t.anchor.mean_n = 6.0e5;
  t.anchor.std_n = 4.0e3;
  t.anchor.zero_upcrossing_period_s = 10.5;
  t.anchor.most_probable_max_n = 6.0e5 + 4.0e3 * 4.0;
  t.spectrum_omega_rad_s = (Vector(2) << 0.5, 1.0).finished();
  t.fairlead_spectrum_n2_s_per_rad = (Vector(2) << 1.0e8, 2.0e7).finished();
  t.anchor_spectrum_n2_s_per_rad = (Vector(2) << 3.0e7, 4.0e6).finished();
  t.iterations = 200;
  t.residual = 0.02;
  t.converged = false;
  t.diagnostic = "no fixed point within 200 iterations";
  return t;
}

json written(const std::string& scene_text, std::vector<DynamicTension> tensions) {
  SceneResult result;
  result.scene = parse_scene_text(scene_text, "dt.toml").front();
  result.request = result.scene.request;
  SolverOutput output;
  output.solver = "fe";
  output.dynamic_tension = std::move(tensions);
  result.outputs.push_back(output);
  return json::parse(results_to_json({result}))["scenes"][0];
}

TEST(DynamicTensionJson, RegularRecordsCarryEveryValueUnderTheIssuesNames) {
  const json scene =
      written(kCable +
                  "diameter = 0.1\ndrag_normal = 1.2\n[request.motion]\namplitude = 2.0\n"
                  "periods = [8.0, 12.0]\n",
              {regular_tension(8.0), regular_tension(12.0)});
  const json& list = scene["solvers"]["fe"]["dynamic_tension"];
  ASSERT_EQ(list.size(), 2u) << "one record per period";
  const json& t = list[1];
  EXPECT_EQ(t["motion"], "regular");
  EXPECT_EQ(t["period_s"].get<double>(), 12.0);
  EXPECT_EQ(t["omega_rad_s"].get<double>(), 2.0 * kPi / 12.0);
  const DynamicTension expected = regular_tension(12.0);
  ASSERT_EQ(t["stations"].size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const json& station = t["stations"][i];
    EXPECT_EQ(station["s_m"].get<double>(), expected.s_m[i]);
    EXPECT_EQ(station["mean_n"].get<double>(), expected.mean_n[i]);
    EXPECT_EQ(station["amplitude_n"].get<double>(), expected.amplitude_n[i]);
    EXPECT_EQ(station["phase_deg"].get<double>(), expected.phase_deg[i]);
    EXPECT_EQ(station["motion_m"].get<double>(), expected.motion_m[i]);
    EXPECT_FALSE(station.contains("std_n"));
    EXPECT_EQ(t["damping_n_s_per_m2"][i].get<double>(), expected.normal_damping_n_s_per_m2[i]);
    EXPECT_EQ(t["tangential_damping_n_s_per_m2"][i].get<double>(),
              expected.tangential_damping_n_s_per_m2[i]);
  }
  EXPECT_EQ(t["fairlead"]["amplitude_n"].get<double>(), 3.0e4);
  EXPECT_EQ(t["fairlead"]["mean_n"].get<double>(), 8.0e5);
  EXPECT_EQ(t["anchor"]["phase_deg"].get<double>(), -10.0);
  EXPECT_FALSE(t["fairlead"].contains("most_probable_max_n"));
  EXPECT_FALSE(t.contains("spectrum"));
  EXPECT_EQ(t["iterations"], 7);
  EXPECT_EQ(t["residual"].get<double>(), 3.0e-9);
  EXPECT_EQ(t["converged"], true);
  EXPECT_EQ(t["relative_error_estimate"].get<double>(), 2.0e-8);
  EXPECT_EQ(t["diagnostic"], "");
  // The request's motion and the problem's drag and water.
  const json& motion = scene["request"]["motion"];
  EXPECT_EQ(motion["direction"], "vector");
  EXPECT_EQ(motion["amplitude_m"].get<double>(), 2.0);
  EXPECT_EQ(motion["periods_s"], json({8.0, 12.0}));
  EXPECT_EQ(motion["tolerance"].get<double>(), 1e-8);
  const json& drag = scene["problem"]["cable"]["drag"];
  EXPECT_EQ(drag["diameter_m"].get<double>(), 0.1);
  EXPECT_EQ(drag["drag_normal"].get<double>(), 1.2);
  EXPECT_EQ(drag["drag_tangential"].get<double>(), 0.0);
  EXPECT_EQ(scene["problem"]["environment"]["water_density_kg_per_m3"].get<double>(), 1025.0);
  EXPECT_EQ(scene["problem"]["environment"]["gravity_m_per_s2"].get<double>(), 9.80665);
}

TEST(DynamicTensionJson, IrregularRecordCarriesStdSpectraAndAnUnconvergedFixedPoint) {
  const json scene = written(kCable +
                                 "[environment]\nwater_density = 1020.0\n[request.motion]\n"
                                 "direction = \"out_of_plane\"\njonswap = { hs = 6.0, tp = 12.0 }\n"
                                 "rao = { omega = [0.2, 1.0], amplitude = [1.0, 0.2], per = "
                                 "\"wave_height\" }\n",
                             {irregular_tension()});
  const json& t = scene["solvers"]["fe"]["dynamic_tension"][0];
  EXPECT_EQ(t["motion"], "irregular");
  EXPECT_FALSE(t.contains("period_s"));
  EXPECT_EQ(t["stations"][1]["std_n"].get<double>(), 9.0e3);
  EXPECT_FALSE(t["stations"][1].contains("amplitude_n"));
  EXPECT_EQ(t["fairlead"]["std_n"].get<double>(), 9.0e3);
  EXPECT_EQ(t["fairlead"]["zero_upcrossing_period_s"].get<double>(), 9.5);
  EXPECT_EQ(t["fairlead"]["most_probable_max_n"].get<double>(), 8.0e5 + 9.0e3 * 4.0);
  EXPECT_EQ(t["anchor"]["most_probable_max_n"].get<double>(), 6.0e5 + 4.0e3 * 4.0);
  EXPECT_EQ(t["spectrum"]["omega_rad_s"], json({0.5, 1.0}));
  EXPECT_EQ(t["spectrum"]["fairlead_n2_s_per_rad"], json({1.0e8, 2.0e7}));
  EXPECT_EQ(t["spectrum"]["anchor_n2_s_per_rad"], json({3.0e7, 4.0e6}));
  EXPECT_EQ(t["converged"], false);
  EXPECT_EQ(t["residual"].get<double>(), 0.02);
  EXPECT_EQ(t["diagnostic"], "no fixed point within 200 iterations");
  const json& motion = scene["request"]["motion"];
  EXPECT_EQ(motion["direction"], "out_of_plane");
  EXPECT_FALSE(motion.contains("vector"));
  EXPECT_FALSE(motion.contains("periods_s"));
  EXPECT_EQ(motion["jonswap"]["hs_m"].get<double>(), 6.0);
  EXPECT_EQ(motion["jonswap"]["gamma"].get<double>(), 3.3);
  EXPECT_EQ(motion["rao"]["per"], "wave_height");
  EXPECT_EQ(motion["duration_s"].get<double>(), 10800.0);
  EXPECT_EQ(motion["frequencies"], 200);
  // No drag, but a water that is not the default one: written.
  EXPECT_EQ(scene["problem"]["environment"]["water_density_kg_per_m3"].get<double>(), 1020.0);
  EXPECT_FALSE(scene["problem"]["cable"].contains("drag"));
}

TEST(DynamicTensionJson, WithoutDragOrMotionTheDocumentIsAsBefore) {
  const json scene = written(kCable, {});
  EXPECT_FALSE(scene["problem"].contains("environment"));
  EXPECT_FALSE(scene["problem"]["cable"].contains("drag"));
  EXPECT_FALSE(scene["problem"]["cable"].contains("added_mass_tangential_kg_per_m"));
  EXPECT_FALSE(scene["request"].contains("motion"));
  EXPECT_FALSE(scene["solvers"]["fe"].contains("dynamic_tension"));
}

TEST(DynamicTensionJson, NonFiniteValuesAreNull) {
  DynamicTension t = regular_tension(8.0);
  t.amplitude_n[1] = std::numeric_limits<double>::quiet_NaN();
  t.residual = std::numeric_limits<double>::infinity();
  const json scene = written(kCable + "[request.motion]\namplitude = 2.0\nperiods = [8.0]\n", {t});
  const json& record = scene["solvers"]["fe"]["dynamic_tension"][0];
  EXPECT_TRUE(record["stations"][1]["amplitude_n"].is_null());
  EXPECT_TRUE(record["residual"].is_null());
}

TEST(DynamicTensionJson, SegmentsCarryTheirOwnDragAndTangentialAddedMass) {
  const json scene = written(R"(
[line]
a = [0.0, -100.0]
b = [400.0, 0.0]
[[line.segments]]
length = 300.0
weight = 500.0
EA = 1e8
mass = 60.0
diameter = 0.1
drag_tangential = 0.4
[[line.segments]]
length = 200.0
weight = 200.0
EA = 1e8
mass = 30.0
added_mass_tangential = 2.5
)",
                             {});
  const json& segments = scene["problem"]["line"]["segments"];
  EXPECT_EQ(segments[0]["drag"]["drag_tangential"].get<double>(), 0.4);
  EXPECT_FALSE(segments[0].contains("added_mass_tangential_kg_per_m"));
  EXPECT_FALSE(segments[1].contains("drag"));
  EXPECT_EQ(segments[1]["added_mass_tangential_kg_per_m"].get<double>(), 2.5);
  EXPECT_TRUE(scene["problem"].contains("environment")) << "the line has drag";
}

}  // namespace
}  // namespace catena
