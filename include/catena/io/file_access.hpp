// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// How catena touches the file system, in one place (docs/reference/scene-format.md, "Limits"):
/// input files are read only when they are regular files of bounded size; an output that is a
/// regular file (or a new one) is written to a temporary file in the same directory and renamed
/// over the target, so a reader never sees a 0-byte or half-written file; a symlink is followed
/// (its target replaced, the link kept); a character device or FIFO is written through, never
/// replaced; an output that is an input of the same run is refused; output locations are checked
/// before any work is done, without creating anything. Every failure is an Error naming the path
/// (escaped when it is not UTF-8) and the reason.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace catena {

/// Largest input file read (scene, tolerance table, findings): 1 MiB. Our largest scene is a few
/// kB; a file this large is a mistake (or a device such as /dev/zero), not a scene.
inline constexpr std::uintmax_t kMaxInputFileBytes = 1u << 20;

/// The path as UTF-8 text for messages and JSON: bytes that are not valid UTF-8 are written as
/// \\xNN, so a file name in any encoding can be shown and stored.
std::string path_text(const std::filesystem::path& path);

/// The whole of a regular file of at most `max_bytes`. ParseError "<path>: cannot read <what>:
/// <reason>" when it is missing, a dangling symlink or a symlink loop, not a regular file (a
/// FIFO, a device, a directory), too large, unreadable, or UTF-16 text (a byte-order mark).
std::string read_input_file(const std::filesystem::path& path,
                            const std::string& what,
                            std::uintmax_t max_bytes = kMaxInputFileBytes);

/// Writes `text` to `path`:
/// - a regular file or a new one: into a temporary file next to it, then renamed over it (parent
///   directories created; an existing file keeps its permissions, and its owner when catena may
///   give the file away, as root may);
/// - a symlink to a regular file: the same, next to the link's final target, which is replaced;
///   the link stays a link;
/// - a character device or FIFO (/dev/null, /dev/stdout, a named pipe): written through, opened
///   without creating or truncating, so the node stays; a FIFO waits for its reader;
/// - /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N leading to a regular file (a shell's
///   redirection): written through the process's own descriptor, after what it printed there.
/// InvalidInput naming the path when it is empty, a directory, a block device, a socket, a
/// dangling symlink or a loop, or cannot be written; the target is then left as it was and no
/// temporary file remains.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

/// Checks, before any work, that write_file_atomically(path, ...) can succeed: the path is of a
/// kind it writes, the directory it goes in exists or can be created and is writable (a file is
/// created there and removed; no directory is created). InvalidInput naming the path and the
/// reason otherwise.
void check_output_file(const std::filesystem::path& path);

/// Checks, before any work, that `directory` exists and is writable or can be created (nothing is
/// created). InvalidInput naming the path and the reason otherwise.
void check_output_directory(const std::filesystem::path& directory);

/// InvalidInput "<what> <output>: cannot write: it is the same file as the input <input> ..."
/// when `output` exists and is one of `inputs`: compared by device and inode, so "S", "./S", a
/// hard link and a symlink to S all match. Called before any work, so that no run replaces its
/// own input.
void check_not_an_input(const std::filesystem::path& output,
                        const std::vector<std::filesystem::path>& inputs,
                        const std::string& what);

}  // namespace catena
