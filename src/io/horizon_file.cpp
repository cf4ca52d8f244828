#include "io/horizon_file.hpp"

#include "core/text.hpp"
#include "io/table.hpp"

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <vector>

namespace gbssn1d {

namespace {

/// The text of cell `column` on line `line` of `path` (for messages).
std::string cell_text(const std::string& path, std::size_t line, std::size_t column) {
  std::ifstream in(path);
  std::string text;
  for (std::size_t k = 0; k < line && std::getline(in, text); ++k) {
  }
  std::istringstream words(text);
  std::string word;
  for (std::size_t c = 0; c <= column && words >> word; ++c) {
  }
  return word;
}

/// Why a cell that is not a finite number is refused: "t = 'nan' is not finite",
/// "r_ah = 'ok' is not a number".
std::string not_finite(const char* name, const std::string& text) {
  return fmt::format("{} = '{}' is not {}", name, printable(text),
                     table_cell(text).kind == TableCell::Kind::number ? "finite" : "a number");
}

} // namespace

std::function<double(double)> read_horizon_history(const std::string& path, double t_end) {
  // A regular file of sane size, checked before reading (/dev/zero would be read for ever).
  constexpr std::uintmax_t max_bytes = 1u << 30;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw HorizonFileError("is not a regular file");
  if (const auto size = std::filesystem::file_size(path, ec); ec || size > max_bytes)
    throw HorizonFileError(
        fmt::format("is larger than {} bytes (not a gbssn1d output file)", max_bytes));
  Table table;
  try {
    table = read_table(path);
  } catch (const TableError& e) {
    throw HorizonFileError(e.reason());
  }
  const auto col_t = table.column("t"), col_r = table.column("r_ah");
  if (!col_t || !col_r)
    throw HorizonFileError("needs the columns 't' and 'r_ah'");
  std::vector<double> t, r_ah;
  for (std::size_t k = 0; k < table.rows.size(); ++k) {
    const auto& row = table.rows[k];
    const std::size_t line = table.lines[k];
    // every row as wide as the header: a row cut short (a file copied while it was written,
    // or truncated) may still hold numbers in the t and r_ah columns, but not the run's
    if (row.size() != table.columns.size())
      throw HorizonFileError(fmt::format(
          "line {}: {} column{} where the header names {} ({}): a row {}", line, row.size(),
          row.size() == 1 ? "" : "s", table.columns.size(), fmt::join(table.columns, " "),
          row.size() < table.columns.size() ? "cut short (the file truncated?)"
                                            : "of another table"));
    const double t_k = row[*col_t], r_k = row[*col_r];
    if (!std::isfinite(t_k))
      throw HorizonFileError(
          fmt::format("line {}: {}", line, not_finite("t", cell_text(path, line, *col_t))));
    if (!t.empty() && !(t_k > t.back()))
      throw HorizonFileError(fmt::format(
          "line {}: t = {} does not follow t = {} of the row before (times must increase)", line,
          t_k, t.back()));
    if (!std::isfinite(r_k)) {
      const std::string text = cell_text(path, line, *col_r);
      if (std::isnan(r_k) && table_cell(text).kind == TableCell::Kind::number)
        throw HorizonFileError(
            fmt::format("line {}: has no horizon (r_ah = nan) at t = {}", line, t_k));
      throw HorizonFileError(fmt::format("line {}: {}", line, not_finite("r_ah", text)));
    }
    if (!(r_k > 0.0))
      throw HorizonFileError(
          fmt::format("line {}: r_ah = {} is not a radius (must be positive)", line, r_k));
    t.push_back(t_k);
    r_ah.push_back(r_k);
  }
  if (t.size() < 5)
    throw HorizonFileError("needs at least 5 rows");
  const double dt = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw HorizonFileError(
        fmt::format("its times must increase (t = {} ... {})", t.front(), t.back()));
  for (std::size_t k = 1; k < t.size(); ++k)
    if (std::abs(t[k] - t[0] - static_cast<double>(k) * dt) > 1e-9 * (1.0 + std::abs(t[k])))
      throw HorizonFileError(
          fmt::format("line {}: t = {}: its times are not equally spaced", table.lines[k], t[k]));
  if (t.front() > 0.0 || t.back() < t_end - 1e-9 * (1.0 + t_end))
    throw HorizonFileError(
        fmt::format("covers t = {} ... {}, not the run's 0 ... {}", t.front(), t.back(), t_end));
  // end slopes from 4th-order one-sided differences (Boost's default estimate is cruder)
  const std::size_t m = r_ah.size() - 1;
  const double slope_left =
      (-25.0 * r_ah[0] + 48.0 * r_ah[1] - 36.0 * r_ah[2] + 16.0 * r_ah[3] - 3.0 * r_ah[4])
      / (12.0 * dt);
  const double slope_right = (25.0 * r_ah[m] - 48.0 * r_ah[m - 1] + 36.0 * r_ah[m - 2]
                              - 16.0 * r_ah[m - 3] + 3.0 * r_ah[m - 4])
                             / (12.0 * dt);
  auto spline = std::make_shared<boost::math::interpolators::cardinal_cubic_b_spline<double>>(
      r_ah.begin(), r_ah.end(), t.front(), dt, slope_left, slope_right);
  return [spline](double time) { return (*spline)(time); };
}

} // namespace gbssn1d
