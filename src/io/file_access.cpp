// SPDX-License-Identifier: MIT
#include "catena/io/file_access.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <system_error>

#include "catena/core/error.hpp"
#include "io/internal/utf8_text.hpp"

namespace catena {
namespace {

namespace fs = std::filesystem;

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
  throw InvalidInput(
      fmt::format("{}: cannot write: {}", path.empty() ? "\"\"" : path_text(path), reason));
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

// The nearest of `directory` and its parents that exists ("." for a relative path's start).
fs::path nearest_existing(fs::path directory) {
  std::error_code error;
  while (!directory.empty() && !fs::exists(fs::symlink_status(directory, error))) {
    const fs::path parent = directory.parent_path();
    if (parent == directory) break;
    directory = parent;
  }
  return directory.empty() ? fs::path(".") : directory;
}

// Checks that `directory` could be created (it is not, so that a run refused later leaves nothing
// behind) and written: a file is created in the nearest existing directory and removed again.
// A real file rather than access(2), which says yes to root on /proc and to anyone on some
// network file systems. InvalidInput naming `target` otherwise.
void probe_directory(const fs::path& directory, const fs::path& target) {
  const fs::path existing = nearest_existing(directory);
  std::error_code error;
  if (!fs::is_directory(existing, error))
    cannot_write(target, fmt::format("{} is not a directory", path_text(existing)));
  std::string probe;
  const int fd = make_temporary(existing, "catena-write-check", probe, target);
  ::close(fd);
  ::unlink(probe.c_str());
}

// What is at an output path, and so how it is written.
struct OutputTarget {
  enum class Kind { New, Regular, WriteThrough } kind = Kind::New;
  fs::path path;    // where the file is replaced (a symlink's target) or written through
  mode_t mode = 0;  // a regular file's permissions, kept when it is replaced
  uid_t owner = 0;  // and its owner and group (run as root, the new file would be root's)
  gid_t group = 0;
};

// Classifies `path`. A symlink is followed deliberately: users keep links such as
// latest.json -> runs/today.json, and a shell's `>` writes through them; replacing the link with a
// regular file would break it silently. So its target is replaced and the link stays. A dangling
// link or a loop is refused: where the file would be created is not what the user can see.
// A character device or FIFO (/dev/null, /dev/stdout, a named pipe) is written through, never
// replaced; a directory, block device or socket is refused.
OutputTarget classify_output(const fs::path& path) {
  if (path.empty()) cannot_write(path, "an empty path");
  struct stat link {};
  if (::lstat(path.c_str(), &link) != 0) return {OutputTarget::Kind::New, path, 0};
  struct stat target = link;
  if (S_ISLNK(link.st_mode) && ::stat(path.c_str(), &target) != 0) {
    cannot_write(path, errno == ELOOP    ? "a loop of symbolic links"
                       : errno == ENOENT ? "a dangling symbolic link (its target does not exist)"
                                         : std::strerror(errno));
  }
  // /dev/stdout, /dev/fd/1 or /proc/self/fd/1 leading to a regular file: a stream this process
  // has open (`catena solve S --json /dev/stdout > out.json`), not a file to replace; renaming
  // over it would leave the shell's descriptor on an unlinked file.
  const bool stream = S_ISLNK(link.st_mode) && (path.native().rfind("/dev/", 0) == 0 ||
                                                path.native().rfind("/proc/", 0) == 0);
  if (S_ISREG(target.st_mode) && !stream) {
    std::error_code error;
    const fs::path resolved = S_ISLNK(link.st_mode) ? fs::canonical(path, error) : path;
    if (error) cannot_write(path, error.message());
    return {OutputTarget::Kind::Regular, resolved, static_cast<mode_t>(target.st_mode & 07777),
            target.st_uid, target.st_gid};
  }
  if (S_ISCHR(target.st_mode) || S_ISFIFO(target.st_mode) || S_ISREG(target.st_mode))
    return {OutputTarget::Kind::WriteThrough, path, 0};
  if (S_ISDIR(target.st_mode)) cannot_write(path, "it is a directory");
  const fs::file_type type = S_ISBLK(target.st_mode)    ? fs::file_type::block
                             : S_ISSOCK(target.st_mode) ? fs::file_type::socket
                                                        : fs::file_type::unknown;
  cannot_write(path, describe(type) +
                         "; only regular files, character devices and FIFOs are "
                         "written");
}

// The descriptor of this process that `path` names (/dev/stdout, /dev/stderr, /dev/fd/N,
// /proc/self/fd/N), or -1. Written through that descriptor, the output shares its offset with
// what the process prints there: opened anew, it would be overwritten by the next print.
int own_descriptor(const fs::path& path) {
  const std::string& text = path.native();
  if (text == "/dev/stdout") return STDOUT_FILENO;
  if (text == "/dev/stderr") return STDERR_FILENO;
  for (const std::string prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    if (text.rfind(prefix, 0) != 0 || text.size() == prefix.size() ||
        text.size() > prefix.size() + 6)
      continue;
    if (text.find_first_not_of("0123456789", prefix.size()) != std::string::npos) continue;
    return std::stoi(text.substr(prefix.size()));
  }
  return -1;
}

// Writes `text` through to a character device, FIFO or open stream: opened without O_CREAT or
// O_TRUNC, so the node stays what it is (a stream of this process: through its descriptor, after
// what was printed to it, flushed first). A FIFO blocks until a reader opens it, as a shell's `>`
// does.
void write_through(const fs::path& path, const std::string& text) {
  std::fflush(nullptr);
  const int own = own_descriptor(path);
  if (own >= 0 && ::fcntl(own, F_GETFD) != -1) {
    if (!write_all(own, text)) cannot_write(path, std::strerror(errno));
    return;
  }
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) cannot_write(path, std::strerror(errno));
  const bool written = write_all(fd, text);
  const int write_errno = errno;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) cannot_write(path, std::strerror(written ? errno : write_errno));
}

