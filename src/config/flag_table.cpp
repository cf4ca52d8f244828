#include "config/flag_table.hpp"

#include "config/config_file.hpp"
#include "config/param_rules.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <type_traits>

namespace gbssn1d {

namespace {

/// B's driver stencil as it differences without beta_H: centred, or one upwind stencil
/// (upwind-gd and upwind-full agree when beta_GD is the whole shift; matched is the
/// --delta-advection stencil of Delta^r's own term).
AdvectionStencil upwind_or_centred(AdvectionStencil driver, const Params& p) {
  const AdvectionStencil s =
      driver == AdvectionStencil::matched ? p.delta_advection.value() : driver;
  return s == AdvectionStencil::centred ? AdvectionStencil::centred : AdvectionStencil::upwind_full;
}

} // namespace

/// Whether a flag that acts `where` acts in `p`.
bool acts(Acts where, const ResolvedParams& p) {
  switch (where) {
  case Acts::always:
    return true;
  case Acts::with_shift:
    return shift_on(p);
  case Acts::with_smooth_normal:
    return shift_on(p) && p.rah_normal == ShiftNormal::smooth;
  case Acts::on_boxes:
    return p.grid == RadialGrid::boxes;
  case Acts::with_box_taper:
    return p.grid == RadialGrid::boxes && p.box_taper() > 0.0;
  case Acts::on_sinh:
    return p.grid == RadialGrid::sinh;
  case Acts::with_wormhole:
    return p.id == InitialDataKind::wormhole;
  case Acts::with_z4c:
    return z4c_on(p);
  case Acts::with_scalar:
    return scalar_on(p);
  case Acts::with_z4c_damping:
    return damped_z4c(p);
  case Acts::with_searches:
    return shift_on(p) && !uses_hAH_file(p);
  case Acts::with_tapered_boxes:
    return p.grid == RadialGrid::boxes && p.levels() > 1 && 0.5 * p.rmax > p.box_taper_from * p.M;
  case Acts::with_delta_stencil:
    return shift_on(p) || p.delta_advection.value() == AdvectionStencil::centred;
  case Acts::with_driver_stencil:
    return shift_on(p)
           || upwind_or_centred(p.driver_advection.value(), p)
                  != upwind_or_centred(AdvectionStencil::matched, p);
  }
  return true;
}

/// Why a flag that acts `where` does nothing in `p` (acts(where, p) is false), as a user reads
/// it ("with --rahA 0"), and what to do instead.
std::pair<std::string, std::string> idle_because(Acts where, const ResolvedParams& p) {
  const std::string shift_off =
      "the horizon-adjusting shift is off (give --rahA A, e.g. 0.5, to move the horizon)";
  switch (where) {
  case Acts::with_shift:
    return {"with --rahA 0", shift_off};
  case Acts::with_searches:
    if (!shift_on(p))
      return {"with --rahA 0", shift_off};
    return {"with --rah-hAH-file",
            "h_AH(t) comes from the file, and no horizon search steers the shift (leave the "
            "file out for searches)"};
  case Acts::with_smooth_normal:
    if (!shift_on(p))
      return {"with --rahA 0", shift_off};
    return {"with --rah-normal " + p.rah_normal.name(), "chi_s enters only --rah-normal smooth"};
  case Acts::with_box_taper:
    if (p.grid == RadialGrid::boxes)
      return {"with --box-taper 0", "no box is tapered (give --box-taper F, 0 < F <= 0.5)"};
    [[fallthrough]];
  case Acts::on_boxes:
  case Acts::on_sinh:
    return {"with --grid " + p.grid.name(),
            "only the sinh grid has an innermost width to set, and only boxes have boxes"};
  case Acts::with_wormhole:
    return {"with --id " + p.id.name(), "the trumpets' data fix their own lapse"};
  case Acts::with_scalar:
    return {"with --matter " + p.matter.name(),
            "it sets the scalar field's pulse or its diagnostics (give --matter scalar)"};
  case Acts::with_z4c_damping:
    if (z4c_on(p))
      return {"with --kappa1 0 --kappa1-hole 0",
              "kappa2 only ever multiplies kappa1 in Z4c's damping terms (give --kappa1 > 0)"};
    [[fallthrough]];
  case Acts::with_z4c:
    return {"with --formulation " + p.formulation.name(),
            "BSSN has no constraint damping (give --formulation z4c)"};
  case Acts::with_tapered_boxes:
    if (p.grid == RadialGrid::boxes)
      return {fmt::format("with no fine box beyond --box-taper-from {} (the largest reaches {} M)",
                          p.box_taper_from, 0.5 * p.rmax / p.M),
              "a taper relaxes only boxes reaching beyond --box-taper-from M (give a larger "
              "--rmax or a smaller --box-taper-from)"};
    return {"with --grid " + p.grid.name(), "only boxes have boxes"};
  case Acts::with_delta_stencil:
  case Acts::with_driver_stencil:
    return {"with --rahA 0",
            "without the horizon shift beta_GD is the whole shift: upwind-gd and upwind-full are "
            "one stencil, and B's matched term is --delta-advection's (give --rahA A, or a "
            "centred stencil)"};
  case Acts::always:
    break;
  }
  return {};
}

std::optional<std::string> Bounds::refusal(double v) const {
  const std::string why = note ? fmt::format(" ({})", note) : "";
  if (!std::isfinite(v))
    return "must be a finite number" + why;
  const bool low = lo && (lo_open ? !(v > *lo) : !(v >= *lo));
  const bool high = hi && (hi_open ? !(v < *hi) : !(v <= *hi));
  if (!low && !high)
    return std::nullopt;
  if (lo && hi)
    return fmt::format("must lie in {}{}, {}{}{}", lo_open ? '(' : '[', *lo, *hi,
                       hi_open ? ')' : ']', why);
  return fmt::format("must be {} {}{}", lo_open ? ">" : ">=", *lo, why);
}

Bounds finite() {
  return {};
}
Bounds above(double lo, const char* note) {
  return {lo, std::nullopt, true, false, note};
}
Bounds at_least(double lo, const char* note) {
  return {lo, std::nullopt, false, false, note};
}
Bounds within(double lo, double hi, const char* note) {
  return {lo, hi, false, false, note};
}
Bounds within_below(double lo, double hi, const char* note) {
  return {lo, hi, false, true, note};
}

/// The value as config-file text, or nothing for an unset optional (the file then leaves the
/// key out, which reads back as unset).
std::optional<std::string> value_text(const Params& p, const ParamSpec& spec) {
  return std::visit(
      [&](auto member) -> std::optional<std::string> {
        using T = std::decay_t<decltype(p.*member)>;
        if constexpr (std::is_same_v<T, std::string>)
          return toml_string(p.*member);
        else if constexpr (ChoiceValue<T>)
          return toml_string((p.*member).name());
        else if constexpr (is_optional_choice<T>)
          return p.*member ? std::optional(toml_string((p.*member)->name())) : std::nullopt;
        else if constexpr (std::is_same_v<T, bool>)
          return p.*member ? "true" : "false";
        else if constexpr (std::is_same_v<
                               T, std::optional<double>> || std::is_same_v<T, std::optional<int>>)
          return p.*member ? std::optional(fmt::format("{}", *(p.*member))) : std::nullopt;
        else
          return fmt::format("{}", p.*member); // shortest representation that round-trips
      },
      spec.member);
}

void check_bounds(const Params& p) {
  for (const auto& spec : param_specs())
    std::visit(
        [&](auto member) {
          using T = std::decay_t<decltype(p.*member)>;
          const std::string flag = "--" + std::string(spec.name);
          const auto check = [&](double v, const std::string& shown) {
            if (!spec.bounds)
              return;
            if (const auto why = spec.bounds->refusal(v))
              throw ParamError(flag, shown, *why);
          };
          if constexpr (ChoiceValue<T>) {
            if constexpr (!std::is_same_v<T, AhEvery>) // its number form: validate()
              require_choice(flag, p.*member);
          } else if constexpr (is_optional_choice<T>) {
            if (p.*member)
              require_choice(flag, *(p.*member));
          } else if constexpr (std::is_same_v<T, double>) {
            check(p.*member, num(p.*member));
          } else if constexpr (std::is_same_v<T, int>) {
            check(p.*member, std::to_string(p.*member));
          } else if constexpr (std::is_same_v<T, std::optional<double>>) {
            if (p.*member)
              check(*(p.*member), num(*(p.*member)));
          } else if constexpr (std::is_same_v<T, std::optional<int>>) {
            if (p.*member)
              check(*(p.*member), std::to_string(*(p.*member)));
          }
        },
        spec.member);
}

void copy_into(const Params& p, EvolutionConfig& c) {
  for (const auto& spec : param_specs())
    std::visit(
        [&](auto member, auto field) {
          using T = std::decay_t<decltype(p.*member)>;
          if constexpr (!std::is_same_v<decltype(field), std::monostate>) {
            if constexpr (std::is_same_v<std::decay_t<decltype(field(c))>, T>)
              field(c) = p.*member;
            else
              throw std::logic_error("--" + std::string(spec.name)
                                     + "'s row puts it into a field of another type");
          }
        },
        spec.member, spec.into);
}

} // namespace gbssn1d
