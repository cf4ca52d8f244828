#include "evolution/observe.hpp"

#include "grid/interpolation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace gbssn1d {

namespace {

/// Samples at radius r are interpolated on the finest level on which r lies this many cells
/// inside the edge: the 6-point stencil (k - 2 ... k + 3) then reads interior cells only.
constexpr double sample_margin_cells = 4.0;

/// Diagnostic copies: they never search (their h_AH is set from the evolution's).
std::vector<GbssnRhs> diagnostic_copies(const EvolutionConfig& config,
                                        const mesh::MeshLayout& layout) {
  std::vector<GbssnRhs> rhs;
  for (std::size_t l = 0; l < layout.levels(); ++l)
    rhs.emplace_back(layout.grid(l), config.rhs);
  return rhs;
}

} // namespace

std::vector<DerivedProfiles> level_profiles(const mesh::MeshLayout& layout,
                                            const std::vector<State>& levels) {
  std::vector<DerivedProfiles> d;
  for (std::size_t l = 0; l < layout.levels(); ++l)
    d.push_back(derived_profiles(levels[l], layout.grid(l)));
  return d;
}

DerivedProfiles composite_profiles(const mesh::MeshLayout& layout, const mesh::Composite& composite,
                                   const std::vector<DerivedProfiles>& levels) {
  if (layout.levels() == 1)
    return levels.front();
  auto gather = [&](std::vector<double> DerivedProfiles::*member) {
    std::vector<std::span<const double>> arrays;
    for (const auto& d : levels)
      arrays.emplace_back(d.*member);
    return composite.gather_interior(arrays);
  };
  DerivedProfiles c;
  c.H = gather(&DerivedProfiles::H);
  c.M_r = gather(&DerivedProfiles::M_r);
  c.G_r = gather(&DerivedProfiles::G_r);
  c.R_areal = gather(&DerivedProfiles::R_areal);
  c.Theta_plus = gather(&DerivedProfiles::Theta_plus);
  c.m_ms = gather(&DerivedProfiles::m_ms);
  if (!levels.front().Theta.empty())
    c.Theta = gather(&DerivedProfiles::Theta);
  if (!levels.front().flux.empty())
    c.flux = gather(&DerivedProfiles::flux);
  return c;
}

double value_at_radius(const mesh::MeshLayout& layout, const std::vector<State>& levels, Var v,
                       double r) {
  const std::size_t l = layout.finest_level_covering(r, sample_margin_cells);
  const Grid& g = layout.grid(l);
  const double value = interpolate_at_radius(g, field(levels[l], g, v), r);
  // K is the ADM K (Z1), as in profiles.dat
  const FormulationTraits& f = traits(levels[l].formulation());
  if (v == Var::K && !f.K_is_adm())
    return adm_K(f, value, interpolate_at_radius(g, field(levels[l], g, Var::Theta), r));
  return value;
}

double H_at_radius(const mesh::MeshLayout& layout, const std::vector<DerivedProfiles>& levels,
                   double r) {
  const std::size_t l = layout.finest_level_covering(r, sample_margin_cells);
  const Grid& g = layout.grid(l);
  // the interior values with their nearest neighbours continued into the ghosts
  std::vector<double> f(g.n_total());
  const auto& H = levels.at(l).H;
  for (std::size_t i = 0; i < g.n_total(); ++i) {
    const std::size_t k = std::clamp(i, g.first_interior(), g.end_interior() - 1);
    f[i] = H[k - g.first_interior()];
  }
  return interpolate_at_radius(g, f, r);
}

namespace {

/// An odd profile's interior values on `g` with every ghost: the origin's by parity
/// (f(-r) = -f(r)), the outer ones continued from the last point (never read: the stencils of
/// sphere_at_areal_radius end at the last interior point).
std::vector<double> with_odd_ghosts(const Grid& g, std::span<const double> interior) {
  std::vector<double> f(g.n_total());
  for (std::size_t i = 0; i < g.n_total(); ++i)
    f[i] = i < g.first_interior() ? -interior[Grid::mirror(i) - g.first_interior()]
           : i < g.end_interior() ? interior[i - g.first_interior()]
                                  : interior.back();
  return f;
}

} // namespace

