// SPDX-License-Identifier: MIT
// How catena touches the file system (catena/io/file_access.hpp): input files only when they are
// regular and small, output written whole or not at all, output locations checked before work,
// every failure naming the path (escaped when it is not UTF-8).
#include "catena/io/file_access.hpp"

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

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

// Issue 32: `--json /dev/null` run as root renamed a regular file over the device node; a FIFO
// or a symlink given as the target was replaced the same way.
TEST(WriteFileAtomically, WritesThroughDevNullWhichStaysACharacterDevice) {
  EXPECT_NO_THROW(check_output_file("/dev/null"));
  EXPECT_NO_THROW(write_file_atomically("/dev/null", "{}\n"));
  struct stat after {};
  ASSERT_EQ(::lstat("/dev/null", &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode)) << "/dev/null is no longer a character device";
}

TEST(WriteFileAtomically, WritesThroughAFifoToItsReaderAndKeepsTheFifo) {
  const fs::path dir = fresh_dir("fifo");
  const fs::path fifo = dir / "out.json";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  EXPECT_NO_THROW(check_output_file(fifo));  // must not open it: there is no reader yet
  std::string received;
  std::thread reader([&] { received = contents(fifo); });
  EXPECT_NO_THROW(write_file_atomically(fifo, "through the pipe\n"));
  reader.join();
  EXPECT_EQ(received, "through the pipe\n");
  EXPECT_EQ(fs::symlink_status(fifo).type(), fs::file_type::fifo);
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1);  // no temporary file next to it
}

TEST(WriteFileAtomically, FollowsASymlinkReplacingItsTargetAndKeepingTheLink) {
  const fs::path dir = fresh_dir("symlink");
  fs::create_directories(dir / "runs");
  fs::create_directories(dir / "links");
  std::ofstream(dir / "runs" / "today.json") << "old\n";
  fs::permissions(dir / "runs" / "today.json", fs::perms(0640));
  fs::create_symlink("../runs/today.json", dir / "links" / "latest.json");
  fs::create_symlink("links/latest.json", dir / "chain.json");  // a link to a link
  write_file_atomically(dir / "chain.json", "new\n");
  EXPECT_TRUE(fs::is_symlink(dir / "chain.json"));
  EXPECT_TRUE(fs::is_symlink(dir / "links" / "latest.json"));
  EXPECT_EQ(contents(dir / "runs" / "today.json"), "new\n");
  // The replaced file keeps its permissions.
  EXPECT_EQ(static_cast<int>(fs::status(dir / "runs" / "today.json").permissions()) & 0777, 0640);
  // And, run as root, its owner: `sudo catena ... --json ~user/x.json` must not take it away.
  if (::geteuid() == 0) {
    ASSERT_EQ(::chown((dir / "runs" / "today.json").c_str(), 4321, 4321), 0);
    write_file_atomically(dir / "chain.json", "newer\n");
    struct stat after {};
    ASSERT_EQ(::stat((dir / "runs" / "today.json").c_str(), &after), 0);
    EXPECT_EQ(after.st_uid, 4321u);
    EXPECT_EQ(after.st_gid, 4321u);
    EXPECT_EQ(after.st_mode & 0777, 0640u);
  }
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    files += fs::is_regular_file(fs::symlink_status(entry.path()));
  EXPECT_EQ(files, 1);  // the temporary was renamed, none left in either directory
}

