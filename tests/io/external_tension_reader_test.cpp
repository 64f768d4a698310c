// SPDX-License-Identifier: MIT
// Reading another program's dynamic tension for `catena check`
// (include/catena/io/external_tension_reader.hpp): s_m and node-based files, the optional columns,
// how a tension file is told from a frequencies file, and bad input naming the file, row and
// column. Files are written by the test to a temporary directory.
#include "catena/io/external_tension_reader.hpp"

#include <gtest/gtest.h>

#include "catena/core/error.hpp"
#include "cli/cli_support.hpp"

namespace catena {
namespace {

std::filesystem::path file(const std::string& name, const std::string& text) {
  return testing::write_temp_file("catena_external_tension_test", name, text);
}

void expect_error(const std::string& text, const std::string& part) {
  const auto path = file("bad.csv", text);
  try {
    read_external_tension(path);
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(part), std::string::npos)
        << error.what() << "\nexpected: " << part;
  }
}

TEST(ExternalTensionReader, ArcLengthFileWithOptionalColumns) {
  const auto path = file("sigma.csv",
                         "# MoorDyn, 3 h, segment midpoints\n"
                         "s_m,tension_std_n,tension_uncertainty_n,resolution\n"
                         "5,1200,30,50\n995,5400,80,50\n");
  EXPECT_TRUE(is_tension_results_file(path));
  const ExternalTension tension = read_external_tension(path);
  EXPECT_EQ(tension.quantity, TensionQuantity::StandardDeviation);
  EXPECT_FALSE(tension.period_s.has_value());
  ASSERT_EQ(tension.stations.size(), 2u);
  EXPECT_EQ(*tension.stations[1].s_m, 995.0);
  EXPECT_EQ(tension.stations[1].tension_n, 5400.0);
  EXPECT_EQ(*tension.stations[1].uncertainty_n, 80.0);
  EXPECT_EQ(*tension.stations[1].resolution, 50.0);
  EXPECT_NE(tension.stations[1].origin.find("row 2 (line 4)"), std::string::npos)
      << tension.stations[1].origin;
}

TEST(ExternalTensionReader, NodeFileMapsNodesToEqualSegments) {
  const auto path =
      file("nodes.csv", "node,nodes,tension_amplitude_n,period_s\n0,5,10,12\n4,5,20,12\n");
  const ExternalTension tension = read_external_tension(path);
  EXPECT_EQ(tension.quantity, TensionQuantity::Amplitude);
  EXPECT_EQ(*tension.period_s, 12.0);
  ASSERT_EQ(tension.stations.size(), 2u);
  EXPECT_DOUBLE_EQ(station_s_m(tension.stations[0], 1000.0), 0.0);
  EXPECT_DOUBLE_EQ(station_s_m(tension.stations[1], 1000.0), 1000.0);
  ExternalTensionStation middle = tension.stations[1];
  middle.node = 1;
  EXPECT_DOUBLE_EQ(station_s_m(middle, 1000.0), 250.0);  // s = i L / (nodes - 1)
}

TEST(ExternalTensionReader, FrequencyFilesAreNotTensionFiles) {
  EXPECT_FALSE(is_tension_results_file(file("f.csv", "plane,mode,frequency_hz\nin-plane,1,0.1\n")));
  EXPECT_FALSE(is_tension_results_file(file("f.json", "{}")));
  EXPECT_FALSE(is_tension_results_file("/nonexistent/catena/t.csv"));
}

TEST(ExternalTensionReader, BadHeadersAreNamed) {
  expect_error("s_m,node,nodes,tension_std_n\n1,1,3,5\n", "columns 's_m' and 'node' both given");
  expect_error("node,tension_std_n\n1,5\n", "column 'node' without column 'nodes'");
  expect_error("nodes,s_m,tension_std_n\n3,1,5\n", "column 'nodes' without column 'node'");
  expect_error("tension_std_n\n5\n", "missing column 's_m'");
  expect_error("s_m,tension\n1,5\n", "unknown column 'tension'");
  expect_error("s_m,resolution\n1,5\n", "missing column 'tension_std_n' or 'tension_amplitude_n'");
  expect_error("s_m,tension_std_n,tension_amplitude_n\n1,5,5\n", "both given");
  expect_error("s_m,tension_std_n,period_s\n1,5,10\n", "'period_s' with 'tension_std_n'");
  expect_error("s_m,tension_std_n\n", "no data rows");
}

TEST(ExternalTensionReader, BadCellsNameRowAndColumn) {
  expect_error("s_m,tension_std_n\n1,5\n2,nan\n", "row 2 (line 3), column 'tension_std_n': 'nan'");
  expect_error("s_m,tension_std_n\n1,5\ninf,5\n", "row 2 (line 3), column 's_m': 'inf'");
  expect_error("s_m,tension_std_n\n1,\n", "row 1 (line 2), column 'tension_std_n': empty");
  expect_error("s_m,tension_std_n\n1,-5\n", "column 'tension_std_n': -5 must be >= 0");
  expect_error("node,nodes,tension_std_n\n1.5,3,5\n", "column 'node': 1.5 is not a whole number");
  expect_error("s_m,tension_amplitude_n,period_s\n1,5,10\n2,5,11\n",
               "row 2 (line 3), column 'period_s': 11 s differs from row 1's 10 s");
  expect_error("s_m,tension_amplitude_n,period_s\n1,5,-1\n", "column 'period_s': -1 must be > 0");
}

}  // namespace
}  // namespace catena
