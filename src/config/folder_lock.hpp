// One writer per output folder. Every command that writes a folder (evolve, resume, converge
// and its members, sweep) holds an advisory lock on DIR/.gbssn1d.lock (a POSIX record lock,
// released by the kernel when the process ends, however it ends) from before its first write
// to its exit; a second process on the same folder is refused before it writes anything,
// naming the holder's pid. The lock file stays, empty: it is never written, so a refused
// command leaves every byte of the folder as it was.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>

namespace gbssn1d {

/// The lock file's name inside an output folder (not counted as content: a folder holding only
/// it is empty).
inline constexpr const char* folder_lock_name = ".gbssn1d.lock";

/// The process id recorded by the process that holds `dir`'s lock now, or nullopt when no
/// process holds it (no lock file, or one nobody holds). Takes no lock.
std::optional<long> folder_lock_holder(const std::filesystem::path& dir);

/// exclusive: the one writer of the folder; shared: one of several writers that may work side
/// by side (a sweep's member tasks), which together exclude an exclusive holder.
enum class LockMode { exclusive, shared };

/// Holds the lock of `dir` (created, with its parents, if missing) until destroyed. Throws
/// ParamError(flag, dir, ...) when another process holds it (in a mode that excludes this
/// one), or when the lock file is a symbolic link or cannot be made.
class FolderLock {
public:
  FolderLock(const std::string& flag, const std::filesystem::path& dir,
             LockMode mode = LockMode::exclusive);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  FolderLock(FolderLock&& other) noexcept : fd_(other.fd_), key_(std::move(other.key_)) {
    other.fd_ = -1;
  }
  FolderLock& operator=(FolderLock&&) = delete;

private:
  int fd_ = -1;
  std::string key_; ///< the lock file's canonical path, in this process's list of held locks
};

} // namespace gbssn1d
