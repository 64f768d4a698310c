// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// How catena touches the file system, in one place (docs/reference/scene-format.md, "Limits"):
/// input files are read only when they are regular files of bounded size; output files are written
/// to a temporary file in the same directory and renamed over the target, so a reader never sees a
/// 0-byte or half-written file; output locations can be checked before any work is done. Every
/// failure is an Error naming the path (escaped when it is not UTF-8) and the reason.

#include <cstdint>
#include <filesystem>
#include <string>

namespace catena {

/// Largest input file read (scene, tolerance table, findings): 1 MiB. Our largest scene is a few
/// kB; a file this large is a mistake (or a device such as /dev/zero), not a scene.
inline constexpr std::uintmax_t kMaxInputFileBytes = 1u << 20;

/// The path as UTF-8 text for messages and JSON: bytes that are not valid UTF-8 are written as
/// \\xNN, so a file name in any encoding can be shown and stored.
std::string path_text(const std::filesystem::path& path);

/// The whole of a regular file of at most `max_bytes`. ParseError "<path>: cannot read <what>:
/// <reason>" when it is missing, a dangling symlink or a symlink loop, not a regular file (a
/// FIFO, a device, a directory), too large, or unreadable.
std::string read_input_file(const std::filesystem::path& path,
                            const std::string& what,
                            std::uintmax_t max_bytes = kMaxInputFileBytes);

/// Writes `text` to `path` atomically: into a temporary file next to it, then renamed over it
/// (parent directories created). InvalidInput naming the path when it cannot be written; the
/// target is then left as it was and no temporary file remains.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

/// Checks, before any work, that write_file_atomically(path, ...) can succeed: the parent
/// directory exists or can be created, is writable, and `path` is not a directory.
/// InvalidInput naming the path and the reason otherwise.
void check_output_file(const std::filesystem::path& path);

/// Checks, before any work, that `directory` exists or can be created and is a writable
/// directory. InvalidInput naming the path and the reason otherwise.
void check_output_directory(const std::filesystem::path& directory);

}  // namespace catena
