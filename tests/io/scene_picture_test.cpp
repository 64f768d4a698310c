// SPDX-License-Identifier: MIT
// The scene picture (include/catena/io/scene_picture.hpp; `catena plot`, `catena solve --plot`),
// golden-free: a line of two segments over a seabed, with a clump weight and a buoy, is solved
// (shooting, shapes asked) and drawn. The SVG must parse as XML (Boost.PropertyTree's parser), hold
// one path per segment and per drawn mode, keep every coordinate inside its viewBox, and put the
// seabed, the ends and the touchdown where the scene puts them: the panel's own transform (its
// data-x-range, data-y-range and data-frame attributes) read back into metres is compared with the
// scene's numbers, not with the JSON the picture was drawn from. Then bad input through the CLI:
// exit 2 naming the file or the option.
#include "catena/io/scene_picture.hpp"

#include <gtest/gtest.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/json_writer.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/io/tolerance_reader.hpp"
#include "catena/verification/scene_runner.hpp"
#include "cli/cli_support.hpp"

namespace {

namespace fs = std::filesystem;
namespace pt = boost::property_tree;
using catena::testing::run_cli;
using catena::testing::write_temp_file;

constexpr const char* kFolder = "catena_scene_picture_test";
constexpr double kSeabedZ = -200.0;
constexpr double kBx = 780.0, kBz = -20.0;

// Chain on the seabed from a, then wire up to b; a clump (20 kN) grounded at s = 600 m and a buoy
// (lifting 30 kN) at s = 750 m on the suspended wire. 121 stations.
std::string scene_text(bool shapes) {
  return std::string(
             "name = \"picture-line\"\n[line]\na = [0.0, -200.0]\nb = [780.0, -20.0]\n"
             "[[line.segments]]\nlength = 400.0\nweight = 1000.0\nEA = 1.0e9\nmass = 120.0\n"
             "added_mass = 20.0\n"
             "[[line.segments]]\nlength = 500.0\nweight = 300.0\nEA = 5.0e8\nmass = 40.0\n"
             "added_mass = 8.0\n"
             "[[line.points]]\ns = 600.0\nmass = 3000.0\nweight = 20000.0\n"
             "[[line.points]]\ns = 750.0\nmass = 2000.0\nweight = -30000.0\n"
             "[seabed]\nz = -200.0\n"
             "[request]\ninplane_modes = 3\noutofplane_modes = 2\npoints = 121\nshapes = ") +
         (shapes ? "true" : "false") + "\n[solvers]\nshooting = {}\n";
}

std::string solved_json(bool shapes) {
  catena::SceneRunOptions options;
  options.tolerances = catena::builtin_tolerance_table();
  std::vector<catena::SceneResult> results;
  for (const auto& scene : catena::parse_scene_text(scene_text(shapes), "picture-line.toml"))
    results.push_back(catena::run_scene(scene, options));
  return catena::results_to_json(results);
}

class ScenePicture : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    results_ = new std::string(solved_json(true));
    std::istringstream svg(catena::scene_picture_svg(*results_, "picture-line.json", "", {}));
    tree_ = new pt::ptree;
    pt::read_xml(svg, *tree_);  // throws on anything that is not well-formed XML
  }
  static void TearDownTestSuite() {
    delete results_;
    delete tree_;
  }
  static const pt::ptree& svg() { return tree_->get_child("svg"); }
  static std::string* results_;
  static pt::ptree* tree_;
};
std::string* ScenePicture::results_ = nullptr;
pt::ptree* ScenePicture::tree_ = nullptr;

std::string attribute(const pt::ptree& element, const std::string& name) {
  return element.get<std::string>("<xmlattr>." + name, "");
}

// Every element below `node` (depth first) with its tag.
void collect(const pt::ptree& node,
             const std::string& tag,
             std::vector<std::pair<std::string, const pt::ptree*>>& out) {
  out.emplace_back(tag, &node);
  for (const auto& [child_tag, child] : node) {
    if (child_tag != "<xmlattr>" && child_tag != "<xmlcomment>") collect(child, child_tag, out);
  }
}

std::vector<double> numbers_in(const std::string& text) {
  std::vector<double> out;
  std::string cleaned = text;
  for (char& c : cleaned) c = c == ',' ? ' ' : c;
  std::istringstream in(cleaned);
  for (double value; in >> value;) out.push_back(value);
  return out;
}

// A panel's transform read back: data units of a pixel position.
struct PanelTransform {
  double x_low, x_high, y_low, y_high, left, top, right, bottom;
  double x(double px) const { return x_low + (px - left) / (right - left) * (x_high - x_low); }
  double z(double py) const { return y_low + (bottom - py) / (bottom - top) * (y_high - y_low); }
  // Coordinates are printed to 0.01 px: half of that, in data units.
  double resolution() const { return 0.005 * (y_high - y_low) / (bottom - top); }
};