SphereSample sphere_at_areal_radius(const mesh::MeshLayout& layout,
                                    const std::vector<State>& levels, const DerivedProfiles& d,
                                    const Grid& composite, double R,
                                    std::vector<std::optional<DerivedProfiles>>& computed) {
  if (d.flux.empty())
    throw std::invalid_argument("sphere_at_areal_radius: the profiles of a state without matter");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::span<const double> R_c = d.R_areal;
  const std::size_t n = R_c.size();
  if (n < 2 || !(R <= R_c[n - 1]))
    return {nan, nan, nan}; // beyond the outer boundary's areal radius
  // the outermost point at or below R, walking in on the outer sheet
  const std::size_t sheet = outer_sheet_begin(R_c);
  std::size_t k = n - 1;
  while (k > sheet && R_c[k] > R)
    --k;
  if (R_c[k] > R)
    return {nan, nan, nan}; // below the throat's or the innermost point's
  const double r_hi = composite.r()[composite.first_interior() + std::min(k + 1, n - 1)];
  // on the finest level that covers the bracket: its own values, interpolated at the 6th order
  const std::size_t l = layout.finest_level_covering(r_hi, sample_margin_cells);
  const Grid& g = layout.grid(l);
  computed.resize(layout.levels());
  if (layout.levels() > 1 && !computed[l])
    computed[l] = derived_profiles(levels[l], g);
  const DerivedProfiles& dl = layout.levels() > 1 ? *computed[l] : d;
  const std::vector<double> R_l = with_odd_ghosts(g, dl.R_areal);
  std::size_t j =
      static_cast<std::size_t>(std::upper_bound(g.r().begin(), g.r().end(), r_hi) - g.r().begin());
  j = std::min(j + 1, g.end_interior() - 1);
  const std::size_t top = j;
  while (j > g.first_interior() && R_l[j] > R)
    --j;
  if (j == top || R_l[j] > R)
    return {nan, nan, nan}; // the level's values do not bracket R where the composite's do
  // the stencil around [j, j + 1], kept off the outer ghosts (a fine box's are beyond
  // sample_margin_cells; the outermost level's, near rmax, are made one-sided)
  const std::size_t k0 = std::min(lagrange6_start(j, g.n_total()), g.end_interior() - 6);
  const Lagrange6Newton R_of_x(g.x(), R_l, k0);
  double x_lo = g.x()[j], x_hi = g.x()[j + 1]; // R_of_x(x_lo) <= R < R_of_x(x_hi)
  for (int it = 0; it < 100 && x_hi - x_lo > 1e-15 * std::max(1.0, std::abs(x_hi)); ++it) {
    const double x = 0.5 * (x_lo + x_hi);
    (R_of_x(x) <= R ? x_lo : x_hi) = x;
  }
  const double x = 0.5 * (x_lo + x_hi);
  const std::vector<double> m_l = with_odd_ghosts(g, dl.m_ms), F_l = with_odd_ghosts(g, dl.flux);
  return {g.map().r(x), Lagrange6Newton(g.x(), m_l, k0)(x), Lagrange6Newton(g.x(), F_l, k0)(x)};
}

std::vector<EmptyNormWindow> empty_norm_windows(const Grid& g, std::span<const double> R_areal,
                                                const NormWindows& w) {
  std::vector<EmptyNormWindow> empty;
  const std::vector<double> ones(g.n_interior(), 1.0);
  if (std::isnan(l2_norm(ones, g, w.rmin, w.rmax)))
    empty.push_back({"--norm-rmin/--norm-rmax",
                     fmt::format("the coordinate window {} <= r <= {} holds no grid point, so "
                                 "that H_L2_ext, M_L2_ext, G_L2_ext and dtalpha_max_ext are NaN",
                                 w.rmin, w.rmax)});
  if (std::isnan(l2_norm_areal(ones, R_areal, w.Rmin, w.Rmax))) {
    const auto [lo, hi] = std::minmax_element(R_areal.begin(), R_areal.end());
    empty.push_back(
        {"--norm-Rmin/--norm-Rmax",
         fmt::format("the areal window {} <= R <= {} holds no point of the initial data (whose "
                     "areal radius spans {:.4g} ... {:.4g} on the grid), so that H_L2_R and M_L2_R "
                     "are NaN",
                     w.Rmin, w.Rmax, R_areal.empty() ? 0.0 : *lo, R_areal.empty() ? 0.0 : *hi)});
  }
  return empty;
}

std::vector<EmptyNormWindow> absent_spheres(std::span<const double> R_areal,
                                            std::span<const double> spheres, double M) {
  std::vector<EmptyNormWindow> absent;
  if (R_areal.empty())
    return absent;
  const double lo = R_areal[outer_sheet_begin(R_areal)], hi = R_areal.back();
  for (const double X : spheres)
    if (!(X * M >= lo && X * M <= hi))
      absent.push_back(
          {"--flux-R", fmt::format("no sphere of areal radius {} M lies on the initial data's grid "
                                   "(its outer sheet spans R = {:.4g} ... {:.4g} M), so that m_R{} "
                                   "and flux_R{} are NaN until one does",
                                   X, lo / M, hi / M, X, X)});
  return absent;
}

