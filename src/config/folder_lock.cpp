#include "config/folder_lock.hpp"

#include "config/params.hpp"
#include "config/paths.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <mutex>
#include <set>
#include <string>
#include <unistd.h>

namespace gbssn1d {

namespace {

// POSIX record locks (fcntl), not flock(2): F_GETLK names the holder's pid, and they work on
// NFS. They belong to the process and end when it closes any descriptor of the file, so this
// process never opens a lock file it holds a second time: the folders it holds are listed here.
std::mutex held_mutex;
std::set<std::string>& held_files() {
  static std::set<std::string> files;
  return files;
}

std::string key_of(const std::filesystem::path& file) {
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(file, ec);
  return ec ? file.string() : canonical.string();
}

struct flock whole_file(short type) {
  struct flock l {};
  l.l_type = type;
  l.l_whence = SEEK_SET;
  l.l_start = 0;
  l.l_len = 0; // to the end, however long
  return l;
}

} // namespace

std::optional<long> folder_lock_holder(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / folder_lock_name;
  {
    const std::lock_guard guard(held_mutex);
    if (held_files().count(key_of(file)))
      return static_cast<long>(::getpid());
  }
  const int fd = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0)
    return std::nullopt;
  struct flock l = whole_file(F_WRLCK);
  std::optional<long> holder;
  if (::fcntl(fd, F_GETLK, &l) == 0 && l.l_type != F_UNLCK)
    holder = static_cast<long>(l.l_pid);
  ::close(fd);
  return holder;
}

FolderLock::FolderLock(const std::string& flag, const std::filesystem::path& dir, LockMode mode) {
  create_output_dir(flag, dir);
  const std::filesystem::path file = dir / folder_lock_name;
  const std::lock_guard guard(held_mutex);
  if (held_files().count(key_of(file)))
    throw ParamError(flag, dir.string(), "is already being written by this process");
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    const int err = errno;
    throw ParamError(flag, dir.string(),
                     err == ELOOP ? fmt::format("its lock file {} is a symbolic link: remove it",
                                                folder_lock_name)
                                  : fmt::format("cannot {} its lock file {}: {}",
                                                std::filesystem::exists(file) ? "open" : "make",
                                                folder_lock_name, std::strerror(err)));
  }
  const short type = mode == LockMode::exclusive ? F_WRLCK : F_RDLCK;
  struct flock l = whole_file(type);
  if (::fcntl(fd_, F_SETLK, &l) != 0) {
    const int err = errno;
    struct flock who = whole_file(type);
    const bool known = ::fcntl(fd_, F_GETLK, &who) == 0 && who.l_type != F_UNLCK;
    ::close(fd_);
    fd_ = -1;
    throw ParamError(
        flag, dir.string(),
        err == EACCES || err == EAGAIN
            ? fmt::format("is being written by another gbssn1d process{}: wait for it to end, "
                          "or give another folder",
                          known ? fmt::format(" (pid {})", static_cast<long>(who.l_pid)) : "")
            : fmt::format("cannot lock {}: {}", folder_lock_name, std::strerror(err)));
  }
  key_ = key_of(file);
  held_files().insert(key_);
}

FolderLock::~FolderLock() {
  if (fd_ < 0)
    return;
  const std::lock_guard guard(held_mutex);
  held_files().erase(key_);
  ::close(fd_); // releases the lock
}

} // namespace gbssn1d
