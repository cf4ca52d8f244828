// Reading gbssn1d's own ASCII tables back: the last '#' line before the data names the
// columns; the first block of data rows is read (profiles.dat blocks after the first, and
// their '# t = ...' lines, are not).
//
// Every cell goes through one checked reader (table_cell): a cell that starts as a number does
// (a digit or '.', after an optional sign) must be a whole decimal number by the grammar of
// core/decimal.hpp (no trailing characters, no hexadecimal, within a double's range), else the
// table is refused, naming the file, the line and the text. The words gbssn1d writes for
// non-finite values, nan and inf (with a sign), are those values; other words (a sweep
// summary's status and reasons, '-') are read as NaN. A word that begins with a digit (a sweep
// over --id's 1log-trumpet) cannot be told from a malformed number and is refused.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gbssn1d {

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows; ///< each as long as its line (words read as NaN)
  std::vector<std::size_t> lines;        ///< each row's line number in the file (from 1)
  /// Index of a column, if the table has it.
  std::optional<std::size_t> column(const std::string& name) const;
};

/// A table that cannot be opened, or holds a malformed number ("PATH, line N: ...").
class TableError : public std::runtime_error {
public:
  TableError(const std::string& path, const std::string& reason)
      : std::runtime_error(path + ", " + reason), reason_(reason) {}
  /// The message without the path ("cannot be opened", "line N: ...").
  const std::string& reason() const { return reason_; }

private:
  std::string reason_;
};

/// What a cell of a table is.
struct TableCell {
  enum class Kind { number, word, malformed };
  Kind kind;
  double value; ///< the number (nan and inf words: their values); NaN for words and malformed
};

/// One cell's text read as above.
TableCell table_cell(std::string_view text);

/// Throws TableError if the file cannot be opened or a cell is malformed.
Table read_table(const std::filesystem::path& path);

} // namespace gbssn1d