HorizonSearch find_all_horizons(const mesh::MeshLayout& layout, const std::vector<State>& levels,
                                const HorizonFinderParams& finder, double t) {
  auto with_time = [t](auto search) {
    try {
      return search();
    } catch (const HorizonFinderError& e) {
      throw HorizonFinderError(fmt::format("{} (t = {:.6g})", e.what(), t));
    }
  };
  if (layout.levels() == 1)
    return with_time([&] { return find_horizons(levels[0], layout.grid(0), finder); });
  // each level searches the part of the composite it supplies: r beyond its child's extent
  HorizonSearch all;
  for (std::size_t l = 0; l < layout.levels(); ++l) {
    HorizonFinderParams p = finder;
    if (l + 1 < layout.levels())
      p.r_min = std::max(p.r_min, layout.extent(l + 1));
    HorizonSearch found = with_time([&] { return find_horizons(levels[l], layout.grid(l), p); });
    for (auto& s : found.surfaces) {
      s.level = l;
      all.surfaces.push_back(s);
    }
  }
  std::sort(all.surfaces.begin(), all.surfaces.end(),
            [](const MarginalSurface& a, const MarginalSurface& b) { return a.r > b.r; });
  return all;
}

SeriesDiagnostics::SeriesDiagnostics(const EvolutionConfig& config, const mesh::MeshLayout& layout)
    : config_(config), layout_(layout), rhs_(diagnostic_copies(config, layout)),
      dudt_(layout.levels()) {}

SeriesRow SeriesDiagnostics::row(const std::vector<State>& levels, double t,
                                 const DerivedProfiles& d, const HorizonSearch& found,
                                 const std::optional<double>& h_AH,
                                 const mesh::Composite& composite) {
  const Grid& g = composite.grid();
  const std::size_t finest = layout_.levels() - 1;
  const double inf = std::numeric_limits<double>::infinity();
  SeriesRow row;
  row.t = t;
  row.alpha_center =
      central_value(field(levels[finest], layout_.grid(finest), Var::alpha), layout_.grid(finest));
  row.H_L2 = l2_norm(d.H, g, 0.0, inf);
  const NormWindows& w = config_.norms;
  row.H_L2_ext = l2_norm(d.H, g, w.rmin, w.rmax);
  row.M_L2 = l2_norm(d.M_r, g, 0.0, inf);
  row.M_L2_ext = l2_norm(d.M_r, g, w.rmin, w.rmax);
  row.G_L2 = l2_norm(d.G_r, g, 0.0, inf);
  row.G_L2_ext = l2_norm(d.G_r, g, w.rmin, w.rmax);
  row.H_L2_R = l2_norm_areal(d.H, d.R_areal, w.Rmin, w.Rmax);
  row.M_L2_R = l2_norm_areal(d.M_r, d.R_areal, w.Rmin, w.Rmax);
  row.H_L2_int = l2_norm_interior(d.H, d.R_areal, g, w.Rint);
  // Z4c's own (Sec. 17): G^r and Theta in the areal window, Theta in the coordinate one
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool z4c = !d.Theta.empty();
  row.G_L2_R = z4c ? l2_norm_areal(d.G_r, d.R_areal, w.Rmin, w.Rmax) : nan;
  row.Theta_L2_ext = z4c ? l2_norm(d.Theta, g, w.rmin, w.rmax) : nan;
  row.Theta_L2_R = z4c ? l2_norm_areal(d.Theta, d.R_areal, w.Rmin, w.Rmax) : nan;
  // the scalar field's own (Sec. 19): Phi and Pi at the centre, as alpha_center
  const State& centre = levels[finest];
  const Grid& centre_grid = layout_.grid(finest);
  const bool scalar = centre.fields().holds(Var::Phi);
  row.Phi_center = scalar ? central_value(field(centre, centre_grid, Var::Phi), centre_grid) : nan;
  row.Pi_center = scalar ? central_value(field(centre, centre_grid, Var::Pi), centre_grid) : nan;
  std::vector<std::optional<DerivedProfiles>> computed;
  for (const double R : config_.spheres) {
    const SphereSample s =
        sphere_at_areal_radius(layout_, levels, d, g, R * config_.initial_data.M, computed);
    row.sphere_m.push_back(s.m);
    row.sphere_flux.push_back(s.flux);
  }
  // d_t alpha on every level with the h_AH the evolution would use now
  std::vector<std::span<const double>> dt_alpha_levels;
  for (std::size_t l = 0; l < layout_.levels(); ++l) {
    rhs_[l].set_horizon_radius(h_AH);
    rhs_[l](levels[l], dudt_[l], t);
    dt_alpha_levels.push_back(field(std::as_const(dudt_[l]), layout_.grid(l), Var::alpha));
  }
  const std::vector<double> dt_alpha = composite.gather(dt_alpha_levels);
  const auto horizon = found.horizon();
  row.r_ah = horizon ? horizon->r : std::numeric_limits<double>::quiet_NaN();
  row.M_ah = horizon ? horizon->mass : std::numeric_limits<double>::quiet_NaN();
  row.M_ah_err = row.M_ah - config_.initial_data.M;
  // (NaN, as the norms, when the window holds no point: no value, not a vanishing one)
  row.dtalpha_max_ext = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = g.first_interior(); i < g.end_interior(); ++i)
    if (g.r()[i] >= config_.norms.rmin && g.r()[i] <= config_.norms.rmax)
      row.dtalpha_max_ext = std::isnan(row.dtalpha_max_ext)
                                ? std::abs(dt_alpha[i])
                                : std::max(row.dtalpha_max_ext, std::abs(dt_alpha[i]));
  return row;
}

