#include "io/horizon_file.hpp"

#include "io/table.hpp"

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

namespace gbssn1d {

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
  } catch (const std::runtime_error&) {
    throw HorizonFileError("cannot be read");
  }
  const auto col_t = table.column("t"), col_r = table.column("r_ah");
  if (!col_t || !col_r)
    throw HorizonFileError("needs the columns 't' and 'r_ah'");
  std::vector<double> t, r_ah;
  for (const auto& row : table.rows) {
    if (row.size() <= std::max(*col_t, *col_r))
      throw HorizonFileError(fmt::format("has a short data row (row {})", t.size() + 1));
    if (!std::isfinite(row[*col_r]))
      throw HorizonFileError(fmt::format("has no horizon (r_ah = NaN) at t = {}", row[*col_t]));
    t.push_back(row[*col_t]);
    r_ah.push_back(row[*col_r]);
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
          fmt::format("its times are not equally spaced (row {}: t = {})", k, t[k]));
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
