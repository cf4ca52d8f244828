// Shared helpers of the test suite: scratch directories, tables read back with the library's
// reader (checked to be rectangular and non-empty) and convergence orders fitted with the
// library's fit.
#pragma once

#include "io/table.hpp"
#include "study/orders.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace gbssn1d::testing {

/// An empty path TMP/gbssn1d_tests_PID_NAME (per process: ctest runs test cases concurrently):
/// whatever was there is removed; created as an empty directory if `create`.
inline std::filesystem::path scratch(const std::string& name, bool create = false) {
  const auto dir = std::filesystem::temp_directory_path()
                   / ("gbssn1d_tests_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(dir);
  if (create)
    std::filesystem::create_directories(dir);
  return dir;
}

/// A file's bytes ("" if it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Every regular file below `dir` with its bytes, by path relative to `dir` (a folder's
/// fingerprint: two equal maps, nothing written or changed).
inline std::map<std::string, std::string> contents(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file())
      files[std::filesystem::relative(e.path(), dir).string()] = slurp(e.path());
  return files;
}

/// A table with its columns by name.
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

/// The first block of a table (gbssn1d::read_table); throws if it is empty or ragged.
inline Table read_table(const std::string& path) {
  const gbssn1d::Table t = gbssn1d::read_table(path);
  if (t.rows.empty())
    throw std::runtime_error("no data in " + path);
  for (const auto& row : t.rows)
    if (row.size() != t.columns.size())
      throw std::runtime_error("ragged row in " + path);
  return {t.columns, t.rows};
}

/// Least-squares slope of log(err) against log(h): the observed order of convergence (the
/// library's fit over N = 1/h).
inline double fit_order(const std::vector<double>& h, const std::vector<double>& err) {
  std::vector<double> N;
  for (double x : h)
    N.push_back(1.0 / x);
  return gbssn1d::order_fitted(N, err);
}

} // namespace gbssn1d::testing
