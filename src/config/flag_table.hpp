// The table of evolve flags (internal to src/config): for each flag its name, where it lives in
// Params, its --help group and text, where it acts and the values it accepts (its rows:
// flag_rows.cpp). One row per flag: the CLI11 options, config files (config_file.cpp), the
// effective configuration (same_run.cpp), each flag's own refusals (check_bounds()) and, for a
// flag copied as given, its place in the evolution's configuration (copy_into()) all read it.
#pragma once

#include "config/params.hpp"

#include <concepts>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace gbssn1d {

struct EvolutionConfig; // evolution/evolution_config.hpp

/// A field of the evolution's configuration, reached through the members `path` from it
/// (at<&EvolutionConfig::rhs, &RhsParams::ko_sigma>): where a flag copied there as given goes.
template <auto... path>
auto& at(EvolutionConfig& c) {
  return (c.*....*path);
}
/// Where a flag's row puts its value in the evolution's configuration (evolution_config()), for
/// a flag copied there unchanged: its row then is its whole conversion. None: param_convert.cpp
/// converts it (a rule, a unit, or a value that others depend on).
using Destination =
    std::variant<std::monostate, double& (*)(EvolutionConfig&), bool& (*)(EvolutionConfig&)>;

/// A choice flag's value (config/choices.hpp): read from its name, written as its name.
template <class T>
concept ChoiceValue = requires(const T& value, std::string_view text) {
  { T::parse(text) } -> std::same_as<T>;
  { value.name() } -> std::same_as<std::string>;
};
/// A choice flag whose unset value stands for a rule (resolve()).
template <class T>
inline constexpr bool is_optional_choice = false;
template <ChoiceValue C>
inline constexpr bool is_optional_choice<std::optional<C>> = true;

/// Where a flag acts: everywhere, or only in configurations where what it sets exists (in
/// others it does nothing, whatever its value).
enum class Acts {
  always,
  with_shift,         ///< the horizon-adjusting shift is on: shift_on()
  with_smooth_normal, ///< the shift is on with --rah-normal smooth
  on_boxes,           ///< --grid boxes
  with_box_taper,     ///< --grid boxes with a tapered buffer (--box-taper > 0)
  on_sinh,            ///< --grid sinh
  with_wormhole,      ///< --id wormhole
  with_z4c,           ///< --formulation z4c
  with_scalar,        ///< --matter scalar: scalar_on()
  with_z4c_damping,   ///< --formulation z4c with its damping on (kappa1 > 0): damped_z4c()
  with_searches,      ///< horizon searches steer the shift: shift_on(), no --rah-hAH-file
  /// --grid boxes with a fine box reaching beyond --box-taper-from (the level-1 box, rmax/2):
  /// the only boxes a taper relaxes
  with_tapered_boxes,
  /// --delta-advection: with the shift on, or centred (without beta_H, beta_GD is the whole
  /// shift: upwind-gd is upwind-full)
  with_delta_stencil,
  /// --driver-advection: with the shift on, or a stencil other than what the default becomes
  /// without beta_H (matched is --delta-advection's own term, upwind-gd and upwind-full one
  /// upwind stencil)
  with_driver_stencil,
};

/// Whether a flag that acts `where` acts in `p`.
bool acts(Acts where, const ResolvedParams& p);

/// Why a flag that acts `where` does nothing in `p` (acts(where, p) is false), as a user reads
/// it ("with --rahA 0"), and what to do instead.
std::pair<std::string, std::string> idle_because(Acts where, const ResolvedParams& p);

/// The values a number flag accepts: finite, and beyond or at `lo` and `hi` where given (open
/// or closed), with a note on why; every row's bounds are checked by check_bounds() wherever the
/// flag is given, before validate()'s checks between flags.
struct Bounds {
  std::optional<double> lo, hi;
  bool lo_open = false, hi_open = false;
  const char* note = nullptr; ///< appended to the refusal, in parentheses
  /// Why `v` is refused ("must be > 0", "must lie in [0, 1] (note)"), or nothing.
  std::optional<std::string> refusal(double v) const;
};
/// Bounds of the table's rows: any finite number; > lo; >= lo; within [lo, hi] or [lo, hi).
Bounds finite();
Bounds above(double lo, const char* note = nullptr);
Bounds at_least(double lo, const char* note = nullptr);
Bounds within(double lo, double hi, const char* note = nullptr);
Bounds within_below(double lo, double hi, const char* note = nullptr);

/// One run parameter: its flag (without "--"), where it lives in Params, group and help,
/// where it acts, and the values it accepts (a number flag's bounds; a choice flag's are its
/// table's names). The same table drives the CLI11 options, the config file and the effective
/// configuration (a flag's value where it does nothing is not part of the run), so they cannot
/// drift apart.
struct ParamSpec {
  const char* name;
  std::variant<int Params::*, double Params::*, std::optional<double> Params::*,
               std::optional<int> Params::*, std::string Params::*, bool Params::*,
               GridChoice Params::*, TimeInterpChoice Params::*, InitialDataChoice Params::*,
               LapseChoice Params::*, UpwindChoice Params::*, std::optional<TaperChoice> Params::*,
               ProfileChoice Params::*, NormalChoice Params::*, DriverStencilChoice Params::*,
               StencilChoice Params::*, AhEvery Params::*, VariantChoice Params::*,
               FormulationChoice Params::*, VolumeChoice Params::*, MatterChoice Params::*,
               ShiftChoice Params::*>
      member;
  const char* group;
  const char* help;
  Acts acts = Acts::always;
  std::optional<Bounds> bounds = std::nullopt; ///< none: checked by validate() itself
  Destination into = {}; ///< the value's field in EvolutionConfig, for a flag copied as given
};

/// Every evolve parameter, in the order of --help and config.toml.
const std::vector<ParamSpec>& param_specs();

/// The value as config-file text, or nothing for an unset optional (the file then leaves the
/// key out, which reads back as unset).
std::optional<std::string> value_text(const Params& p, const ParamSpec& spec);

/// Copies every flag whose row names its field (ParamSpec::into) into `c`.
void copy_into(const Params& p, EvolutionConfig& c);

/// Throws ParamError for the first flag in table order whose value lies outside its row's
/// bounds, or a choice flag's that names none of its choices (a rule's value as given).
void check_bounds(const Params& p);

/// The rule a flag's unset value stands for, shown by --help as its default.
const std::map<std::string, std::string>& default_rules();

} // namespace gbssn1d
