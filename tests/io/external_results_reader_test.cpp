// SPDX-License-Identifier: MIT
// Reading another program's results for `catena check`
// (include/catena/io/external_results_reader.hpp): CSV with a long-format shapes CSV, JSON, plane
// spellings, and bad input naming file, row/path and column. Files are written by the test to a
// temporary directory.
#include "catena/io/external_results_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/core/error.hpp"
#include "cli/cli_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

std::filesystem::path file(const std::string& name, const std::string& text) {
  return testing::write_temp_file("catena_external_results_test", name, text);
}

TEST(ExternalResultsReader, PlaneSpellingsAreCaseInsensitive) {
  for (const char* text : {"in-plane", "INPLANE", "In-Plane"})
    EXPECT_EQ(parse_plane(text), Plane::InPlane) << text;
  for (const char* text : {"out-of-plane", "OutOfPlane"})
    EXPECT_EQ(parse_plane(text), Plane::OutOfPlane) << text;
  EXPECT_FALSE(parse_plane("in plane").has_value());
}

TEST(ExternalResultsReader, CsvWithShapesAttachesEachShapeToItsResult) {
  const auto results = file("r.csv",
                            "# from code X\nplane,mode,resolution,frequency_hz\nin-plane,1,10,0.5\n"
                            "in-plane,1,20,0.52\nout-of-plane,1,20,0.4\n");
  const auto shapes =
      file("s.csv",
           "plane,mode,resolution,station_s_m,u,w,v,tension_n\n"
           "in-plane,1,20,0,0.1,0,,5\nin-plane,1,20,50,0.1,1,,6\nin-plane,1,20,100,0.1,0,,5\n"
           "outofplane,1,20,0,,,0,\noutofplane,1,20,100,,,0,\noutofplane,1,20,50,,,1,\n");
  const auto modes = read_external_results(results, shapes);
  ASSERT_EQ(modes.size(), 3u);
  EXPECT_NEAR(modes[0].omega_rad_s, 2 * kPi * 0.5, 1e-15);
  EXPECT_FALSE(modes[0].shape.has_value());
  ASSERT_TRUE(modes[1].shape.has_value());
  EXPECT_EQ(modes[1].shape->w.size(), 3);
  EXPECT_EQ(modes[1].shape->tension_n[1], 6.0);
  EXPECT_EQ(modes[1].shape->v.size(), 0);
  EXPECT_EQ(modes[2].shape->v.size(), 3);
  EXPECT_EQ(modes[2].shape->u.size(), 0);
}

TEST(ExternalResultsReader, ShapeOfAModeWithoutResultIsRejected) {
  const auto results = file("r2.csv", "plane,mode,frequency_hz\nin-plane,1,0.5\n");
  const auto shapes = file("s2.csv", "plane,mode,station_s_m,w\nin-plane,2,0,0\nin-plane,2,10,1\n");
  testing::expect_invalid([&] { read_external_results(results, shapes); }, "s2.csv row 1 (line 2)");
  const auto ragged = file("s3.csv", "plane,mode,station_s_m,w\nin-plane,1,0,0\nin-plane,1,10,\n");
  testing::expect_invalid([&] { read_external_results(results, ragged); },
                          "row 2 (line 3), column 'w'");
}

TEST(ExternalResultsReader, JsonWithShapes) {
  const auto path =
      file("r.json", R"({"results": [{"plane": "out-of-plane", "mode": 2, "resolution": 40,
      "omega_rad_s": 1.5, "shape": {"s_m": [0, 1, 2], "v": [0, 1, 0]}}]})");
  const auto modes = read_external_results(path);
  ASSERT_EQ(modes.size(), 1u);
  EXPECT_EQ(modes[0].plane, Plane::OutOfPlane);
  EXPECT_EQ(modes[0].mode, 2);
  EXPECT_EQ(*modes[0].resolution, 40.0);
  EXPECT_EQ(modes[0].shape->v[1], 1.0);
}

TEST(ExternalResultsReader, JsonErrorsNameThePath) {
  testing::expect_invalid(
      [&] {
        read_external_results(
            file("a.json", R"({"results": [{"plane": "up", "mode": 1, "omega_rad_s": 1}]})"));
      },
      "results[0].plane");
  testing::expect_invalid(
      [&] {
        read_external_results(file(
            "b.json", R"({"results": [{"plane": "inplane", "mode": 1, "omega_rad_s": "x"}]})"));
      },
      "results[0].omega_rad_s");
  testing::expect_invalid(
      [&] {
        read_external_results(file(
            "c.json",
            R"({"results": [{"plane": "inplane", "mode": 1, "omega_rad_s": 1, "shape": {"s_m": [0, "a"]}}]})"));
      },
      "results[0].shape.s_m[1]");
  testing::expect_invalid([&] { read_external_results(file("d.json", R"({"results": []})")); },
                          "non-empty");
  testing::expect_invalid(
      [&] {
        read_external_results(file(
            "e.json", R"({"results": [{"plane": "inplane", "mode": 1, "omega_rad_s": NaN}]})"));
      },
      "not valid JSON");
  testing::expect_invalid(
      [&] {
        read_external_results(file(
            "f.json",
            R"([{"plane": "inplane", "mode": 1, "omega_rad_s": 1}, {"plane": "inplane", "mode": 1, "omega_rad_s": 2}])"));
      },
      "duplicate");
}

