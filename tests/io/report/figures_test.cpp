// SPDX-License-Identifier: MIT
// draw_figures without Python: a stand-in interpreter (a shell script) records the command line it
// is given and writes the index.json the real figures.py would, so that the arguments, the images
// read back and every "figures not drawn" note can be checked.
#include "io/report/figures.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace catena::internal {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> lines_of(const fs::path& path) {
  std::vector<std::string> lines;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

class DrawFigures : public ::testing::Test {
 protected:
  // Paths with spaces: the arguments reach the program as they are, with no shell to quote for.
  // One directory per test, as ctest runs the tests in parallel.
  fs::path root = fs::temp_directory_path() / "catena figures test" /
                  ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::path figures_dir = root / "out dir" / "figures";
  fs::path results = root / "report.json";
  FigureInputs inputs;

  void SetUp() override {
    fs::remove_all(root);
    fs::create_directories(root);
    inputs.script = root / "figures.py";
    std::ofstream(inputs.script) << "# never run by python here\n";
    inputs.published_dir = root / "published";
    inputs.time_vs_error = root / "time-vs-error.csv";
    inputs.python = interpreter("ok",
                                "printf '%s\\n' \"$@\" > \"$dir/args.txt\"\n"
                                "printf '%s' '" +
                                    index_json_ + "' > \"$out/index.json\"\n");
  }

  // A stand-in interpreter: finds --out among its arguments, then runs `body` (sh) with $dir (its
  // own directory) and $out set.
  std::string interpreter(const std::string& name, const std::string& body) const {
    const fs::path path = root / ("python " + name);
    std::ofstream(path) << "#!/bin/sh\ndir=$(dirname \"$0\")\nout=\n"
                           "for a in \"$@\"; do [ \"$prev\" = --out ] && out=$a; prev=$a; done\n"
                        << body;
    fs::permissions(path, fs::perms::owner_all);
    return path.string();
  }

  std::vector<Image> draw(std::string& note) const {
    return draw_figures(results, inputs, figures_dir, note);
  }

  const std::string index_json_ =
      R"([{"file": "frequencies.png", "caption": "Frequencies"}, {"file": "sub/timing.svg", "caption": "Time, error"},)"
      R"( {"file": "bare.png"}])";
};

TEST_F(DrawFigures, PassesTheInputsToTheScriptAndReadsTheIndexBackInOrder) {
  std::string note;
  const std::vector<Image> images = draw(note);
  EXPECT_EQ(note, "");
  EXPECT_EQ(
      lines_of(root / "args.txt"),
      (std::vector<std::string>{inputs.script.string(), "--results", results.string(),
                                "--published", inputs.published_dir.string(), "--time-vs-error",
                                inputs.time_vs_error.string(), "--out", figures_dir.string()}));
  ASSERT_EQ(images.size(), 3u);
  EXPECT_EQ(images[0].file, figures_dir / "frequencies.png");
  EXPECT_EQ(images[0].caption, "Frequencies");
  EXPECT_EQ(images[1].file, figures_dir / "sub/timing.svg");
  EXPECT_EQ(images[1].caption, "Time, error");
  EXPECT_EQ(images[2].caption, "");  // no caption given
  // The script's output goes to a log beside the figures.
  EXPECT_TRUE(fs::exists(figures_dir / "figures.log"));
}

TEST_F(DrawFigures, MissingScriptDrawsNothingAndSaysWhere) {
  inputs.script = root / "nowhere.py";
  std::string note;
  EXPECT_TRUE(draw(note).empty());
  EXPECT_EQ(note, "figures not drawn: " + inputs.script.string() + " not found");
  EXPECT_FALSE(fs::exists(figures_dir));  // nothing started, nothing created
}

TEST_F(DrawFigures, FailingInterpreterGivesItsStatusAndTheLog) {
  inputs.python = interpreter("failing", "echo 'No module named matplotlib' >&2\nexit 3\n");
  std::string note;
  EXPECT_TRUE(draw(note).empty());
  EXPECT_EQ(note, "figures not drawn: '" + inputs.python + "' failed (status 3); see " +
                      (figures_dir / "figures.log").string());
  EXPECT_NE(read(figures_dir / "figures.log").find("No module named matplotlib"),
            std::string::npos);
}

TEST_F(DrawFigures, MissingInterpreterIsStatus127) {
  inputs.python = (root / "no-such-python").string();
  std::string note;
  EXPECT_TRUE(draw(note).empty());
  EXPECT_NE(note.find("failed (status 127)"), std::string::npos) << note;
}

TEST_F(DrawFigures, ScriptThatWritesNoIndexDrawsNothing) {
  inputs.python = interpreter("silent", "exit 0\n");
  std::string note;
  EXPECT_TRUE(draw(note).empty());
  EXPECT_EQ(note, "figures not drawn: figures.py wrote no index.json");
}

TEST_F(DrawFigures, UnreadableOrNonListIndexDrawsNothing) {
  for (const std::string index : {"[{\"file\": ", "{\"file\": \"a.png\"}"}) {
    inputs.python = interpreter("bad index", "printf '%s' '" + index + "' > \"$out/index.json\"\n");
    std::string note;
    EXPECT_TRUE(draw(note).empty()) << index;
    EXPECT_EQ(note, "figures not drawn: unreadable figures/index.json") << index;
  }
}

}  // namespace
}  // namespace catena::internal
