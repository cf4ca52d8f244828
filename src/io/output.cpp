#include "io/output.hpp"

#include "core/registry.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace gbssn1d {

void append_scientific(fmt::memory_buffer& out, double v) {
  char text[32]; // at most 24: -d.dddddddddddddddde+308
  const auto [end, error] =
      std::to_chars(text, text + sizeof text, v, std::chars_format::scientific, 16);
  if (error != std::errc{})
    throw std::logic_error("append_scientific: std::to_chars failed");
  out.append(text, end);
}

double SeriesRow::extra(std::string_view column) const {
  for (const auto& [name, value] : {std::pair<std::string_view, double>{"G_L2_R", G_L2_R},
                                    {"Theta_L2_ext", Theta_L2_ext},
                                    {"Theta_L2_R", Theta_L2_R}})
    if (name == column)
      return value;
  throw std::invalid_argument("no series column " + std::string(column));
}

std::vector<std::string> series_columns(Formulation formulation) {
  std::vector<std::string> cols{
      "t",        "alpha_center", "H_L2",     "H_L2_ext",        "M_L2",
      "M_L2_ext", "G_L2",         "G_L2_ext", "dtalpha_max_ext", "r_ah",
      "M_ah",     "H_L2_R",       "M_L2_R",   "H_L2_int",        "M_ah_err"};
  for (const std::string_view name : traits(formulation).extra_series)
    cols.emplace_back(name);
  return cols;
}

std::vector<std::string> profile_columns(Formulation formulation) {
  std::vector<std::string> cols{"r"};
  for (const auto& entry : evolved(formulation))
    cols.emplace_back(entry.name);
  for (const char* name :
       {"H", "M_r", "G_r", "R_areal", "Theta_plus", "m_ms", "beta_GD", "beta_H", "level"})
    cols.emplace_back(name);
  return cols;
}

std::vector<std::string> horizon_columns() {
  return {"t",       "r_ah",    "R_ah",    "M_ah",    "n_roots",
          "r_root2", "R_root2", "r_root3", "R_root3", "level"};
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

namespace {

const char* const series_legend =
    "timeseries.dat: *_L2 norms over the whole grid, *_L2_ext over the fixed coordinate region "
    "norm-rmin <= r <= norm-rmax (the same rule before and after a horizon forms), weighted by "
    "cell width; *_L2_R over the areal-radius window norm-Rmin M <= R <= norm-Rmax M (the same "
    "place in every gauge), weighted by areal width |dR|; H_L2_int from the puncture out to "
    "R = norm-Rint M, weighted by cell width; a norm (and dtalpha_max_ext) is NaN while its "
    "window holds no point; r_ah, M_ah: apparent horizon (NaN if none), M_ah_err = M_ah - M\n";
std::string legend(Formulation formulation) {
  return std::string(series_legend) + std::string(traits(formulation).series_legend);
}
const char* const horizon_legend =
    "horizon.dat: r_ah, R_ah, M_ah = R_ah/2 of the apparent horizon (outermost zero of Theta_+ "
    "with Theta_+ < 0 inside; NaN if none); n_roots counts every zero of Theta_+; r_root2/3, "
    "R_root2/3 are the next zeros inwards (NaN if none); level: the box the horizon was found "
    "on (0 on a single grid, -1 without a horizon)\n";

} // namespace

Output::Output(const std::filesystem::path& dir, const std::string& parameter_header,
               Formulation formulation)
    : dir_(dir), formulation_(formulation),
      series_(dir / "timeseries.dat", parameter_header + legend(formulation),
              series_columns(formulation)),
      profiles_(dir / "profiles.dat", parameter_header, profile_columns(formulation)),
      horizons_(dir / "horizon.dat", parameter_header + horizon_legend, horizon_columns()) {}

Output::Output(const std::filesystem::path& dir, const std::string& parameter_header,
               Formulation formulation, const OutputMarks& m)
    : dir_(dir), formulation_(formulation),
      series_(dir / "timeseries.dat", parameter_header + legend(formulation),
              series_columns(formulation), m.series_header, m.series),
      profiles_(dir / "profiles.dat", parameter_header, profile_columns(formulation),
                m.profiles_header, m.profiles),
      horizons_(dir / "horizon.dat", parameter_header + horizon_legend, horizon_columns(),
                m.horizons_header, m.horizons),
      first_block_(m.profiles <= m.profiles_header) {}

void Output::check_resumable(const std::filesystem::path& dir, const OutputMarks& m) {
  const std::pair<const char*, std::pair<std::uint64_t, std::uint64_t>> files[] = {
      {"timeseries.dat", {m.series_header, m.series}},
      {"profiles.dat", {m.profiles_header, m.profiles}},
      {"horizon.dat", {m.horizons_header, m.horizons}}};
  for (const auto& [name, mark] : files) {
    const std::filesystem::path path = dir / name;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
      throw OutputError(fmt::format("{} is missing: the run cannot be resumed", path.string()));
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || size < mark.second || mark.second < mark.first)
      throw OutputError(fmt::format("{} is shorter than at the checkpoint ({} bytes, {} expected)",
                                    path.string(), size, mark.second));
  }
  if (!m.hashed)
    return; // a checkpoint of format 3 or earlier: lengths alone
  const std::pair<const char*, std::uint64_t> hashes[] = {{"timeseries.dat", m.series_hash},
                                                          {"profiles.dat", m.profiles_hash},
                                                          {"horizon.dat", m.horizons_hash}};
  for (std::size_t k = 0; k < 3; ++k) {
    const std::filesystem::path path = dir / files[k].first;
    const auto [from, to] = files[k].second;
    std::ifstream in(path, std::ios::binary);
    std::string rows(to - from, '\0');
    if (!in.seekg(static_cast<std::streamoff>(from))
        || !in.read(rows.data(), static_cast<std::streamsize>(rows.size())))
      throw OutputError(fmt::format("cannot read {} to resume", path.string()));
    if (fnv1a_continue(fnv1a_offset, rows) != hashes[k].second)
      throw OutputError(fmt::format(
          "{} is not what the run wrote up to its checkpoint (its rows were edited or replaced "
          "since): the run cannot be resumed from it",
          path.string()));
  }
}

