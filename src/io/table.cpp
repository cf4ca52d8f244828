#include "io/table.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace gbssn1d {

std::optional<std::size_t> Table::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end())
    return std::nullopt;
  return static_cast<std::size_t>(it - columns.begin());
}

Table read_table(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error("cannot open " + path.string());
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
  for (std::string line; std::getline(in, line);) {
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
    for (std::string w; words >> w;)
      row.push_back(std::strtod(w.c_str(), nullptr));
    table.rows.push_back(std::move(row));
  }
  return table;
}

} // namespace gbssn1d
