#include "io/output.hpp"

#include "core/registry.hpp"

#include <fmt/format.h>

#include <fstream>
#include <limits>
#include <span>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace gbssn1d {

double SeriesRow::extra(std::string_view column) const {
  for (const auto& [name, value] : {std::pair<std::string_view, double>{"G_L2_R", G_L2_R},
                                    {"Theta_L2_ext", Theta_L2_ext},
                                    {"Theta_L2_R", Theta_L2_R},
                                    {"Phi_center", Phi_center},
                                    {"Pi_center", Pi_center}})
    if (name == column)
      return value;
  throw std::invalid_argument("no series column " + std::string(column));
}

std::vector<std::string> series_columns(Fields fields, std::span<const double> spheres) {
  std::vector<std::string> cols{
      "t",        "alpha_center", "H_L2",     "H_L2_ext",        "M_L2",
      "M_L2_ext", "G_L2",         "G_L2_ext", "dtalpha_max_ext", "r_ah",
      "M_ah",     "H_L2_R",       "M_L2_R",   "H_L2_int",        "M_ah_err"};
  for (const std::string_view name : traits(fields.formulation).extra_series)
    cols.emplace_back(name);
  for (const std::string_view name : traits(fields.matter).extra_series)
    cols.emplace_back(name);
  for (const double R : spheres) {
    cols.push_back(fmt::format("m_R{}", R));
    cols.push_back(fmt::format("flux_R{}", R));
  }
  return cols;
}

std::vector<std::string> profile_columns(Fields fields) {
  std::vector<std::string> cols{"r"};
  for (const auto& entry : fields.rows())
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

const char* const series_legend =
    "timeseries.dat: *_L2 norms over the whole grid, *_L2_ext over the fixed coordinate region "
    "norm-rmin <= r <= norm-rmax (the same rule before and after a horizon forms), weighted by "
    "cell width; *_L2_R over the areal-radius window norm-Rmin M <= R <= norm-Rmax M (the same "
    "place in every gauge), weighted by areal width |dR|; H_L2_int from the puncture out to "
    "R = norm-Rint M, weighted by cell width; a norm (and dtalpha_max_ext) is NaN while its "
    "window holds no point; r_ah, M_ah: apparent horizon (NaN if none), M_ah_err = M_ah - M\n";
const char* const sphere_legend =
    "m_R<X>, flux_R<X>: on the outermost sphere of areal radius R = X M, the Misner-Sharp mass "
    "inside it and the energy leaving it per unit coordinate time, -dm/dt at fixed R (its "
    "integral over t from t0 to t1 is m_R<X>(t0) - m_R<X>(t1)); NaN while no sphere of that R "
    "lies on the grid's outer sheet\n";
std::string legend(Fields fields, std::span<const double> spheres) {
  return std::string(series_legend) + std::string(traits(fields.formulation).series_legend)
         + std::string(traits(fields.matter).series_legend)
         + (spheres.empty() ? std::string() : std::string(sphere_legend));
}
const char* const horizon_legend =
    "horizon.dat: r_ah, R_ah, M_ah = R_ah/2 of the apparent horizon (outermost zero of Theta_+ "
    "with Theta_+ < 0 inside; NaN if none); n_roots counts every zero of Theta_+; r_root2/3, "
    "R_root2/3 are the next zeros inwards (NaN if none); level: the box the horizon was found "
    "on (0 on a single grid, -1 without a horizon)\n";

} // namespace

Output::Output(const std::filesystem::path& dir, const std::string& parameter_header, Fields fields,
               std::vector<double> spheres)
    : dir_(dir), fields_(fields), spheres_(std::move(spheres)),
      series_(dir / "timeseries.dat", parameter_header + legend(fields, spheres_),
              series_columns(fields, spheres_)),
      profiles_(dir / "profiles.dat", parameter_header, profile_columns(fields)),
      horizons_(dir / "horizon.dat", parameter_header + horizon_legend, horizon_columns()) {}

Output::Output(const std::filesystem::path& dir, const std::string& parameter_header, Fields fields,
               std::vector<double> spheres, const OutputMarks& m)
    : dir_(dir), fields_(fields), spheres_(std::move(spheres)),
      series_(dir / "timeseries.dat", parameter_header + legend(fields, spheres_),
              series_columns(fields, spheres_), m.series_header, m.series),
      profiles_(dir / "profiles.dat", parameter_header, profile_columns(fields), m.profiles_header,
                m.profiles),
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
  for (const auto& own :
       {traits(fields_.formulation).extra_series, traits(fields_.matter).extra_series})
    for (const std::string_view column : own) {
      line.push_back(' ');
      append_scientific(line, row.extra(column));
    }
  if (row.sphere_m.size() != spheres_.size() || row.sphere_flux.size() != spheres_.size())
    throw std::logic_error(fmt::format("a series row with {} spheres for a file of {}",
                                       row.sphere_m.size(), spheres_.size()));
  for (std::size_t k = 0; k < spheres_.size(); ++k)
    for (const double v : {row.sphere_m[k], row.sphere_flux[k]}) {
      line.push_back(' ');
      append_scientific(line, v);
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
  const FormulationTraits& f = traits(fields_.formulation);
  fmt::memory_buffer line;
  for (std::size_t k = 0; k < grid.n_interior(); ++k) {
    const std::size_t i = grid.first_interior() + k;
    line.clear();
    append_scientific(line, grid.r()[i]);
    const double beta_GD = field(u, grid, Var::beta)[i];
    for (const auto& entry : fields_.rows()) {
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