OutputMarks Output::marks() {
  OutputMarks m;
  m.series = series_.size();
  m.profiles = profiles_.size();
  m.horizons = horizons_.size();
  m.series_header = series_.header_size();
  m.profiles_header = profiles_.header_size();
  m.horizons_header = horizons_.header_size();
  m.series_hash = series_.body_hash();
  m.profiles_hash = profiles_.body_hash();
  m.horizons_hash = horizons_.body_hash();
  m.hashed = true;
  return m;
}

void Output::write_series(const SeriesRow& row) {
  fmt::memory_buffer line;
  fmt::format_to(std::back_inserter(line), "{}", time_text(row.t));
  for (double v : {row.alpha_center, row.H_L2, row.H_L2_ext, row.M_L2, row.M_L2_ext, row.G_L2,
                   row.G_L2_ext, row.dtalpha_max_ext, row.r_ah, row.M_ah, row.H_L2_R, row.M_L2_R,
                   row.H_L2_int, row.M_ah_err}) {
    line.push_back(' ');
    append_scientific(line, v);
  }
  for (const std::string_view column : traits(formulation_).extra_series) {
    line.push_back(' ');
    append_scientific(line, row.extra(column));
  }
  line.push_back('\n');
  series_.write(line.data(), line.size());
  series_.flush();
}

void Output::write_horizons(double t, const HorizonSearch& search) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto horizon = search.horizon();
  // the zeros inside the horizon (or all of them, without one), outermost first
  std::vector<const MarginalSurface*> others;
  for (const auto& s : search.surfaces)
    if (!horizon || s.r < horizon->r)
      others.push_back(&s);
  auto r_of = [&](std::size_t k) { return k < others.size() ? others[k]->r : nan; };
  auto R_of = [&](std::size_t k) { return k < others.size() ? others[k]->R_areal : nan; };
  // the box the horizon was found on (-1 without one)
  const long level = horizon ? static_cast<long>(horizon->level) : -1;
  horizons_.print("{} {:.16e} {:.16e} {:.16e} {} {:.16e} {:.16e} {:.16e} {:.16e} {}\n",
                  time_text(t), horizon ? horizon->r : nan, horizon ? horizon->R_areal : nan,
                  horizon ? horizon->mass : nan, search.surfaces.size(), r_of(0), R_of(0), r_of(1),
                  R_of(1), level);
  horizons_.flush();
}

void Output::write_end(const std::string& how) {
  series_.print("# end: {}\n", how);
  series_.flush();
}

void Output::write_profiles(double t, const State& u, const Grid& grid, const DerivedProfiles& d,
                            const std::vector<double>& beta_H,
                            const std::vector<std::size_t>& level) {
  // gnuplot's `index` separates blocks by two blank lines.
  if (!first_block_)
    profiles_.print("\n\n");
  first_block_ = false;
  profiles_.print("# t = {}\n", time_text(t));
  const FormulationTraits& f = traits(formulation_);
  fmt::memory_buffer line;
  for (std::size_t k = 0; k < grid.n_interior(); ++k) {
    const std::size_t i = grid.first_interior() + k;
    line.clear();
    append_scientific(line, grid.r()[i]);
    const double beta_GD = field(u, grid, Var::beta)[i];
    for (const auto& entry : f.rows()) {
      double v = field(u, grid, entry.var)[i];
      if (entry.var == Var::beta)
        v = beta_GD + beta_H[i];
      else if (entry.var == Var::K && !f.K_is_adm())
        v = adm_K(f, v, field(u, grid, Var::Theta)[i]); // the ADM K (Z1)
      line.push_back(' ');
      append_scientific(line, v);
    }
    for (double v : {d.H[k], d.M_r[k], d.G_r[k], d.R_areal[k], d.Theta_plus[k], d.m_ms[k], beta_GD,
                     beta_H[i]}) {
      line.push_back(' ');
      append_scientific(line, v);
    }
    fmt::format_to(std::back_inserter(line), " {}\n", level.empty() ? 0 : level[k]);
    profiles_.write(line.data(), line.size());
  }
  profiles_.flush();
}

} // namespace gbssn1d
