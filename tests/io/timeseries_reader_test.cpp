// SPDX-License-Identifier: MIT
// The time-series reader on files written here in MoorDyn's layouts (v2's space-padded main and
// line files with a units row, v1's tab-separated file) and as CSV: names, units, samples and the
// segment count read back; and each bad input refused with InvalidInput naming the file, the line
// and the column (no data rows, a ragged row, a non-numeric cell, a non-monotone or non-finite
// time, a missing channel with the closest names, a NaN sample, a time unit other than seconds).
#include "catena/io/timeseries_reader.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "catena/core/error.hpp"

namespace catena {
namespace {

// The message of parsing `text`, which must be refused with InvalidInput.
std::string refusal(const std::string& text) {
  try {
    parse_time_series_text(text, "run.out");
  } catch (const InvalidInput& error) {
    return error.what();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return "";
}

// As MoorDyn v2 writes its main file: setw(10) time with 4 decimals, setw(20) scientific values.
std::string moordyn_v2_main() {
  std::string text = fmt::format("{:>10}{:>20}{:>20}\n{:>10}{:>20}{:>20}\n", "Time", "FAIRTEN1",
                                 "L1N5PX", "(s)", "(N)", "(m)");
  for (int k = 0; k < 5; ++k)
    text += fmt::format("{:>10.4f}{:>20.7e}{:>20.7e}\n", 0.05 * k, 1e6 + k, -400.0 + 0.1 * k);
  return text;
}

TEST(TimeSeriesReader, ReadsMoorDynV2MainFile) {
  const TimeSeries s = parse_time_series_text(moordyn_v2_main(), "decay.out");
  EXPECT_EQ(s.format, "moordyn");
  ASSERT_EQ(s.names, (std::vector<std::string>{"FAIRTEN1", "L1N5PX"}));
  EXPECT_EQ(s.units, (std::vector<std::string>{"N", "m"}));
  ASSERT_EQ(s.time_s.size(), 5);
  EXPECT_DOUBLE_EQ(s.time_s[4], 0.2);
  EXPECT_DOUBLE_EQ(s.columns[0][3], 1e6 + 3);
  EXPECT_DOUBLE_EQ(s.columns[1][2], -399.8);
  EXPECT_EQ(s.line_numbers.front(), 3);
  EXPECT_FALSE(s.num_segments.has_value());
  EXPECT_EQ(&s.channel("fairten1"), &s.columns[0]);  // any case
}

TEST(TimeSeriesReader, ReadsMoorDynLineFileAndItsSegmentCount) {
  // Line<k>.out with positions of nodes 0..2 and tensions of segments 1..2 (N = 2).
  std::string text = "Time";
  for (int i = 0; i <= 2; ++i) text += fmt::format("\tNode{}px\tNode{}py\tNode{}pz", i, i, i);
  text += "\tSeg1Te\tSeg2Te\n(s)";
  for (int i = 0; i < 9; ++i) text += "\t(m)";
  text += "\t(N)\t(N)\n";
  for (int k = 0; k < 3; ++k) {
    text += fmt::format("{}", 0.1 * k);
    for (int i = 0; i < 11; ++i) text += fmt::format("\t{}", i + k);
    text += "\n";
  }
  const TimeSeries s = parse_time_series_text(text, "Line1.out");
  EXPECT_EQ(s.format, "moordyn");
  EXPECT_EQ(s.names.size(), 11u);
  ASSERT_TRUE(s.num_segments.has_value());
  EXPECT_EQ(*s.num_segments, 2);
  EXPECT_EQ(s.units.back(), "N");
  EXPECT_DOUBLE_EQ(s.channel("Seg2Te")[2], 12.0);
}

TEST(TimeSeriesReader, ReadsMoorDynWithoutUnitsRow) {
  const TimeSeries s = parse_time_series_text("Time FAIRTEN1\n0 1\n0.5 2\n1.0 +3\n", "x.out");
  EXPECT_EQ(s.units, (std::vector<std::string>{""}));
  EXPECT_DOUBLE_EQ(s.columns[0][2], 3.0);
}

TEST(TimeSeriesReader, ReadsCsvWithTimeColumnAnywhereAndUnits) {
  for (const char* time : {"time", "Time [s]", "TIME_s", "time (s)"}) {
    const TimeSeries s = parse_time_series_text(
        fmt::format("tension [N],{},y_m\n10,0,1\n11,0.1,2\r\n12,0.2,3\n", time), "run.csv");
    EXPECT_EQ(s.format, "csv") << time;
    ASSERT_EQ(s.names, (std::vector<std::string>{"tension [N]", "y_m"})) << time;
    EXPECT_EQ(s.units[0], "N");
    EXPECT_DOUBLE_EQ(s.time_s[2], 0.2);
    EXPECT_DOUBLE_EQ(s.columns[1][1], 2.0);
  }
}

TEST(TimeSeriesReader, ReadsAFileAndTellsTimeSeriesFromResults) {
  const auto dir = std::filesystem::temp_directory_path() / "catena_timeseries_reader_test";
  std::filesystem::create_directories(dir);
  const auto write = [&](const char* name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  };
  const auto decay = write("decay.txt", moordyn_v2_main());  // told by content, not the name
  EXPECT_TRUE(looks_like_time_series(decay));
  EXPECT_EQ(read_time_series(decay).names.size(), 2u);
  EXPECT_TRUE(looks_like_time_series(write("d.csv", "\nfairten,Time_s\n1,0\n")));
  EXPECT_FALSE(looks_like_time_series(write("r.csv", "plane,mode,frequency_hz\nin-plane,1,1\n")));
  EXPECT_FALSE(looks_like_time_series(write("t.csv", "s_m,tension_std_n\n0,1\n")));
  EXPECT_FALSE(looks_like_time_series(dir / "missing.out"));
  EXPECT_THROW(read_time_series(dir / "missing.out"), Error);
}

TEST(TimeSeriesReader, RefusesAFileWithoutDataRows) {
  for (const std::string& text :
       {std::string("Time FAIRTEN1\n(s) (N)\n"), std::string("time,x\n"), std::string("\n\n")}) {
    const std::string message = refusal(text);
    EXPECT_TRUE(message.find("no data rows") != std::string::npos ||
                message.find("empty") != std::string::npos)
        << message;
  }
}

TEST(TimeSeriesReader, RefusesANonMonotoneTimeNamingTheLine) {
  const std::string message = refusal("Time FAIRTEN1\n(s) (N)\n0 1\n0.1 2\n0.1 3\n");
  EXPECT_NE(message.find("run.out line 5"), std::string::npos) << message;
  EXPECT_NE(message.find("increase strictly"), std::string::npos) << message;
  EXPECT_NE(refusal("time,x\n0,1\n-1,2\n").find("line 3"), std::string::npos);
  EXPECT_NE(refusal("Time X\n0 1\nnan 2\n").find("line 3"), std::string::npos);
}

TEST(TimeSeriesReader, RefusesARaggedRowAndANonNumericCell) {
  const std::string ragged = refusal("Time A B\n0 1 2\n0.1 1\n");
  EXPECT_NE(ragged.find("line 3: 2 cells, the header has 3"), std::string::npos) << ragged;
  const std::string text = refusal("time,a\n0,1\n0.1,abc\n");
  EXPECT_NE(text.find("line 3, column 'a': 'abc' is not a number"), std::string::npos) << text;
  EXPECT_NE(refusal("Time A\n(s) (N) (m)\n0 1\n").find("units row"), std::string::npos);
}

TEST(TimeSeriesReader, RefusesTimesNotInSecondsAndFilesWithoutTime) {
  EXPECT_NE(refusal("time [ms],a\n0,1\n").find("seconds"), std::string::npos);
  EXPECT_NE(refusal("Time A\n(ms) (N)\n0 1\n").find("seconds"), std::string::npos);
  EXPECT_NE(refusal("t,a\n0,1\n").find("no time column"), std::string::npos);
  EXPECT_NE(refusal("hello world\n").find("not a time series"), std::string::npos);
  EXPECT_NE(refusal("Time\n0\n1\n").find("no channel"), std::string::npos);
}

TEST(TimeSeriesReader, MissingChannelListsTheClosestNames) {
  const TimeSeries s = parse_time_series_text(moordyn_v2_main(), "decay.out");
  try {
    s.channel("FAIRTEN2");
    FAIL() << "accepted a missing channel";
  } catch (const InvalidInput& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("no channel 'FAIRTEN2'"), std::string::npos) << message;
    EXPECT_NE(message.find("closest: FAIRTEN1"), std::string::npos) << message;
  }
}

TEST(TimeSeriesReader, NanSampleIsRefusedNamingLineAndChannel) {
  const TimeSeries s =
      parse_time_series_text("Time FAIRTEN1 L1N5PX\n(s) (N) (m)\n0 1 2\n0.1 -nan 2\n", "r.out");
  EXPECT_TRUE(std::isnan(s.columns[0][1]));  // read as it is; refused when used
  EXPECT_NO_THROW(s.channel("L1N5PX"));
  try {
    s.channel("FAIRTEN1");
    FAIL() << "accepted a NaN sample";
  } catch (const InvalidInput& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("r.out line 4 (time 0.1 s), channel 'FAIRTEN1'"), std::string::npos)
        << message;
  }
}

}  // namespace
}  // namespace catena