NonFiniteError::NonFiniteError(double t_, double r_, const std::string& var_)
    : std::runtime_error(fmt::format(
        "the evolution became non-finite at t = {:.6g}, r = {:.6g} in {}", t_, r_, var_)),
      t(t_), r(r_), var(var_) {}

NonFiniteError::NonFiniteError(double t_, double r_, const std::string& var_, double value,
                               const std::string& why)
    : std::runtime_error(fmt::format("the evolution left the physical range at t = {:.6g}, "
                                     "r = {:.6g}: {} = {:.6g} ({})",
                                     t_, r_, var_, value, why)),
      t(t_), r(r_), var(var_) {}

namespace {

/// Whether every value of level `u` is finite and chi > 0, alpha_min <= alpha <= alpha_max on
/// the interior: branch-free reductions that vectorise (the check runs after every step of the
/// hierarchy); check_physical_range then searches a failing level point by point for its
/// report.
bool in_physical_range(const State& u, const Grid& g, double alpha_min, double alpha_max) {
  // a count of the values outside (an integer sum vectorises; a bool reduction did not)
  std::size_t outside = 0;
  constexpr double largest = std::numeric_limits<double>::max();
  for (const auto& entry : u.vars()) {
    const double* const f = field(u, g, entry.var).data();
    for (std::size_t i = g.first_interior(); i < g.n_total(); ++i)
      outside += std::abs(f[i]) <= largest ? 0 : 1; // inf and NaN
  }
  const double* const chi = field(u, g, Var::chi).data();
  const double* const alpha = field(u, g, Var::alpha).data();
  for (std::size_t i = g.first_interior(); i < g.end_interior(); ++i) // & rather than &&: no branch
    outside += (chi[i] > 0.0) & (alpha[i] >= alpha_min) & (alpha[i] <= alpha_max) ? 0 : 1;
  return outside == 0;
}

} // namespace

void check_physical_range(const mesh::MeshLayout& layout, const std::vector<State>& levels,
                          double t, double alpha_min, double alpha_max) {
  // the finest box first: a coarse cell under a finer box holds that box's restriction, so the
  // finest box with a bad value names where it arose (a blow-up at a box's outer boundary was
  // reported at the first cell of box 0, which holds its restriction)
  for (std::size_t l = layout.levels(); l-- > 0;) {
    const Grid& g = layout.grid(l);
    const State& u = levels[l];
    if (in_physical_range(u, g, alpha_min, alpha_max))
      continue;
    const std::string where = layout.levels() > 1 ? fmt::format(" (box {})", l) : "";
    for (std::size_t i = g.first_interior(); i < g.n_total(); ++i)
      for (const auto& entry : u.vars())
        if (!std::isfinite(field(u, g, entry.var)[i]))
          throw NonFiniteError(t, g.r()[i], std::string(entry.name) + where);
    const auto chi = field(u, g, Var::chi), alpha = field(u, g, Var::alpha);
    for (std::size_t i = g.first_interior(); i < g.end_interior(); ++i) {
      if (!(chi[i] > 0.0))
        throw NonFiniteError(t, g.r()[i], "chi" + where, chi[i], "must be > 0; see --chi-floor");
      if (alpha[i] < alpha_min || alpha[i] > alpha_max)
        throw NonFiniteError(t, g.r()[i], "alpha" + where, alpha[i],
                             fmt::format("must lie in [{}, {}]", alpha_min, alpha_max));
    }
  }
}

} // namespace gbssn1d
