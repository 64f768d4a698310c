// SPDX-License-Identifier: MIT
// How catena touches the file system (catena/io/file_access.hpp): input files only when they are
// regular and small, output written whole or not at all, output locations checked before work,
// every failure naming the path (escaped when it is not UTF-8).
#include "catena/io/file_access.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "catena/core/error.hpp"
#include "catena/io/scene_reader.hpp"

namespace catena {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("catena_file_access_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string contents(const fs::path& path) {
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

template <class Exception>
void expect_error(const std::function<void()>& action, const std::vector<std::string>& words) {
  try {
    action();
    ADD_FAILURE() << "no error; expected one with '" << words.front() << "'";
  } catch (const Exception& error) {
    for (const auto& word : words)
      EXPECT_NE(std::string(error.what()).find(word), std::string::npos) << error.what();
  }
}

TEST(PathText, EscapesBytesThatAreNotUtf8AndKeepsTheRest) {
  EXPECT_EQ(path_text("scenes/caténaire.toml"), "scenes/caténaire.toml");
  EXPECT_EQ(path_text(std::string("a\xff"
                                  "b.toml")),
            "a\\xFFb.toml");
  // A lead byte without its continuation, an overlong '/', a UTF-16 surrogate: all invalid.
  EXPECT_EQ(path_text(std::string("\xc3"
                                  "x")),
            "\\xC3x");
  EXPECT_EQ(path_text(std::string("\xc0\xaf")), "\\xC0\\xAF");
  EXPECT_EQ(path_text(std::string("\xed\xa0\x80")), "\\xED\\xA0\\x80");
}

// `solve /dev/zero` used to read until memory ran out (41 s); FIFOs, dangling symlinks and
// symlink loops named *.toml were skipped by `verify` or ended in an internal error.
TEST(ReadInputFile, RefusesWhatIsNotASmallRegularFileNamingThePath) {
  const fs::path dir = fresh_dir("read");
  expect_error<ParseError>([] { read_input_file("/dev/zero", "scene file"); },
                           {"/dev/zero", "character device"});
  expect_error<ParseError>([&] { read_input_file(dir, "scene file"); }, {"a directory"});
  ASSERT_EQ(mkfifo((dir / "fifo.toml").c_str(), 0644), 0);
  expect_error<ParseError>([&] { read_input_file(dir / "fifo.toml", "scene file"); },
                           {"fifo.toml", "FIFO"});
  fs::create_symlink("nowhere.toml", dir / "dangling.toml");
  expect_error<ParseError>([&] { read_input_file(dir / "dangling.toml", "scene file"); },
                           {"dangling.toml", "dangling symbolic link"});
  fs::create_symlink("loop2.toml", dir / "loop1.toml");
  fs::create_symlink("loop1.toml", dir / "loop2.toml");
  expect_error<ParseError>([&] { read_input_file(dir / "loop1.toml", "scene file"); },
                           {"loop1.toml", "symbolic links"});
  std::ofstream(dir / "big.toml") << std::string(kMaxInputFileBytes + 1, '#');
  expect_error<ParseError>([&] { read_input_file(dir / "big.toml", "scene file"); },
                           {"big.toml", "1048577 bytes, more than the limit of 1048576"});
  std::ofstream(dir / "small.toml") << "name = 'x'\n";
  EXPECT_EQ(read_input_file(dir / "small.toml", "scene file"), "name = 'x'\n");
}

TEST(ListSceneFiles, ListsUnreadableEntriesSoThatTheyAreReported) {
  const fs::path dir = fresh_dir("list");
  std::ofstream(dir / "good.toml") << "x = 1\n";
  fs::create_symlink("nowhere.toml", dir / "dangling.toml");
  ASSERT_EQ(mkfifo((dir / "fifo.toml").c_str(), 0644), 0);
  fs::create_directories(dir / "sub.toml");  // a directory is searched, not listed
  std::ofstream(dir / "sub.toml" / "inner.toml") << "x = 1\n";
  std::ofstream(dir / "notes.txt") << "not a scene\n";
  const std::vector<fs::path> files = list_scene_files(dir);
  const std::vector<fs::path> expected = {dir / "dangling.toml", dir / "fifo.toml",
                                          dir / "good.toml", dir / "sub.toml" / "inner.toml"};
  EXPECT_EQ(files, expected);
  expect_error<InvalidInput>([&] { list_scene_files(dir / "good.toml"); },
                             {"good.toml", "not a directory"});
}

TEST(WriteFileAtomically, ReplacesTheFileWholeAndLeavesNoTemporary) {
  const fs::path dir = fresh_dir("write");
  const fs::path target = dir / "deeper" / "out.json";
  write_file_atomically(target, "first\n");
  EXPECT_EQ(contents(target), "first\n");
  write_file_atomically(target, "second\n");
  EXPECT_EQ(contents(target), "second\n");
  // Permissions as a plain open() would give (0666 less the umask), not mkstemp's 0600.
  const mode_t mask = umask(0);
  umask(mask);
  EXPECT_EQ(static_cast<mode_t>(fs::status(target).permissions()) & 0777, 0666 & ~mask);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir / "deeper")) files += entry.is_regular_file();
  EXPECT_EQ(files, 1);  // no temporary left behind
}

// `--json /proc/x/out.json`, a path under a file and `verify --out` on a file used to end in an
// internal error (exit 3), after the solving.
TEST(WriteFileAtomically, UnwritablePlacesAreInvalidInputNamingThePath) {
  const fs::path dir = fresh_dir("unwritable");
  std::ofstream(dir / "afile") << "x";
  expect_error<InvalidInput>([] { write_file_atomically("/proc/x/out.json", "{}"); },
                             {"/proc/x/out.json", "cannot write", "/proc/x"});
  expect_error<InvalidInput>([&] { write_file_atomically(dir / "afile" / "out.json", "{}"); },
                             {"afile/out.json", "Not a directory"});
  expect_error<InvalidInput>([&] { write_file_atomically(dir, "{}"); }, {"is a directory"});
  expect_error<InvalidInput>([] { check_output_file("/proc/x/out.json"); },
                             {"/proc/x/out.json", "cannot write"});
  expect_error<InvalidInput>([&] { check_output_file(dir / "afile" / "out.json"); },
                             {"afile/out.json"});
  expect_error<InvalidInput>([&] { check_output_directory(dir / "afile"); },
                             {"afile: cannot write", "directory"});
  expect_error<InvalidInput>([] { check_output_directory("/proc/1/catena"); }, {"/proc/1/catena"});
  EXPECT_NO_THROW(check_output_file(dir / "new" / "out.json"));
  EXPECT_NO_THROW(check_output_directory(dir / "report"));
  EXPECT_EQ(contents(dir / "afile"), "x");
  int entries = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    entries += entry.is_regular_file();
  EXPECT_EQ(entries, 1);  // the checks leave no probe file behind
}

}  // namespace
}  // namespace catena
