#include "config/paths.hpp"

#include "config/folder_lock.hpp"
#include "config/params.hpp"
#include "core/text.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <optional>
#include <string>
#include <unistd.h>

namespace gbssn1d {

bool folder_is_empty(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::directory_iterator it(dir, ec);
  if (ec)
    return false; // unreadable: not known to be empty
  for (const auto& entry : it)
    if (entry.path().filename() != folder_lock_name)
      return false;
  return true;
}

namespace {
void refuse_dangling_link(const std::string& flag, const std::filesystem::path& dir);
} // namespace

void validate_output_dir(const Params& p) {
  namespace fs = std::filesystem;
  if (p.out.empty())
    throw ParamError("--out", "''", "an output directory is required");
  check_path("--out", p.out);
  std::error_code ec;
  const fs::path dir(p.out);
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec))
      throw ParamError("--out", p.out, "exists and is not a directory");
    if (const std::optional<long> pid = folder_lock_holder(dir))
      throw ParamError("--out", p.out,
                       *pid > 0 ? fmt::format("is being written by another gbssn1d process (pid "
                                              "{}): wait for it to end, or give another folder",
                                              *pid)
                                : "is being written by another gbssn1d process: wait for it to "
                                  "end, or give another folder");
    if (!folder_is_empty(dir) && !p.force)
      throw ParamError("--out", p.out,
                       fs::is_regular_file(dir / "checkpoint.bin", ec)
                           ? fmt::format("exists and holds a run with a checkpoint: `gbssn1d "
                                         "resume {}` continues it; --force overwrites it",
                                         printable(p.out))
                           : "exists and is not empty (use --force to overwrite)");
    // gbssn1d writes no file through a symbolic link: with --force, a link where it writes
    // would send a file elsewhere (or be replaced): refused, whichever file it stands for
    for (const auto& entry : fs::directory_iterator(dir, ec))
      if (entry.is_symlink(ec))
        throw ParamError("--out", p.out,
                         fmt::format("holds a symbolic link, {}: gbssn1d writes no file through "
                                     "a link; remove it, or give another --out",
                                     printable(entry.path().filename().string())));
    if (::access(dir.c_str(), W_OK | X_OK) != 0)
      throw ParamError("--out", p.out, "is not writable");
    return;
  }
  refuse_dangling_link("--out", dir);
  // The nearest existing ancestor must be a writable directory.
  fs::path parent = fs::absolute(dir, ec).parent_path();
  while (!parent.empty() && !fs::exists(parent, ec))
    parent = parent.parent_path();
  if (parent.empty() || !fs::is_directory(parent, ec) || ::access(parent.c_str(), W_OK | X_OK))
    throw ParamError("--out", p.out, "cannot be created: parent directory is not writable");
}

namespace {

/// A path for a message: at most 120 bytes of it, non-printable bytes escaped.
std::string shown_path(const std::string& path) {
  return path.size() <= 120
             ? printable(path)
             : fmt::format("{}... ({} bytes)", printable(path.substr(0, 100)), path.size());
}

/// Refuses (ParamError naming `flag`) a folder to be made that is, or lies below, a symbolic
/// link to nothing: no folder can be made there (the system says 'File exists'), and making
/// the link's target instead would write elsewhere than the path says.
void refuse_dangling_link(const std::string& flag, const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  fs::path prefix;
  for (const auto& part : dir) {
    prefix /= part;
    std::error_code ec;
    const fs::file_status link = fs::symlink_status(prefix, ec);
    if (ec || !fs::exists(link))
      return; // nothing from here on exists: a path to make
    if (!fs::is_symlink(link))
      continue;
    (void)fs::status(prefix, ec);
    if (ec != std::errc::no_such_file_or_directory)
      continue; // a link to something (a loop is check_path's)
    const bool leaf = (prefix / "").lexically_normal() == (dir / "").lexically_normal();
    throw ParamError(flag, shown_path(dir.string()),
                     leaf ? std::string("is a symbolic link to nothing (its target does not exist)")
                          : fmt::format("lies below {}, a symbolic link to nothing (its target "
                                        "does not exist)",
                                        shown_path(prefix.string())));
  }
}

} // namespace

void check_path(const std::string& flag, const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  const std::string text = path.string();
  // '-' is standard input or output to many tools (the plot scripts read it as standard
  // input; sweep --emit-tasks - writes to standard output): here it would be a file or folder
  // of that name, made or read without a word
  if (text == "-")
    throw ParamError(flag, "-",
                     "not standard input or output here: it would name a file or folder "
                     "called '-' (a run writes several files into a folder); give ./- if that "
                     "is meant");
  if (text.size() > 4095)
    throw ParamError(flag, shown_path(text), "is longer than 4095 bytes, the system's limit");
  for (const auto& part : path)
    if (part.string().size() > 255)
      throw ParamError(
          flag, shown_path(text),
          fmt::format("has a name of {} bytes; the system's limit is 255", part.string().size()));
  std::error_code ec;
  (void)fs::status(path, ec);
  if (!ec || ec == std::errc::no_such_file_or_directory)
    return;
  if (ec == std::errc::too_many_symbolic_link_levels)
    throw ParamError(flag, shown_path(text), "leads into a loop of symbolic links");
  if (ec == std::errc::not_a_directory)
    throw ParamError(flag, shown_path(text), "has a part that is a file, not a folder");
  if (ec == std::errc::permission_denied)
    throw ParamError(flag, shown_path(text), "cannot be reached: permission denied");
  throw ParamError(flag, shown_path(text), "cannot be used: " + ec.message());
}

void check_input_file(const std::string& flag, const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  check_path(flag, path);
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st))
    throw ParamError(flag, shown_path(path.string()), "no such file");
  if (fs::is_directory(st))
    throw ParamError(flag, shown_path(path.string()), "is a folder, not a file");
  if (!fs::is_regular_file(st))
    throw ParamError(flag, shown_path(path.string()),
                     "is not a regular file (a FIFO, device or socket): give a file");
  if (::access(path.c_str(), R_OK) != 0)
    throw ParamError(flag, shown_path(path.string()), "cannot be read: permission denied");
}

void create_output_dir(const std::string& flag, const std::filesystem::path& dir) {
  check_path(flag, dir);
  refuse_dangling_link(flag, dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw ParamError(flag, dir.string(), "cannot be created: " + ec.message());
}

} // namespace gbssn1d
