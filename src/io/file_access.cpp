// SPDX-License-Identifier: MIT
#include "catena/io/file_access.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include "catena/core/error.hpp"

namespace catena {
namespace {

namespace fs = std::filesystem;

// Length of the valid UTF-8 sequence starting at text[i] (1 to 4), or 0 when it is not one
// (overlong forms, surrogates and code points above U+10FFFF are invalid, as in RFC 3629).
std::size_t utf8_sequence_length(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) return 1;
  std::size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 ? 2 : 0;
  if (length == 0 || lead > 0xF4 || i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  }
  const unsigned char second = byte(i + 1);
  if ((lead == 0xE0 && second < 0xA0) || (lead == 0xED && second >= 0xA0) ||
      (lead == 0xF0 && second < 0x90) || (lead == 0xF4 && second >= 0x90)) {
    return 0;
  }
  return length;
}

std::string describe(fs::file_type type) {
  switch (type) {
    case fs::file_type::directory:
      return "a directory";
    case fs::file_type::fifo:
      return "a FIFO";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

[[noreturn]] void cannot_write(const fs::path& path, const std::string& reason) {
  throw InvalidInput(fmt::format("{}: cannot write: {}", path_text(path), reason));
}

fs::path directory_of(const fs::path& path) {
  return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

// Creates `directory` (and its parents) unless it exists; InvalidInput naming `target` otherwise.
void make_directory(const fs::path& directory, const fs::path& target) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error)
    cannot_write(target, fmt::format("cannot create directory {}: {}", path_text(directory),
                                     error.message()));
  if (!fs::is_directory(directory, error))
    cannot_write(target, fmt::format("{} is not a directory", path_text(directory)));
}

// A new empty file "<directory>/.<stem>.tmp-XXXXXX" opened for writing; its name in `name`.
int make_temporary(const fs::path& directory,
                   const std::string& stem,
                   std::string& name,
                   const fs::path& target) {
  name = (directory / ("." + stem + ".tmp-XXXXXX")).string();
  const int fd = mkstemp(name.data());
  if (fd < 0)
    cannot_write(target, fmt::format("cannot create a file in {}: {}", path_text(directory),
                                     std::strerror(errno)));
  return fd;
}

// The permissions a newly created file gets (0666 less the umask), as open() would give.
mode_t new_file_mode() {
  static const mode_t mode = [] {
    const mode_t mask = umask(0);
    umask(mask);
    return static_cast<mode_t>(0666 & ~mask);
  }();
  return mode;
}

bool write_all(int fd, const std::string& text) {
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    written += static_cast<std::size_t>(n);
  }
  return true;
}

// Creates `directory` and a file in it (removed again); InvalidInput naming `target` otherwise.
void probe_directory(const fs::path& directory, const fs::path& target) {
  make_directory(directory, target);
  std::string probe;
  const int fd = make_temporary(directory, "catena-write-check", probe, target);
  ::close(fd);
  ::unlink(probe.c_str());
}

}  // namespace

std::string path_text(const fs::path& path) {
  const std::string& bytes = path.native();
  std::string text;
  for (std::size_t i = 0; i < bytes.size();) {
    const std::size_t length = utf8_sequence_length(bytes, i);
    if (length == 0) {
      text += fmt::format("\\x{:02X}", static_cast<unsigned char>(bytes[i]));
      ++i;
    } else {
      text.append(bytes, i, length);
      i += length;
    }
  }
  return text;
}

std::string read_input_file(const fs::path& path,
                            const std::string& what,
                            std::uintmax_t max_bytes) {
  auto fail = [&](const std::string& reason) {
    throw ParseError(fmt::format("{}: cannot read {}: {}", path_text(path), what, reason));
  };
  std::error_code error;
  const fs::file_status status = fs::status(path, error);  // follows symlinks
  if (error || status.type() == fs::file_type::not_found) {
    std::error_code link_error;
    const bool missing = !error || error == std::errc::no_such_file_or_directory;
    const bool dangling = missing && fs::is_symlink(fs::symlink_status(path, link_error));
    fail(dangling ? "dangling symbolic link" : error ? error.message() : "no such file");
  }
  if (status.type() != fs::file_type::regular)
    fail(describe(status.type()) + ", not a regular file");
  const std::uintmax_t size = fs::file_size(path, error);
  if (error) fail(error.message());
  if (size > max_bytes)
    fail(fmt::format("{} bytes, more than the limit of {} bytes", size, max_bytes));
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(std::strerror(errno));
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (in.bad() || static_cast<std::uintmax_t>(in.gcount()) != size) fail("read error");
  return text;
}

void write_file_atomically(const fs::path& path, const std::string& text) {
  std::error_code error;
  if (fs::is_directory(path, error)) cannot_write(path, "it is a directory");
  const fs::path directory = directory_of(path);
  make_directory(directory, path);
  std::string temporary;
  const int fd = make_temporary(directory, path.filename().string(), temporary, path);
  const bool written = fchmod(fd, new_file_mode()) == 0 && write_all(fd, text);
  const int write_errno = errno;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    ::unlink(temporary.c_str());
    cannot_write(path, std::strerror(written ? errno : write_errno));
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int rename_errno = errno;
    ::unlink(temporary.c_str());
    cannot_write(path, std::strerror(rename_errno));
  }
}

void check_output_file(const fs::path& path) {
  std::error_code error;
  if (fs::is_directory(path, error)) cannot_write(path, "it is a directory");
  probe_directory(directory_of(path), path);
}

void check_output_directory(const fs::path& directory) { probe_directory(directory, directory); }

}  // namespace catena
