#include "config/params.hpp"

#include "config/flag_table.hpp"
#include "config/param_rules.hpp"
#include "core/text.hpp"
#include "evolution/levels.hpp"
#include "io/horizon_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gbssn1d {

namespace {

/// --rah-variant's part that changes the equations (the schedules discretise them as specified).
HorizonShiftParams::Variant equations_variant(ShiftVariant v) {
  using V = HorizonShiftParams::Variant;
  switch (v) {
  case ShiftVariant::no_shift_derivatives:
    return V::no_shift_derivatives;
  case ShiftVariant::no_shift_second_derivatives:
    return V::no_shift_second_derivatives;
  case ShiftVariant::delta_rhs_from_gd:
    return V::delta_rhs_from_gd;
  case ShiftVariant::driver_full_shift:
    return V::driver_full_shift;
  case ShiftVariant::consistent:
  case ShiftVariant::midstep_update:
  case ShiftVariant::box_substage:
    break;
  }
  return V::consistent;
}

/// --rah-variant's part that changes when h_AH is searched.
HorizonSearchSettings::Schedule search_schedule(ShiftVariant v) {
  using S = HorizonSearchSettings::Schedule;
  return v == ShiftVariant::midstep_update ? S::midstep_update
         : v == ShiftVariant::box_substage ? S::box_substage
                                           : S::standard;
}

/// The right-hand side's parameters, but those whose flag rows name their field (copy_into()).
RhsParams rhs_params(const ResolvedParams& p) {
  RhsParams r;
  // the Eulerian volume choice is a formulation of its own (gbssn/bssn_eulerian.hpp)
  r.formulation = p.formulation == Formulation::bssn && p.gbssn_volume == Volume::eulerian
                      ? Formulation::bssn_eulerian
                      : p.formulation.value();
  r.matter = p.matter.value();
  r.z4c.kappa1 = p.kappa1();
  r.z4c.kappa1_hole = p.kappa1_hole();
  r.z4c.hole_radius = Z4cParams{}.hole_radius * p.M;
  r.gauge.shift.eta = p.eta();
  if (p.shift == ShiftCondition::zero)
    r.gauge.shift.xi = 0.0; // (G2): d_t beta = 0, and beta = 0 in the data (validate())
  r.gauge.slicing.advective = !p.non_advective_lapse;
  r.horizon_shift.h = p.rah0;
  r.horizon_shift.width = p.rah_width;
  r.horizon_shift.r_cut = p.rah_rcut();
  r.horizon_shift.taper = p.rah_taper().value();
  r.horizon_shift.profile = p.rah_profile.value();
  r.horizon_shift.normal = p.rah_normal.value();
  resolve_automatic_profile(r.horizon_shift, p.M);
  r.advection.driver = p.driver_advection.value();
  r.advection.delta = p.delta_advection.value();
  r.upwind = p.upwind.value();
  r.horizon_shift.variant = equations_variant(p.rah_variant.value());
  return r;
}

} // namespace

EvolutionConfig mesh_config(const ResolvedParams& p) {
  EvolutionConfig c;
  c.grid = grid_spec(p);
  if (p.grid == RadialGrid::boxes) {
    c.refinement.levels = static_cast<std::size_t>(p.levels());
    c.stepping.time = p.time_interp.value();
    c.stepping.subcycling = !p.no_subcycling;
    c.stepping.taper_cells = static_cast<std::size_t>(std::lround(p.box_taper() * p.N));
    c.stepping.taper_min_extent = p.box_taper_from * p.M;
    c.stepping.dt_max = dt_max_of_damping(damping_rate(p));
  }
  c.stepping.cfl = p.cfl;
  return c;
}

GridSpec grid_spec(const Params& p) {
  GridSpec spec;
  // boxes: uniform levels
  spec.kind = p.grid == RadialGrid::sinh ? GridKind::sinh : GridKind::uniform;
  spec.N = static_cast<std::size_t>(p.N);
  spec.rmax = p.rmax;
  spec.dr_inner = p.dr_inner;
  spec.fd_order = p.fd_order;
  return spec;
}

EvolutionConfig evolution_config(const ResolvedParams& p) {
  EvolutionConfig c = mesh_config(p);
  c.initial_data = initial_data_params(p);
  c.rhs = rhs_params(p);
  c.norms.rmax = p.norm_rmax();
  c.norms.Rmin = p.norm_Rmin * p.M; // the areal windows are given in units of M
  c.norms.Rmax = p.norm_Rmax * p.M;
  c.norms.Rint = p.norm_Rint * p.M;
  if (scalar_on(p))
    c.spheres = flux_radii(p); // in units of M, as the columns are named
  c.horizon_search.every_steps = ah_every_steps(p);
  c.horizon_search.extrapolate = p.ah_every == SearchEvery::extrapolated;
  c.horizon_search.interval = p.ah_interval.value_or(0.0);
  c.horizon_search.schedule = search_schedule(p.rah_variant.value());
  c.horizon_search.t_max = p.ah_tmax.value_or(std::numeric_limits<double>::infinity());
  if (uses_hAH_file(p))
    c.horizon_search.prescribed = load_prescribed_horizon(p.rah_hAH_file, p.tmax);
  copy_into(p, c); // the flags whose rows name their field (config/flag_table.hpp)
  return c;
}

InitialDataParams initial_data_params(const Params& p) {
  InitialDataParams id;
  id.M = p.M;
  id.kind = p.id.value();
  id.lapse0 = p.lapse0.value();
  id.scalar = {p.scalar_amp, p.scalar_r0, p.scalar_width};
  return id;
}

std::function<double(double)> load_prescribed_horizon(const std::string& path, double t_end) {
  try {
    return read_horizon_history(path, t_end);
  } catch (const HorizonFileError& e) {
    throw ParamError("--rah-hAH-file", printable(path), e.what());
  }
}

long ah_every_steps(const Params& p) {
  if (p.ah_every == SearchEvery::substage || p.ah_every == SearchEvery::extrapolated)
    return 0;
  if (p.ah_every == SearchEvery::step)
    return 1;
  return p.ah_every.steps().value(); // validated
}

} // namespace gbssn1d
