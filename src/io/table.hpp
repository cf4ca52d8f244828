// Reading gbssn1d's own ASCII tables back: the last '#' line before the data names the
// columns; the first block of data rows is read (profiles.dat blocks after the first, and
// their '# t = ...' lines, are not).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gbssn1d {

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows; ///< each as long as its line (words read as numbers)
  /// Index of a column, if the table has it.
  std::optional<std::size_t> column(const std::string& name) const;
};

/// Throws std::runtime_error if the file cannot be opened.
Table read_table(const std::filesystem::path& path);

} // namespace gbssn1d
