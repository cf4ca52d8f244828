#include "io/table.hpp"

#include "core/decimal.hpp"
#include "core/text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>

namespace gbssn1d {

TableCell table_cell(std::string_view text) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::string_view body = text;
  if (!body.empty() && (body.front() == '-' || body.front() == '+'))
    body.remove_prefix(1);
  const bool number_like =
      !body.empty() && ((body.front() >= '0' && body.front() <= '9') || body.front() == '.');
  if (number_like) {
    if (const auto value = parse_decimal<double>(text))
      return {TableCell::Kind::number, *value};
    return {TableCell::Kind::malformed, nan};
  }
  // the words fmt writes for non-finite doubles
  const bool negative = !text.empty() && text.front() == '-';
  if (body == "nan")
    return {TableCell::Kind::number, negative ? -nan : nan};
  if (body == "inf")
    return {TableCell::Kind::number, negative ? -inf : inf};
  return {TableCell::Kind::word, nan};
}

std::optional<std::size_t> Table::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end())
    return std::nullopt;
  return static_cast<std::size_t>(it - columns.begin());
}

Table read_table(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in)
    throw TableError(printable(path.string()), "cannot be opened");
  Table table;
  std::vector<std::string> names;
  // gbssn1d writes the column names first and its version line second; in other tables (and
  // files of earlier versions, which began with the version line) the names are the last
  // comment line before the first row.
  std::string first, second;
  std::getline(in, first);
  std::getline(in, second);
  const bool names_first = !first.empty() && first[0] == '#' && second.rfind("# gbssn1d", 0) == 0;
  in.clear();
  in.seekg(0);
  std::size_t line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (line.empty()) {
      if (!table.rows.empty())
        break; // end of the first block
      continue;
    }
    if (line[0] == '#') {
      if (names_first ? !names.empty()
                      : line.rfind("# t =", 0) == 0 || line.rfind("# end:", 0) == 0)
        continue; // parameters, block markers and end lines name no columns
      std::istringstream words(line.substr(1));
      names.clear();
      for (std::string w; words >> w;)
        names.push_back(w);
      continue;
    }
    if (table.rows.empty())
      table.columns = names;
    std::istringstream words(line);
    std::vector<double> row;
    for (std::string w; words >> w;) {
      const TableCell cell = table_cell(w);
      if (cell.kind == TableCell::Kind::malformed) {
        const std::size_t c = row.size();
        const std::string why = real_out_of_range(w);
        throw TableError(
            printable(path.string()),
            fmt::format("line {}: '{}'{} {}", line_number, printable(w),
                        c < table.columns.size() ? " in column " + table.columns[c] : "",
                        why.empty() ? "is not a number (a decimal number, nan or inf)" : why));
      }
      row.push_back(cell.value);
    }
    table.rows.push_back(std::move(row));
    table.lines.push_back(line_number);
  }
  return table;
}

} // namespace gbssn1d
