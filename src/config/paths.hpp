// The paths a run reads and writes: checked before anything is written (a name the file system
// cannot take, a loop of symbolic links, a folder not writable, a link where a file would be
// written), and output folders made, each refusal a ParamError naming the flag.
#pragma once

#include <filesystem>
#include <string>

namespace gbssn1d {

struct Params;

/// Throws ParamError if --out cannot be used (exists and is not an empty directory, unless
/// --force; not writable; a path the file system cannot take). Creates nothing.
void validate_output_dir(const Params& p);
/// Whether a folder holds nothing but (perhaps) its lock file (config/folder_lock.hpp).
bool folder_is_empty(const std::filesystem::path& dir);

/// Refuses (ParamError naming `flag`) a path the file system cannot take: a name in it longer
/// than 255 bytes or the whole longer than 4095, a loop of symbolic links, a part that is not a
/// folder, a folder it cannot search, and '-' (not standard input or output: ./- names a file
/// of that name). A path that does not exist yet is fine.
void check_path(const std::string& flag, const std::filesystem::path& path);

/// check_path(), and the path names a regular file that can be read: not missing, not a
/// folder, a FIFO or a device.
void check_input_file(const std::string& flag, const std::filesystem::path& path);

/// create_directories(dir), or ParamError naming `flag` and the reason (no filesystem_error
/// text leaks out).
void create_output_dir(const std::string& flag, const std::filesystem::path& dir);

} // namespace gbssn1d
