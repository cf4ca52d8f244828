// The output files' common ground: a text file with the standard header (the version and every
// parameter as '#' lines, the columns named) whose every flush is checked, whole-or-nothing
// writes, numbers at full precision, the row hashes a checkpoint records, and the error a
// failed write raises. io/output.hpp writes a run's files with it; studies write theirs.
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gbssn1d {

/// A write that failed (full disk, file-size limit, I/O error): names the file and the reason.
class OutputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// An output time as the decimal it stands for: times are k x cadence (or tmax), computed in
/// binary, e.g. 23 x 0.1 = 2.3000000000000003; 15 significant digits, all a double carries
/// exactly, print it as 2.3 (and read back to within one rounding of the computed value).
inline std::string time_text(double t) {
  return fmt::format("{:.15g}", t);
}

/// Appends v as fmt's "{:.16e}" writes it (17 significant digits, d.dddddddddddddddde+XX; nan,
/// -nan, inf, -inf), byte for byte, through std::to_chars: 2.3 times faster than fmt 9's
/// formatting, which was 30% of a 9-box run's time in its profiles. tests/io/test_output.cpp
/// compares the two on a million values and the special ones.
void append_scientific(fmt::memory_buffer& out, double v);

/// A text file with the standard header. Closes on destruction. Every flush is checked: a
/// failed write throws OutputError.
/// FNV-1a 64-bit, continued over `bytes` from `hash` (start from fnv1a_offset): the output
/// files' row hashes a checkpoint records.
inline constexpr std::uint64_t fnv1a_offset = 14695981039346656037ULL;
inline std::uint64_t fnv1a_continue(std::uint64_t hash, std::string_view bytes) {
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ULL;
  }
  return hash;
}

class DataFile {
public:
  DataFile(const std::filesystem::path& path, const std::string& parameter_header,
           const std::vector<std::string>& columns);
  /// Continues a file cut back to `keep` bytes, whose first `old_header` bytes are replaced by
  /// the new header (a resumed run records its own parameters).
  DataFile(const std::filesystem::path& path, const std::string& parameter_header,
           const std::vector<std::string>& columns, std::uint64_t old_header, std::uint64_t keep);
  ~DataFile();
  DataFile(const DataFile&) = delete;
  DataFile& operator=(const DataFile&) = delete;
  /// Buffered writes; failures surface at the next flush().
  template <class... T>
  void print(fmt::format_string<T...> format, T&&... args) {
    const std::string text = fmt::format(format, std::forward<T>(args)...);
    write(text.data(), text.size());
  }
  void write(const char* data, std::size_t size) {
    std::fwrite(data, 1, size, file_);
    if (in_body_)
      body_hash_ = fnv1a_continue(body_hash_, {data, size});
  }
  /// Writes the buffer out (a failed write throws OutputError) and checks that the file is
  /// still the one at its path (a removed or replaced folder throws OutputError).
  void flush();
  /// Bytes written so far (after a flush), and the header's length.
  std::uint64_t size();
  std::uint64_t header_size() const { return header_size_; }
  /// The FNV-1a 64-bit hash of every byte after the header written so far (the rows).
  std::uint64_t body_hash() const { return body_hash_; }

private:
  void flush_buffer();
  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
  std::uint64_t header_size_ = 0;
  bool in_body_ = false; ///< the header is written: write() hashes what follows
  std::uint64_t body_hash_ = fnv1a_offset;
};

/// Writes `text` to `path` whole or not at all (a temporary file, flushed to disk, then renamed
/// over it; on failure the temporary file is removed);
/// throws OutputError naming the file if it cannot.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

/// "# gbssn1d <version>" and the parameters as '#' lines.
std::string header_text(const std::string& parameter_header);

} // namespace gbssn1d