// Writes `text` to a temporary file in the directory of `target.path` and renames it over the
// target: a reader sees the old file or the whole new one.
void replace_atomically(const OutputTarget& target,
                        const fs::path& named,
                        const std::string& text) {
  const fs::path directory = directory_of(target.path);
  make_directory(directory, named);
  std::string temporary;
  const int fd = make_temporary(directory, target.path.filename().string(), temporary, named);
  const mode_t mode = target.kind == OutputTarget::Kind::Regular ? target.mode : new_file_mode();
  // Owner first: chown clears set-id bits, which fchmod then restores. A user who may not give
  // the file away (not root) keeps the new file as their own, as a plain write would not; that
  // failure is not an error.
  if (target.kind == OutputTarget::Kind::Regular &&
      (target.owner != ::geteuid() || target.group != ::getegid()))
    static_cast<void>(::fchown(fd, target.owner, target.group));
  const bool written = fchmod(fd, mode) == 0 && write_all(fd, text);
  const int write_errno = errno;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    ::unlink(temporary.c_str());
    cannot_write(named, std::strerror(written ? errno : write_errno));
  }
  if (std::rename(temporary.c_str(), target.path.c_str()) != 0) {
    const int rename_errno = errno;
    ::unlink(temporary.c_str());
    cannot_write(named, std::strerror(rename_errno));
  }
}

}  // namespace

std::string path_text(const fs::path& path) { return internal::utf8_text(path.native()); }

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
  // A byte-order mark FF FE or FE FF: a Windows editor's "Unicode" (UTF-16, or UTF-32). Every
  // format catena reads is UTF-8 text; parsed on, it would give an error full of NUL bytes.
  if (text.size() >= 2 &&
      ((text[0] == '\xFF' && text[1] == '\xFE') || (text[0] == '\xFE' && text[1] == '\xFF'))) {
    fail(fmt::format("UTF-16 text (it starts with a UTF-16 byte-order mark); save the {} as UTF-8",
                     what));
  }
  return text;
}

void write_file_atomically(const fs::path& path, const std::string& text) {
  const OutputTarget target = classify_output(path);
  if (target.kind == OutputTarget::Kind::WriteThrough) {
    write_through(target.path, text);
  } else {
    replace_atomically(target, path, text);
  }
}

void check_output_file(const fs::path& path) {
  const OutputTarget target = classify_output(path);
  // A device or FIFO is not opened here: a FIFO would block until a reader comes.
  if (target.kind == OutputTarget::Kind::WriteThrough) {
    if (::access(target.path.c_str(), W_OK) != 0) cannot_write(path, std::strerror(errno));
    return;
  }
  probe_directory(directory_of(target.path), path);
}

void check_output_directory(const fs::path& directory) {
  if (directory.empty()) cannot_write(directory, "an empty path");
  probe_directory(directory, directory);
}

void check_not_an_input(const fs::path& output,
                        const std::vector<fs::path>& inputs,
                        const std::string& what) {
  for (const auto& input : inputs) {
    std::error_code error;
    // Device and inode, not names: "S", "./S", a hard link and a symlink to S are one file.
    if (input.empty() || !fs::equivalent(output, input, error) || error) continue;
    throw InvalidInput(fmt::format(
        "{} {}: cannot write: it is the same file as the input {} of this run; refusing to "
        "overwrite an input (write the output elsewhere)",
        what, path_text(output), path_text(input)));
  }
}

}  // namespace catena