PanelTransform transform_of(const pt::ptree& panel) {
  const auto xr = numbers_in(attribute(panel, "data-x-range"));
  const auto yr = numbers_in(attribute(panel, "data-y-range"));
  const auto frame = numbers_in(attribute(panel, "data-frame"));
  EXPECT_EQ(xr.size(), 2u);
  EXPECT_EQ(yr.size(), 2u);
  EXPECT_EQ(frame.size(), 4u);
  return {xr.at(0),    xr.at(1),    yr.at(0),    yr.at(1),
          frame.at(0), frame.at(1), frame.at(2), frame.at(3)};
}

const pt::ptree& panel(const pt::ptree& svg, const std::string& id) {
  for (const auto& [tag, child] : svg) {
    if (tag == "g" && attribute(child, "id") == "panel-" + id) return child;
  }
  throw std::runtime_error("no panel " + id);
}

int count_role(const pt::ptree& node, const std::string& tag, const std::string& role) {
  std::vector<std::pair<std::string, const pt::ptree*>> all;
  collect(node, "", all);
  int count = 0;
  for (const auto& [t, element] : all) count += t == tag && attribute(*element, "class") == role;
  return count;
}

TEST_F(ScenePicture, HasOnePathPerSegmentAndPerDrawnMode) {
  const pt::ptree& profile = panel(svg(), "profile");
  EXPECT_EQ(count_role(profile, "polyline", "segment"), 2);  // chain, wire
  EXPECT_EQ(count_role(profile, "polyline", "mode"), 3);     // in-plane 1, 2, 3
  EXPECT_EQ(count_role(panel(svg(), "out-of-plane"), "polyline", "mode"), 2);
  EXPECT_EQ(count_role(panel(svg(), "tension"), "polyline", "tension"), 2);
  EXPECT_EQ(count_role(profile, "polygon", "point"), 2);  // the clump and the buoy
}

TEST_F(ScenePicture, EveryCoordinateIsInsideTheViewBox) {
  const auto box = numbers_in(attribute(svg(), "viewBox"));
  ASSERT_EQ(box.size(), 4u);
  std::vector<std::pair<std::string, const pt::ptree*>> all;
  collect(svg(), "svg", all);
  int checked = 0;
  for (const auto& [tag, element] : all) {
    for (const char* name : {"x", "x1", "x2", "cx"}) {
      for (double v : numbers_in(attribute(*element, name))) {
        EXPECT_TRUE(v >= box[0] && v <= box[0] + box[2]) << tag << " " << name << " = " << v;
        ++checked;
      }
    }
    for (const char* name : {"y", "y1", "y2", "cy"}) {
      for (double v : numbers_in(attribute(*element, name))) {
        EXPECT_TRUE(v >= box[1] && v <= box[1] + box[3]) << tag << " " << name << " = " << v;
        ++checked;
      }
    }
    const auto points = numbers_in(attribute(*element, "points"));
    for (std::size_t i = 0; i + 1 < points.size(); i += 2, ++checked) {
      EXPECT_TRUE(points[i] >= box[0] && points[i] <= box[0] + box[2]) << tag << " x " << points[i];
      EXPECT_TRUE(points[i + 1] >= box[1] && points[i + 1] <= box[1] + box[3])
          << tag << " y " << points[i + 1];
    }
  }
  EXPECT_GT(checked, 1000);  // the paths' points were seen
}

TEST_F(ScenePicture, SeabedEndsAndTouchdownAreWhereTheSceneSaysInMetres) {
  const pt::ptree& profile = panel(svg(), "profile");
  const PanelTransform t = transform_of(profile);
  const double tolerance = t.resolution();
  std::vector<std::pair<std::string, const pt::ptree*>> all;
  collect(profile, "g", all);
  int seabeds = 0, touchdowns = 0, ends = 0;
  double lowest = INFINITY;
  for (const auto& [tag, element] : all) {
    const std::string role = attribute(*element, "class");
    if (tag == "line" && role == "seabed") {
      ++seabeds;
      EXPECT_NEAR(t.z(element->get<double>("<xmlattr>.y1")), kSeabedZ, tolerance);
      EXPECT_NEAR(t.z(element->get<double>("<xmlattr>.y2")), kSeabedZ, tolerance);
    }
    if (role == "touchdown") {
      ++touchdowns;
      EXPECT_NEAR(t.z(element->get<double>("<xmlattr>.cy")), kSeabedZ, tolerance);
    }
    if (tag == "rect" && role == "end") {  // end a, a square of side 10 px centred on it
      ++ends;
      EXPECT_NEAR(t.x(element->get<double>("<xmlattr>.x") + 5.0), 0.0, tolerance);
      EXPECT_NEAR(t.z(element->get<double>("<xmlattr>.y") + 5.0), kSeabedZ, tolerance);
    }
    if (tag == "polygon" && role == "end") {  // end b, a diamond: its first vertex 5 px above
      ++ends;
      const auto p = numbers_in(attribute(*element, "points"));
      EXPECT_NEAR(t.x(p.at(0)), kBx, tolerance);
      EXPECT_NEAR(t.z(p.at(1) + 5.0), kBz, tolerance);
    }
    if (tag == "polyline" && role == "segment") {
      const auto p = numbers_in(attribute(*element, "points"));
      for (std::size_t i = 1; i < p.size(); i += 2) lowest = std::min(lowest, t.z(p[i]));
    }
  }
  EXPECT_EQ(seabeds, 1);
  EXPECT_EQ(touchdowns, 1);  // the chain lies from a to the touchdown: one touchdown
  EXPECT_EQ(ends, 2);
  // The line rests on the seabed and never goes below it.
  EXPECT_NEAR(lowest, kSeabedZ, tolerance);
  // Equal axes: a metre is as many pixels across as up.
  EXPECT_NEAR((t.right - t.left) / (t.x_high - t.x_low), (t.bottom - t.top) / (t.y_high - t.y_low),
              1e-9 * (t.right - t.left) / (t.x_high - t.x_low));
}

