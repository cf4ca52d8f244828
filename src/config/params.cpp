#include "config/params.hpp"

#include "config/numbers.hpp"
#include "core/decimal.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace gbssn1d {

bool shrinks_wormhole(const Params& p) {
  return p.id == InitialDataKind::wormhole && p.rahA > 0.0
         && p.rah0 < standard_horizon_radius * p.M;
}

std::vector<double> flux_radii(const Params& p) {
  std::vector<double> radii;
  if (p.flux_R.empty())
    return radii;
  const std::string_view text = p.flux_R;
  for (std::size_t from = 0;;) {
    const std::size_t comma = std::min(text.find(',', from), text.size());
    std::string item(text.substr(from, comma - from));
    item.erase(0, item.find_first_not_of(' '));
    item.erase(item.find_last_not_of(' ') + 1);
    if (item.empty())
      throw ParamError("--flux-R", p.flux_R,
                       "has an empty entry: give areal radii in M separated by commas (5,20)");
    const double R = parse_number<double>("--flux-R", item);
    if (!(R > 0.0))
      throw ParamError("--flux-R", p.flux_R,
                       fmt::format("has {}: each areal radius must be > 0", item));
    if (std::find(radii.begin(), radii.end(), R) != radii.end())
      throw ParamError("--flux-R", p.flux_R,
                       fmt::format("names the sphere {} twice (its columns would repeat)", item));
    radii.push_back(R);
    if (radii.size() > max_flux_spheres)
      throw ParamError("--flux-R", p.flux_R,
                       fmt::format("names more than {} spheres", max_flux_spheres));
    if (comma == text.size())
      return radii;
    from = comma + 1;
  }
}

int levels_rule(double rmax, double M) {
  const double levels = 1.0 + std::floor(std::log2(rmax / (4.0 * M)));
  return std::isfinite(levels) ? static_cast<int>(std::clamp(levels, 2.0, 30.0)) : 2;
}

AhEvery AhEvery::parse(std::string_view text) {
  AhEvery every(SearchEvery::substage);
  // a number of steps is kept as the number: one spelling (05 and 5 are the same run, as 0.25
  // and 0.250 are)
  if (const auto n = parse_decimal<long>(text))
    every.steps_ = *n;
  else
    every.word_ = Word::parse(text);
  return every;
}

double dt_max_of_damping(double rate) {
  return rate > 0.0 ? 1.0 / rate : std::numeric_limits<double>::infinity();
}

double damping_rate(const ResolvedParams& p) {
  const double kappa1 = z4c_on(p) ? p.kappa1() * std::max(2.0, 2.0 + p.kappa2) : 0.0;
  return std::max(p.eta(), kappa1);
}

namespace {

/// Z4c's damping kappa1 when not given: 0.02/M, the field's value (docs/z4c-study.md: larger
/// values, up to 5/M, gave lower H and M_AH errors on trumpet data, but grid-scale noise grows
/// where kappa1 dr > 0.3, and no value made wormhole data's M_AH as good as BSSN's).
double kappa1_rule(const Params& p) {
  return 0.02 / p.M;
}

/// Z4c's damping near the hole when not given: 1/M (docs/z4c-study.md, Sec. 9: with kappa1 =
/// 0.02/M alone the horizon mass drifts 15 times BSSN's; raised to 1/M inside ~6 M, 0.3 times
/// BSSN's and H 0.08; 2/M did as well on long runs, but on coarse boxes the momentum constraint
/// lost order in a convergence test: perhaps the cell-width cap, different in each member).
double kappa1_hole_rule(const Params& p) {
  return 1.0 / p.M;
}

/// The rules' values filled into the flags where config.toml records them.
void fill_rule_values(Params& p) {
  if (p.grid == RadialGrid::boxes && !p.levels)
    p.levels = levels_rule(p.rmax, p.M);
  // M and rmax are validated afterwards: a bad M gives a non-finite eta
  if (!p.eta)
    p.eta = (shrinks_wormhole(p) ? 1.0 : 2.0) / p.M;
  // with Z4c only, so that BSSN's config.toml reads as before Z4c (a checkpoint written then
  // resumes)
  if (z4c_on(p) && !p.kappa1)
    p.kappa1 = kappa1_rule(p);
  if (z4c_on(p) && !p.kappa1_hole)
    p.kappa1_hole = kappa1_hole_rule(p);
  // Sec. 6.6: relaxing the outer half of every box reaching beyond 16 M towards its parent
  // (one box, --levels 1, has no parent: 0) absorbs the wormhole's gauge pulse where the parent
  // cannot carry it; with Z4c's damping too (docs/z4c-study.md, Sec. 2: kappa1 = 0.1 ... 2 and
  // the default with tapers 0.1-0.5 run to 1000 M)
  if (!p.box_taper)
    p.box_taper = p.grid == RadialGrid::boxes && p.levels.value_or(1) > 1 ? 0.5 : 0.0;
  if (!p.norm_rmax)
    p.norm_rmax = std::min(10.0 * p.M, 0.5 * p.rmax);
  if (shift_on(p)) {
    if (!p.rah_rcut)
      p.rah_rcut = 0.5 * p.rmax;
    if (!p.rah_taper)
      p.rah_taper = HorizonShiftParams{}.taper;
    // `auto` is written to config.toml as the profile and width it stands for, so that a
    // checkpoint or a sweep member made when auto meant another width is told apart (not
    // resumed with the new one); M is validated afterwards
    // auto chooses the width as well: a width given with it would be dropped (config.toml
    // would record auto's), so it is refused (the unset width is the table's default, as the
    // refinement flags on a single grid are told from theirs)
    if (p.rah_profile == ShiftProfile::automatic && p.rah_width != Params{}.rah_width)
      throw ParamError("--rah-width", fmt::format("{}", p.rah_width),
                       "not used by --rah-profile auto (the default), which chooses the "
                       "width itself (3 max(rah0, M) to stretch, 1 M to shrink); give "
                       "--rah-profile rational, rational3, gauss or gauss3 with --rah-width");
    if (p.rah_profile == ShiftProfile::automatic && std::isfinite(p.M) && p.M > 0.0) {
      HorizonShiftParams hs;
      hs.profile = ShiftProfile::automatic;
      hs.h = p.rah0;
      resolve_automatic_profile(hs, p.M);
      p.rah_profile =
          hs.profile == ShiftProfile::gauss ? ShiftProfile::gauss : ShiftProfile::rational;
      p.rah_width = hs.width;
    }
  }
}

} // namespace

ResolvedParams resolve(Params p) {
  fill_rule_values(p);
  ResolvedParams r(p);
  r.levels_ = p.levels.value_or(1);
  r.box_taper_ = *p.box_taper;
  r.eta_ = *p.eta;
  r.kappa1_ = p.kappa1.value_or(kappa1_rule(p));
  r.kappa1_hole_ = p.kappa1_hole.value_or(kappa1_hole_rule(p));
  r.norm_rmax_ = *p.norm_rmax;
  r.rah_rcut_ = p.rah_rcut.value_or(std::numeric_limits<double>::infinity());
  r.rah_taper_ = p.rah_taper.value_or(TaperChoice(HorizonShiftParams{}.taper));
  return r;
}

} // namespace gbssn1d
