// SPDX-License-Identifier: MIT
// CSV tables: comments, header, typed cells, quoted cells with commas, and a write/read round trip.
#include "catena/io/csv_table.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "catena/core/error.hpp"

namespace catena {
namespace {

std::filesystem::path write(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("catena_csv_test_" + name);
  std::ofstream(path) << text;
  return path;
}

TEST(CsvTable, ReadsCommentsHeaderAndTypedCells) {
  const CsvTable t = read_csv_table(write("a.csv", "# source: here\n\nmode, value\n1, 2.5\n2,\n"));
  EXPECT_EQ(t.comments, std::vector<std::string>{"source: here"});
  EXPECT_EQ(t.columns, (std::vector<std::string>{"mode", "value"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.number(0, "value"), 2.5);
  EXPECT_FALSE(t.number(1, "value"));  // empty cell: missing
  EXPECT_THROW(t.column_index("nope"), ParseError);
}

TEST(CsvTable, QuotedCellsHoldCommasAndQuotes) {
  const CsvTable t = read_csv_table(
      write("q.csv", "scene,solver\n\"shallow (eps 0.05, phi 0)\",fe\n\"say \"\"hi\"\"\",x\n"));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.text(0, "scene"), "shallow (eps 0.05, phi 0)");
  EXPECT_EQ(t.text(0, "solver"), "fe");
  EXPECT_EQ(t.text(1, "scene"), "say \"hi\"");
}

TEST(CsvTable, WriteThenReadRoundTrips) {
  CsvTable table{
      {"written by a test"}, {"name", "value"}, {{"a, b", "1.5"}, {"quote \" here", ""}}};
  const auto path = std::filesystem::temp_directory_path() / "catena_csv_test_round.csv";
  write_csv_table(path, table);
  const CsvTable back = read_csv_table(path);
  EXPECT_EQ(back.comments, table.comments);
  EXPECT_EQ(back.columns, table.columns);
  EXPECT_EQ(back.rows, table.rows);
}

TEST(CsvTable, RaggedRowsAndBadNumbersAreParseErrors) {
  EXPECT_THROW(read_csv_table(write("r.csv", "a,b\n1,2,3\n")), ParseError);
  EXPECT_THROW(read_csv_table(write("e.csv", "# only a comment\n")), ParseError);
  EXPECT_THROW(read_csv_table("/nonexistent.csv"), ParseError);
  const CsvTable t = read_csv_table(write("n.csv", "a\nx1\n"));
  EXPECT_THROW(t.number(0, "a"), ParseError);
}

TEST(CsvTable, DuplicateHeaderIsAParseErrorAndAByteOrderMarkIsDropped) {
  EXPECT_THROW(read_csv_table(write("d.csv", "a,b,a\n1,2,3\n")), ParseError);
  const CsvTable t = read_csv_table(write("bom.csv",
                                          "\xEF\xBB\xBF"
                                          "a,b\n1,2\n"));
  ASSERT_EQ(t.columns.size(), 2u);
  EXPECT_EQ(t.columns[0], "a");
}

}  // namespace
}  // namespace catena
