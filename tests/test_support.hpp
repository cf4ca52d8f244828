// Shared helpers of the test suite: reading named-column tables and fitting convergence orders.
#pragma once

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace gbssn1d::testing {

/// A whitespace-separated table whose last '#' line before the data names the columns.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  double at(std::size_t row, const std::string& column) const {
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (columns[c] == column)
        return rows.at(row).at(c);
    throw std::out_of_range("no column " + column);
  }
};

/// Reads the first block of a table; throws if the file is missing or has no data.
inline Table read_table(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error("cannot open reference file " + path);
  Table t;
  std::string line, last_comment;
  while (std::getline(in, line)) {
    if (line.empty()) {
      if (!t.rows.empty())
        break; // end of the first block
      continue;
    }
    if (line[0] == '#') {
      if (line.rfind("# t =", 0) != 0)
        last_comment = line; // block markers name no columns
      continue;
    }
    if (t.columns.empty()) {
      std::istringstream names(last_comment.substr(1));
      for (std::string n; names >> n;)
        t.columns.push_back(n);
    }
    std::istringstream values(line);
    std::vector<double> row;
    for (std::string v; values >> v;)
      row.push_back(std::stod(v));
    if (row.size() != t.columns.size())
      throw std::runtime_error("ragged row in " + path);
    t.rows.push_back(row);
  }
  if (t.rows.empty())
    throw std::runtime_error("no data in " + path);
  return t;
}

/// Cubic Lagrange interpolation in a table with increasing x (4 neighbouring nodes).
inline double interpolate_cubic(const std::vector<double>& x, const std::vector<double>& y,
                                double xi) {
  std::size_t k = std::upper_bound(x.begin(), x.end(), xi) - x.begin();
  k = std::clamp<std::size_t>(k, 2, x.size() - 2) - 2; // nodes k ... k+3
  double sum = 0;
  for (std::size_t j = k; j < k + 4; ++j) {
    double w = 1;
    for (std::size_t m = k; m < k + 4; ++m)
      if (m != j)
        w *= (xi - x[m]) / (x[j] - x[m]);
    sum += w * y[j];
  }
  return sum;
}

/// Least-squares slope of log(err) against log(h): the observed order of convergence.
inline double fit_order(const std::vector<double>& h, const std::vector<double>& err) {
  const std::size_t n = h.size();
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double x = std::log(h[k]), y = std::log(err[k]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace gbssn1d::testing
