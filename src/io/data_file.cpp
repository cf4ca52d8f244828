#include "io/data_file.hpp"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <sstream>

namespace gbssn1d {

void append_scientific(fmt::memory_buffer& out, double v) {
  char text[32]; // at most 24: -d.dddddddddddddddde+308
  const auto [end, error] =
      std::to_chars(text, text + sizeof text, v, std::chars_format::scientific, 16);
  if (error != std::errc{})
    throw std::logic_error("append_scientific: std::to_chars failed");
  out.append(text, end);
}

namespace {

/// `path` opened for writing as a new file, without following a link: a symbolic link there is
/// refused, naming it, rather than written through; a file already there is unlinked first,
/// not emptied, so that its other names (hard links: a backup made by `cp -al` or `rsync
/// --link-dest`) keep their content (--force, a rerun, a resume's temporary files).
std::FILE* open_for_writing(const std::filesystem::path& path) {
  const auto symlink_refused = [&] {
    return OutputError(fmt::format(
        "cannot write {}: it is a symbolic link (gbssn1d writes no file through a link)",
        path.string()));
  };
  struct ::stat there {};
  if (::lstat(path.c_str(), &there) == 0) {
    if (S_ISLNK(there.st_mode))
      throw symlink_refused();
    if (S_ISREG(there.st_mode) && ::unlink(path.c_str()) != 0 && errno != ENOENT)
      throw OutputError(fmt::format("cannot replace {}: {}", path.string(), std::strerror(errno)));
  }
  // O_EXCL: a new file (a link made at the path meanwhile is refused, not followed)
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0)
    throw errno == ELOOP ? symlink_refused()
                         : OutputError(fmt::format("cannot open {} for writing: {}", path.string(),
                                                   std::strerror(errno)));
  std::FILE* f = ::fdopen(fd, "w");
  if (!f) {
    const int err = errno;
    ::close(fd);
    throw OutputError(
        fmt::format("cannot open {} for writing: {}", path.string(), std::strerror(err)));
  }
  return f;
}

} // namespace

void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
  // a temporary file, flushed to disk, then renamed over the old one: a reader (or a run killed
  // meanwhile) sees the old file or the new one, never a mixture
  const std::filesystem::path tmp = path.string() + ".tmp";
  std::FILE* f = open_for_writing(tmp);
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fflush(f) == 0
                  && ::fsync(::fileno(f)) == 0;
  std::fclose(f);
  if (!ok) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw OutputError(fmt::format("cannot write {}", tmp.string()));
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec)
    throw OutputError(fmt::format("cannot replace {}: {}", path.string(), ec.message()));
}

std::string header_text(const std::string& parameter_header) {
  std::string text = fmt::format("# gbssn1d {}\n", GBSSN1D_VERSION);
  std::istringstream lines(parameter_header);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty())
      text += "# " + line + "\n";
  return text;
}

namespace {

/// The column names first, as a comment line (`numpy.genfromtxt(file, names=True)` takes its
/// names from the first line), then the version and the parameters.
std::string header_with_columns(const std::string& parameter_header,
                                const std::vector<std::string>& columns) {
  std::string text = "#";
  for (const auto& c : columns)
    text += " " + c;
  return text + "\n" + header_text(parameter_header);
}

} // namespace

DataFile::DataFile(const std::filesystem::path& path, const std::string& parameter_header,
                   const std::vector<std::string>& columns)
    : path_(path) {
  file_ = open_for_writing(path);
  const std::string text = header_with_columns(parameter_header, columns);
  std::fputs(text.c_str(), file_);
  header_size_ = text.size();
  in_body_ = true;
  flush();
}

DataFile::DataFile(const std::filesystem::path& path, const std::string& parameter_header,
                   const std::vector<std::string>& columns, std::uint64_t old_header,
                   std::uint64_t keep)
    : path_(path) {
  // the old body, [old_header, keep), under the new header; written to a temporary file and
  // renamed, so that a failure leaves the old file as it was
  std::string body;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in)
      throw OutputError(fmt::format("cannot read {} to resume", path.string()));
    std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (all.size() < keep || keep < old_header)
      throw OutputError(fmt::format("{} is shorter than at the checkpoint", path.string()));
    body = all.substr(old_header, keep - old_header);
  }
  const std::string head = header_with_columns(parameter_header, columns);
  const std::filesystem::path tmp = path.string() + ".resume";
  file_ = open_for_writing(tmp);
  write(head.data(), head.size());
  in_body_ = true;
  write(body.data(), body.size());
  header_size_ = head.size();
  flush_buffer(); // (not flush(): the file is not at its path until renamed)
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec)
    throw OutputError(fmt::format("cannot replace {}: {}", path.string(), ec.message()));
}

std::uint64_t DataFile::size() {
  flush();
  const long pos = std::ftell(file_);
  if (pos < 0)
    throw OutputError(fmt::format("cannot tell the size of {}", path_.string()));
  return static_cast<std::uint64_t>(pos);
}

DataFile::~DataFile() {
  if (file_)
    std::fclose(file_);
}

void DataFile::flush_buffer() {
  if (std::fflush(file_) != 0 || std::ferror(file_))
    throw OutputError(fmt::format("cannot write {}: {}", path_.string(),
                                  errno != 0 ? std::strerror(errno) : "write error"));
}

void DataFile::flush() {
  flush_buffer();
  // Writes into a file whose folder was removed or replaced succeed and vanish: the file must
  // still be the one at its path.
  struct stat open_file {
  }, at_path{};
  if (::fstat(::fileno(file_), &open_file) != 0 || ::stat(path_.c_str(), &at_path) != 0
      || open_file.st_ino != at_path.st_ino || open_file.st_dev != at_path.st_dev)
    throw OutputError(fmt::format("{} was removed or replaced during the run (its folder "
                                  "deleted or moved?): nothing more can be kept",
                                  path_.string()));
}

} // namespace gbssn1d