TEST(WriteFileAtomically, RefusesWhatItMustNotReplaceNamingThePath) {
  const fs::path dir = fresh_dir("refuse");
  fs::create_symlink("nowhere.json", dir / "dangling.json");
  expect_error<InvalidInput>([&] { write_file_atomically(dir / "dangling.json", "{}"); },
                             {"dangling.json", "dangling symbolic link"});
  expect_error<InvalidInput>([&] { check_output_file(dir / "dangling.json"); },
                             {"dangling.json", "dangling symbolic link"});
  EXPECT_FALSE(fs::exists(dir / "nowhere.json"));
  fs::create_symlink("loop2.json", dir / "loop1.json");
  fs::create_symlink("loop1.json", dir / "loop2.json");
  expect_error<InvalidInput>([&] { write_file_atomically(dir / "loop1.json", "{}"); },
                             {"loop1.json", "loop"});
  const fs::path socket_path = dir / "socket.json";
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::snprintf(address.sun_path, sizeof(address.sun_path), "%s", socket_path.c_str());
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)), 0);
  expect_error<InvalidInput>([&] { write_file_atomically(socket_path, "{}"); },
                             {"socket.json", "a socket"});
  expect_error<InvalidInput>([&] { check_output_file(socket_path); }, {"socket.json", "a socket"});
  EXPECT_EQ(fs::symlink_status(socket_path).type(), fs::file_type::socket);
  ::close(fd);
  // A block device, where the machine has one (as root it could otherwise be overwritten).
  for (const auto& entry : fs::directory_iterator("/dev")) {
    if (fs::symlink_status(entry.path()).type() != fs::file_type::block) continue;
    expect_error<InvalidInput>([&] { check_output_file(entry.path()); },
                               {entry.path().string(), "a block device"});
    break;
  }
  expect_error<InvalidInput>([] { write_file_atomically("", "{}"); }, {"an empty path"});
  expect_error<InvalidInput>([] { check_output_file(""); }, {"an empty path"});
  expect_error<InvalidInput>([] { check_output_directory(""); }, {"an empty path"});
}

// `catena check` with bad input left an empty --out directory behind: the checks made before the
// work create nothing.
TEST(CheckOutputDirectory, CreatesNothing) {
  const fs::path dir = fresh_dir("create_nothing");
  EXPECT_NO_THROW(check_output_directory(dir / "new" / "deeper"));
  EXPECT_NO_THROW(check_output_file(dir / "other" / "out.json"));
  EXPECT_FALSE(fs::exists(dir / "new"));
  EXPECT_FALSE(fs::exists(dir / "other"));
}

// `catena solve S --json S` and `catena check R --json R` overwrote their own input.
TEST(CheckNotAnInput, RefusesTheSameFileByAnyNameAndNamesBoth) {
  const fs::path dir = fresh_dir("same_file");
  const fs::path scene = dir / "scene.toml";
  std::ofstream(scene) << "x = 1\n";
  fs::create_hard_link(scene, dir / "hard.toml");
  fs::create_symlink("scene.toml", dir / "soft.toml");
  const fs::path dotted = dir / "." / "scene.toml";
  for (const fs::path& output : {scene, dotted, dir / "hard.toml", dir / "soft.toml"}) {
    expect_error<InvalidInput>(
        [&] {
          check_not_an_input(output, {"", scene}, "--json");
        },
        {"--json " + output.string(), "same file as the input", scene.string()});
  }
  std::ofstream(dir / "other.json") << "{}";
  EXPECT_NO_THROW(check_not_an_input(dir / "other.json", {scene}, "--json"));
  EXPECT_NO_THROW(check_not_an_input(dir / "missing.json", {scene}, "--json"));
  EXPECT_EQ(contents(scene), "x = 1\n");
}

// A scene saved as "Unicode" by a Windows editor: a clear reason, not a TOML error of NUL bytes.
TEST(ReadInputFile, RefusesUtf16TextSayingSo) {
  const fs::path dir = fresh_dir("utf16");
  std::ofstream(dir / "le.toml", std::ios::binary) << std::string("\xFF\xFEx\0=\0", 6);
  std::ofstream(dir / "be.toml", std::ios::binary) << std::string("\xFE\xFF\0x\0=", 6);
  for (const char* name : {"le.toml", "be.toml"}) {
    expect_error<ParseError>([&] { read_input_file(dir / name, "scene file"); },
                             {name, "UTF-16 text", "save the scene file as UTF-8"});
  }
}

}  // namespace
}  // namespace catena
