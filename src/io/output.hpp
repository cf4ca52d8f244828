// ASCII output: timeseries.dat and profiles.dat, each opening with '#' lines that record the
// program version and every parameter, the last '#' line naming the columns. Values are
// written at full precision and flushed after every row/block, so a run that stops early
// leaves complete, parseable files.
#pragma once

#include "diagnostics/constraints.hpp"
#include "gbssn/state.hpp"
#include "grid/grid.hpp"
#include "horizon/apparent_horizon.hpp"
#include "io/data_file.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gbssn1d {

/// One row of timeseries.dat.
struct SeriesRow {
  double t, alpha_center, H_L2, H_L2_ext, M_L2, M_L2_ext, G_L2, G_L2_ext;
  double dtalpha_max_ext; ///< max |d_t alpha| over the exterior region (settling)
  double r_ah, M_ah;      ///< apparent horizon (NaN when none is found)
  double H_L2_R, M_L2_R;  ///< over the areal-radius window [norm-Rmin, norm-Rmax] M
  double H_L2_int;        ///< near the puncture, R <= norm-Rint M
  double M_ah_err;        ///< M_ah - M
  /// Z4c's own (Sec. 17): G^r in the areal window, Theta in the exterior and areal windows
  double G_L2_R, Theta_L2_ext, Theta_L2_R;
  /// the scalar field's own (Sec. 19): Phi and Pi at the centre
  double Phi_center, Pi_center;
  /// per sphere of the run's --flux-R, in its order: the Misner-Sharp mass inside it and the
  /// energy flux through it (SphereSample)
  std::vector<double> sphere_m, sphere_flux;

  /// The value of one of a formulation's or matter model's own columns
  /// (FormulationTraits::extra_series, MatterTraits::extra_series), by name; throws
  /// std::invalid_argument for a name that is none of them.
  double extra(std::string_view column) const;
};

/// Column names, in order: a Z4c run's series has G_L2_R, Theta_L2_ext and Theta_L2_R besides,
/// its profiles Theta (and K is the ADM K = K-hat + 2 Theta in both); the scalar field's series
/// has Phi_center and Pi_center after those, its profiles Phi and Pi; then, per areal radius X
/// (in units of M) of `spheres`, m_R<X> and flux_R<X>.
std::vector<std::string> series_columns(Fields fields, std::span<const double> spheres = {});
std::vector<std::string> profile_columns(Fields fields);
std::vector<std::string> horizon_columns();

/// Where each output file stood at a checkpoint (bytes), its header's length, and the FNV-1a
/// hash of its rows (the bytes between the two) when `hashed` (checkpoints of format 4).
struct OutputMarks {
  std::uint64_t series = 0, profiles = 0, horizons = 0;
  std::uint64_t series_header = 0, profiles_header = 0, horizons_header = 0;
  std::uint64_t series_hash = 0, profiles_hash = 0, horizons_hash = 0;
  bool hashed = false;
};

class Output {
public:
  /// Opens (truncates) the files in `dir`; `parameter_header` is the effective configuration,
  /// one "key = value" per line; `formulation` the run's (its columns).
  /// `spheres`: the areal radii (in units of M) of the series' sphere columns, the run's
  /// EvolutionConfig::spheres (empty: none), which every row must carry.
  Output(const std::filesystem::path& dir, const std::string& parameter_header, Fields fields,
         std::vector<double> spheres);
  /// A resumed run: the files of `dir` cut back to `marks`, with the new header.
  Output(const std::filesystem::path& dir, const std::string& parameter_header, Fields fields,
         std::vector<double> spheres, const OutputMarks& marks);

  /// Throws OutputError unless every file of `dir` is there, at least as long as its mark, and
  /// (marks.hashed) its rows up to the mark are the bytes the run wrote: what the resuming
  /// constructor keeps. Touches nothing. Call before changing any file.
  static void check_resumable(const std::filesystem::path& dir, const OutputMarks& marks);

  const std::filesystem::path& dir() const { return dir_; }
  /// The current marks (flushes).
  OutputMarks marks();

  void write_series(const SeriesRow& row);
  /// `beta_H` is the horizon-adjusting shift on every point (the column `beta` is the full
  /// shift beta_GD + beta_H, `beta_GD` the evolved part); `level` the refinement level of each
  /// interior point (the column `level`; empty: 0, a single grid).
  void write_profiles(double t, const State& u, const Grid& grid, const DerivedProfiles& d,
                      const std::vector<double>& beta_H,
                      const std::vector<std::size_t>& level = {});
  void write_horizons(double t, const HorizonSearch& search);
  /// The last line of timeseries.dat: "# end: <how the run ended>" (completed, interrupted,
  /// stopped), so that a reader can tell a complete file from one cut short.
  void write_end(const std::string& how);

private:
  std::filesystem::path dir_;
  Fields fields_;
  std::vector<double> spheres_;
  DataFile series_;
  DataFile profiles_;
  DataFile horizons_;
  bool first_block_ = true;
};

} // namespace gbssn1d