// The text entry point (used by the Python module for rows given in memory) reads what the file
// reader reads, and names its origin where the file name would be.
TEST(ExternalResultsReader, JsonTextEqualsJsonFile) {
  const std::string text =
      R"({"results": [{"plane": "in-plane", "mode": 1, "resolution": 20, "frequency_hz": 0.5},
      {"plane": "outofplane", "mode": 2, "omega_rad_s": 1.5, "shape": {"s_m": [0, 1], "v": [0, 1]}}]})";
  const auto from_file = read_external_results(file("g.json", text));
  const auto from_text = parse_external_results_json(text, "<results>");
  ASSERT_EQ(from_text.size(), from_file.size());
  for (std::size_t i = 0; i < from_text.size(); ++i) {
    EXPECT_EQ(from_text[i].plane, from_file[i].plane);
    EXPECT_EQ(from_text[i].omega_rad_s, from_file[i].omega_rad_s);
    EXPECT_EQ(from_text[i].resolution, from_file[i].resolution);
    EXPECT_EQ(from_text[i].shape.has_value(), from_file[i].shape.has_value());
  }
  EXPECT_EQ(from_text[1].origin, "<results>: results[1]");
  testing::expect_invalid(
      [&] {
        parse_external_results_json(R"([{"plane": "up", "mode": 1, "omega_rad_s": 1}])",
                                    "<results>");
      },
      "<results>: results[0].plane");
  testing::expect_invalid(
      [&] {
        parse_external_results_json(R"([{"plane": "inplane", "mode": 1, "omega_rad_s": 1},
      {"plane": "inplane", "mode": 1, "omega_rad_s": 2}])",
                                    "<results>");
      },
      "duplicate");
}

// issue 32: a header naming a column twice is refused naming it (the reader would have read the
// first only); a spreadsheet's UTF-8 byte order mark is not part of the first column's name.
TEST(ExternalResultsReader, CsvDuplicateColumnIsRefusedAndAByteOrderMarkIsStripped) {
  try {
    read_external_results(file("dup.csv", "plane,mode,omega_rad_s,mode\ninplane,1,2.0,2\n"));
    ADD_FAILURE() << "a duplicate column was read";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("column 'mode' appears twice"), std::string::npos)
        << error.what();
  }
  const auto modes =
      read_external_results(file("bom.csv", "\xEF\xBB\xBFplane,mode,omega_rad_s\ninplane,2,3.5\n"));
  ASSERT_EQ(modes.size(), 1u);
  EXPECT_EQ(modes[0].mode, 2);
  EXPECT_EQ(modes[0].omega_rad_s, 3.5);
}

// issue 32: nlohmann keeps the last of two equal keys silently; a results file with one is refused
// naming the key, and so is one nested deeper than any results file.
TEST(ExternalResultsReader, JsonDuplicateKeysAndDeepNestingAreRefused) {
  testing::expect_invalid(
      [&] {
        read_external_results(file(
            "dupkey.json",
            R"({"results": [{"plane": "inplane", "mode": 1, "omega_rad_s": 1, "omega_rad_s": 2}]})"));
      },
      "key 'omega_rad_s' given twice");
  testing::expect_invalid(
      [&] {
        read_external_results(
            file("dupresults.json", R"({"results": [], "results": [{"plane": "inplane"}]})"));
      },
      "key 'results' given twice");
  // Found by the check fuzz target: nlohmann throws out_of_range for 31e308, not parse_error.
  testing::expect_invalid(
      [&] {
        read_external_results(
            file("overflow.json", R"([{"plane": "inplane", "mode": 1, "omega_rad_s": 31e308}])"));
      },
      "beyond the range of double");
  const std::string deep =
      "{\"results\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  testing::expect_invalid([&] { read_external_results(file("deep.json", deep)); },
                          "nested deeper than");
  // The same key in two different objects is fine.
  const auto modes = read_external_results(file(
      "two.json",
      R"({"results": [{"plane": "inplane", "mode": 1, "omega_rad_s": 1}, {"plane": "inplane", "mode": 2, "omega_rad_s": 2}]})"));
  EXPECT_EQ(modes.size(), 2u);
}

// Found by the check fuzz target: an unknown top-level key read past the end of the list of
// known keys (std::begin and std::end of two different initializer lists): a segmentation fault.
TEST(ExternalResultsReader, JsonUnknownTopLevelKeyIsNamed) {
  testing::expect_invalid(
      [&] {
        read_external_results(file(
            "unknown.json",
            R"({"resultz": [], "results": [{"plane": "inplane", "mode": 1, "omega_rad_s": 1}]})"));
      },
      "unknown key 'resultz'");
}

}  // namespace
}  // namespace catena