TEST_F(ScenePicture, DataForMatplotlibHoldsTheSamePanels) {
  const auto data = nlohmann::json::parse(catena::scene_picture_data(*results_, "r", "", {}));
  ASSERT_EQ(data.at("panels").size(), 3u);
  EXPECT_EQ(data.at("panels")[0].at("id"), "profile");
  EXPECT_TRUE(data.at("panels")[0].at("equal_axes").get<bool>());
  int segments = 0, modes = 0;
  for (const auto& s : data.at("panels")[0].at("series")) {
    segments += s.at("role") == "segment";
    modes += s.at("role") == "mode";
  }
  EXPECT_EQ(segments, 2);
  EXPECT_EQ(modes, 3);
  // The title names the reference solver of the modes.
  EXPECT_NE(data.at("title").dump().find("shooting"), std::string::npos) << data.at("title");
}

TEST(ScenePictureInput, ResultsWithoutProfileOrStaticsAreRefusedSayingWhy) {
  try {
    catena::scene_picture_svg(solved_json(false), "no-shapes.json", "", {});
    FAIL() << "drawn without a profile";
  } catch (const catena::InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("shapes = true"), std::string::npos) << e.what();
  }
  EXPECT_THROW(catena::scene_picture_svg("{\"catena\": {}}", "x.json", "", {}), catena::ParseError);
  catena::ScenePictureOptions bad;
  bad.mode_scale = 0.0;
  EXPECT_THROW(bad.validate(), catena::InvalidInput);
}

TEST(PlotCommand, BadInputExitsTwoNamingIt) {
  const fs::path scene = write_temp_file(kFolder, "line.toml", scene_text(false));
  // Not a results file: a scene.
  auto run =
      run_cli("plot " + scene.string() + " --out " + (scene.parent_path() / "a.svg").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find(scene.string()), std::string::npos) << run.output;
  // No statics in it: a scene whose statics failed (on the seabed, Newton does not converge).
  std::string failed = scene_text(false);
  failed.replace(failed.find("b = [780.0"), 10, "b = [820.0");
  const fs::path failed_scene = write_temp_file(kFolder, "failed.toml", failed);
  const fs::path failed_json = scene.parent_path() / "failed.json";
  run_cli("solve " + failed_scene.string() + " --json " + failed_json.string() + " -q");
  run = run_cli("plot " + failed_json.string() + " --out " +
                (scene.parent_path() / "b.svg").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("no statics"), std::string::npos) << run.output;
  // An output that cannot be written, and one that is neither .svg nor .png.
  run = run_cli("plot " + failed_json.string() + " --out /proc/catena-no-such-dir/x.svg");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("/proc/catena-no-such-dir/x.svg"), std::string::npos) << run.output;
  run = run_cli("solve " + scene.string() + " --plot " + (scene.parent_path() / "x.pdf").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("--plot"), std::string::npos) << run.output;
  run = run_cli("plot " + failed_json.string() + " --modes 1,x");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("--modes"), std::string::npos) << run.output;
}

TEST(PlotCommand, SolvePlotAsksForTheShapesItDraws) {
  // The scene asks for no shapes; --plot asks the solvers for them.
  const fs::path scene = write_temp_file(kFolder, "plain.toml", scene_text(false));
  const fs::path svg = scene.parent_path() / "plain.svg";
  fs::remove(svg);
  const auto run = run_cli("solve " + scene.string() + " --plot " + svg.string() + " -q");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::ifstream file(svg);
  std::stringstream text;
  text << file.rdbuf();
  pt::ptree tree;
  pt::read_xml(text, tree);
  EXPECT_EQ(count_role(tree.get_child("svg"), "polyline", "segment"), 2);
  EXPECT_EQ(count_role(tree.get_child("svg"), "polyline", "mode"), 5);
}

}  // namespace
