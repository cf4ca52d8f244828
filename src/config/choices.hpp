// The choice flags' values: each a value of its enum that knows its spelling, from one table
// of names per flag. The names exist only where flags and configuration files are read
// (Choice::parse) and where text is written (Choice::name: config.toml, headers, messages);
// the rest of the code compares enums.
#pragma once

#include "gbssn/horizon_shift_params.hpp"
#include "gbssn/rhs_params.hpp"
#include "initial_data/initial_data_params.hpp"
#include "mesh/time_interpolation_kind.hpp"

#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace gbssn1d {

/// The names a choice flag accepts and what each stands for: one table serves the reading of
/// the flag, its validation, its message and its writing, so they cannot drift apart.
template <class E>
using Choices = std::initializer_list<std::pair<std::string_view, E>>;

/// The name of `value` among `choices` (each value has one).
template <class E>
std::string_view choice_name(const Choices<E>& choices, E value) {
  for (const auto& [n, v] : choices)
    if (v == value)
      return n;
  throw std::logic_error("a choice without a name");
}

/// --grid: the radial grid. Box-in-box refinement is its own choice here; its levels are
/// uniform grids (GridKind::uniform) and its boxes a RefinementSettings.
enum class RadialGrid { uniform, sinh, boxes };

/// --ah-every's word forms; a number n stands for every n steps.
enum class SearchEvery { substage, step, extrapolated };

inline const Choices<RadialGrid> grid_choices{
    {"uniform", RadialGrid::uniform}, {"sinh", RadialGrid::sinh}, {"boxes", RadialGrid::boxes}};
inline const Choices<InitialDataKind> id_choices{
    {"wormhole", InitialDataKind::wormhole},
    {"maximal-trumpet", InitialDataKind::maximal_trumpet},
    {"1log-trumpet", InitialDataKind::onelog_trumpet},
    {"flat", InitialDataKind::flat}};
inline const Choices<InitialLapse> lapse0_choices{{"one", InitialLapse::one},
                                                  {"precollapsed", InitialLapse::precollapsed}};
inline const Choices<ShiftProfile> profile_choices{{"auto", ShiftProfile::automatic},
                                                   {"rational", ShiftProfile::rational},
                                                   {"rational3", ShiftProfile::rational3},
                                                   {"gauss", ShiftProfile::gauss},
                                                   {"gauss3", ShiftProfile::gauss3}};
inline const Choices<Taper> taper_choices{{"quartic", Taper::quartic}, {"step", Taper::step}};
inline const Choices<ShiftNormal> normal_choices{{"conformal", ShiftNormal::conformal},
                                                 {"unit", ShiftNormal::unit},
                                                 {"smooth", ShiftNormal::smooth}};
inline const Choices<mesh::TimeInterpolation> time_interp_choices{
    {"rk-stages", mesh::TimeInterpolation::rk_stages},
    {"dense", mesh::TimeInterpolation::dense_output},
    {"quadratic", mesh::TimeInterpolation::quadratic}};
inline const Choices<Formulation> formulation_choices{{"bssn", Formulation::bssn},
                                                      {"z4c", Formulation::z4c}};
inline const Choices<Matter> matter_choices{{"none", Matter::none}, {"scalar", Matter::scalar}};
inline const Choices<Volume> volume_choices{{"lagrangian", Volume::lagrangian},
                                            {"eulerian", Volume::eulerian}};
/// --shift: the Gamma-driver, or none (beta = 0 for all time).
enum class ShiftCondition { gamma_driver, zero };
inline const Choices<ShiftCondition> shift_choices{{"gamma-driver", ShiftCondition::gamma_driver},
                                                   {"zero", ShiftCondition::zero}};
inline const Choices<fd::Upwind> upwind_choices{{"lopsided", fd::Upwind::lopsided},
                                                {"biased", fd::Upwind::biased}};
inline const Choices<AdvectionStencil> stencil_choices{
    {"upwind-gd", AdvectionStencil::upwind_gd},
    {"upwind-full", AdvectionStencil::upwind_full},
    {"centred", AdvectionStencil::centred}};
/// B's driver term also takes `matched` (gbssn/rhs.hpp).
inline const Choices<AdvectionStencil> driver_stencil_choices{
    {"matched", AdvectionStencil::matched},
    {"upwind-gd", AdvectionStencil::upwind_gd},
    {"upwind-full", AdvectionStencil::upwind_full},
    {"centred", AdvectionStencil::centred}};

/// --rah-variant: the study's inconsistent implementations, of the equations
/// (HorizonShiftParams::Variant) or of when h_AH is searched (HorizonSearchSettings::Schedule).
enum class ShiftVariant {
  consistent,
  no_shift_derivatives,
  no_shift_second_derivatives,
  delta_rhs_from_gd,
  driver_full_shift,
  midstep_update,
  box_substage,
};
inline const Choices<ShiftVariant> variant_choices{
    {"consistent", ShiftVariant::consistent},
    {"no-shift-derivatives", ShiftVariant::no_shift_derivatives},
    {"no-shift-second-derivatives", ShiftVariant::no_shift_second_derivatives},
    {"delta-rhs-from-gd", ShiftVariant::delta_rhs_from_gd},
    {"driver-full-shift", ShiftVariant::driver_full_shift},
    {"midstep-update", ShiftVariant::midstep_update},
    {"box-substage", ShiftVariant::box_substage}};
inline const Choices<SearchEvery> search_every_words{{"substage", SearchEvery::substage},
                                                     {"step", SearchEvery::step},
                                                     {"extrapolated", SearchEvery::extrapolated}};

/// A value of a choice flag: one of `table`'s values, or a text that names none of them as it
/// was given (a flag is read whole before it is validated: validate() refuses it, naming the
/// flag and the choices). Compared as its enum; spelled by its table.
template <class E, const Choices<E>& table>
class Choice {
public:
  Choice(E value) : value_(value) {}
  /// The value `text` names, or a choice that names none (kept as `text`).
  static Choice parse(std::string_view text) {
    for (const auto& [n, v] : table)
      if (n == text)
        return Choice(v);
    Choice unknown;
    unknown.unknown_ = std::string(text);
    return unknown;
  }
  /// Whether it names one of the choices (validate() refuses it otherwise).
  bool known() const { return value_.has_value(); }
  /// The value; only for a known choice (after validate()).
  E value() const {
    if (!value_)
      throw std::logic_error("the value of a choice that names none (not validated)");
    return *value_;
  }
  /// The name as the flag takes it: the table's, or the text given if it names no choice.
  std::string name() const { return value_ ? std::string(choice_name(table, *value_)) : unknown_; }
  friend bool operator==(const Choice& c, E value) { return c.value_ == value; }
  friend bool operator==(const Choice&, const Choice&) = default;

private:
  Choice() = default;
  std::optional<E> value_;
  std::string unknown_; ///< the text given, if it names no choice
};

using GridChoice = Choice<RadialGrid, grid_choices>;
using InitialDataChoice = Choice<InitialDataKind, id_choices>;
using LapseChoice = Choice<InitialLapse, lapse0_choices>;
using ProfileChoice = Choice<ShiftProfile, profile_choices>;
using TaperChoice = Choice<Taper, taper_choices>;
using NormalChoice = Choice<ShiftNormal, normal_choices>;
using TimeInterpChoice = Choice<mesh::TimeInterpolation, time_interp_choices>;
using UpwindChoice = Choice<fd::Upwind, upwind_choices>;
using ShiftChoice = Choice<ShiftCondition, shift_choices>;
using FormulationChoice = Choice<Formulation, formulation_choices>;
using VolumeChoice = Choice<Volume, volume_choices>;
using MatterChoice = Choice<Matter, matter_choices>;
using StencilChoice = Choice<AdvectionStencil, stencil_choices>;
using DriverStencilChoice = Choice<AdvectionStencil, driver_stencil_choices>;
using VariantChoice = Choice<ShiftVariant, variant_choices>;

/// --ah-every: a word form, a number of steps (in its one spelling: 05 and 5 are the same run),
/// or a text that is neither, kept for validate()'s message. `step` and `1` search alike but
/// are recorded as given.
class AhEvery {
public:
  AhEvery(SearchEvery word) : word_(word) {}
  /// A whole number (config/numbers.hpp's grammar), else a word, else the text as given
  /// (config/params.cpp).
  static AhEvery parse(std::string_view text);
  /// The number of steps, if given as a number (any whole number; validate() wants >= 1).
  std::optional<long> steps() const { return steps_; }
  /// Whether it names a schedule: a word, or a number >= 1.
  bool valid() const { return steps_ ? *steps_ >= 1 : word_.known(); }
  /// The text config.toml records: the word, the number, or the text given.
  std::string name() const { return steps_ ? std::to_string(*steps_) : word_.name(); }
  friend bool operator==(const AhEvery& a, SearchEvery word) {
    return !a.steps_ && a.word_ == word;
  }
  friend bool operator==(const AhEvery&, const AhEvery&) = default;

private:
  using Word = Choice<SearchEvery, search_every_words>;
  Word word_;                 ///< when not a number
  std::optional<long> steps_; ///< when a number
};

} // namespace gbssn1d
