#include "config/config_file.hpp"

#include "config/numbers.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <concepts>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace gbssn1d {

namespace {

/// A choice flag's value (config/choices.hpp): read from its name, written as its name.
template <class T>
concept ChoiceValue = requires(const T& value, std::string_view text) {
  { T::parse(text) } -> std::same_as<T>;
  { value.name() } -> std::same_as<std::string>;
};
/// A choice flag whose unset value stands for a rule (resolve_defaults).
template <class T>
inline constexpr bool is_optional_choice = false;
template <ChoiceValue C>
inline constexpr bool is_optional_choice<std::optional<C>> = true;

/// One run parameter: its flag (without "--"), where it lives in Params, group and help.
/// The same table drives the CLI11 options and the config file, so they cannot drift apart.
struct ParamSpec {
  const char* name;
  std::variant<int Params::*, double Params::*, std::optional<double> Params::*,
               std::optional<int> Params::*, std::string Params::*, bool Params::*,
               GridChoice Params::*, TimeInterpChoice Params::*, InitialDataChoice Params::*,
               LapseChoice Params::*, UpwindChoice Params::*, std::optional<TaperChoice> Params::*,
               ProfileChoice Params::*, NormalChoice Params::*, DriverStencilChoice Params::*,
               StencilChoice Params::*, AhEvery Params::*, VariantChoice Params::*>
      member;
  const char* group;
  const char* help;
};

/// The grid, initial data, gauge, numerics, times and output cadences.
std::vector<ParamSpec> evolution_specs() {
  return {
      {"N", &Params::N, "Grid", "number of cells"},
      {"rmax", &Params::rmax, "Grid", "outer radius"},
      {"grid", &Params::grid, "Grid",
       "radial grid: uniform | sinh | boxes (box-in-box mesh refinement: --levels boxes, box l "
       "covering r <= rmax/2^l with --N cells, Berger-Oliger subcycling)"},
      {"levels", &Params::levels, "Grid",
       "--grid boxes: number of boxes (refinement levels); default max(2, 1 + "
       "floor(log2(rmax/4M)))"},
      {"time-interp", &Params::time_interp, "Grid",
       "--grid boxes: a fine box's boundary in time: rk-stages (RK4 stage values of the coarse "
       "step, 4th order) | dense (RK4 dense output) | quadratic (three coarse time levels with "
       "buffer zones, as Carpet and BAM)"},
      {"no-subcycling", &Params::no_subcycling, "Grid",
       "--grid boxes: every box steps with the finest box's dt (no Berger-Oliger subcycling)"},
      {"box-taper", &Params::box_taper, "Grid",
       "--grid boxes: the outermost fraction F of a fine box's cells (round(F N) cells) is "
       "relaxed smoothly towards its parent at every synchronisation (a tapered buffer that "
       "absorbs what the parent cannot carry), 0 ... 0.5; 0: off"},
      {"box-taper-from", &Params::box_taper_from, "Grid",
       "--grid boxes: --box-taper only on the boxes that reach beyond this radius, in units "
       "of M"},
      {"dr-inner", &Params::dr_inner, "Grid",
       "innermost cell width of the sinh grid at N = 400; it fixes the map r(x), so at N "
       "cells every spacing is 400/N times that grid's (doubling --N halves every spacing)"},
      {"id", &Params::id, "Initial data", "wormhole | maximal-trumpet | 1log-trumpet"},
      {"M", &Params::M, "Initial data", "black-hole mass"},
      {"lapse0", &Params::lapse0, "Initial data",
       "initial lapse of the wormhole: one | precollapsed"},
      {"eta", &Params::eta, "Gauge",
       "Gamma-driver damping eta (1/M); default 2/M, 1/M for a shrink of wormhole data "
       "(--rahA != 0, --rah0 < 0.8304 M)"},
      {"advective-shift", &Params::advective_shift, "Gauge",
       "add the advection brackets of (G2)/(G3) (moving-puncture shift)"},
      {"non-advective-lapse", &Params::non_advective_lapse, "Gauge",
       "1+log without advection: d_t alpha = -2 alpha K"},
      {"cfl", &Params::cfl, "Numerics",
       "dt = cfl * smallest spacing, in (0, 1] (measured: errors unchanged from 0.25 on every "
       "grid, boxes included; unstable from 0.8)"},
      {"ko-sigma", &Params::ko_sigma, "Numerics", "Kreiss-Oliger dissipation strength, in [0, 1]"},
      {"fd-order", &Params::fd_order, "Numerics",
       "order of the finite differences: 2 | 4 | 6 | 8 (derivatives, upwind advection, and "
       "dissipation of the (order+2)-th difference; boxes: 2 | 4 | 6)"},
      {"upwind", &Params::upwind, "Numerics",
       "stencil of every advection term beta d_r f: lopsided (order fd-order, as moving-puncture "
       "codes) | biased (order fd-order + 1, one point more upwind than downwind: at 4th order "
       "1.5-8 times lower errors from M/12 (horizon mass, H), but up to 7 times higher on a "
       "trumpet at M/8 and 1.5 times on a shrink to 0.6 M; docs/horizon-shift-study.md Sec. 7.4)"},
      {"chi-floor", &Params::chi_floor, "Numerics",
       "after every RK4 step chi is raised to at least this (0: off); wormhole data otherwise "
       "cross chi = 0 at the innermost cell during the lapse collapse"},
      {"tmax", &Params::tmax, "Time", "final time; 0 writes the initial data only"},
      {"dt-series", &Params::dt_series, "Time", "time between rows of timeseries.dat"},
      {"dt-profiles", &Params::dt_profiles, "Time", "time between blocks of profiles.dat"},
      {"checkpoint-every", &Params::checkpoint_every, "Output",
       "simulated time between checkpoints in OUT/checkpoint.bin, for `gbssn1d resume OUT` "
       "(0: none; SIGTERM, SIGINT, SIGHUP, SIGUSR1 and SIGUSR2 always write one)"},
  };
}

/// The norm windows, the horizon-adjusting shift (its profile, stencils, searches and study
/// variants), and the output folder.
std::vector<ParamSpec> diagnostics_and_shift_specs() {
  return {
      {"norm-rmin", &Params::norm_rmin, "Diagnostics", "inner radius of the exterior norms"},
      {"norm-rmax", &Params::norm_rmax, "Diagnostics",
       "outer radius of the exterior norms; default min(10 M, rmax/2)"},
      {"norm-Rmin", &Params::norm_Rmin, "Diagnostics",
       "areal-radius window of the *_R norms: norm-Rmin M <= R (the same place in every gauge)"},
      {"norm-Rmax", &Params::norm_Rmax, "Diagnostics", "... R <= norm-Rmax M"},
      {"norm-Rint", &Params::norm_Rint, "Diagnostics",
       "interior window of H_L2_int: areal radius R <= norm-Rint M, inside the horizon"},
      {"rahA", &Params::rahA, "Horizon", "strength A of the horizon-adjusting shift (0: off)"},
      {"rah0", &Params::rah0, "Horizon", "desired coordinate radius h of the horizon"},
      {"rah-width", &Params::rah_width, "Horizon",
       "width w of f(r), for every --rah-profile but auto"},
      {"rah-rcut", &Params::rah_rcut, "Horizon",
       "beta_H vanishes smoothly by rcut (see --rah-taper), before the outer boundary; default "
       "rmax/2 when --rahA != 0"},
      {"rah-taper", &Params::rah_taper, "Horizon",
       "how beta_H vanishes before the outer boundary: quartic (beta_H x exp(-(2r/rcut)^4): 0.94 "
       "at rcut/4, 0.37 at rcut/2, 1e-7 at rcut; its derivatives are small enough for coarse "
       "boxes) | step (C-infinity step from 1 at rcut/2 to 0 at rcut; large derivatives: "
       "convergence lost on boxes with rmax 128); default quartic when --rahA != 0"},
      {"rah-ramp", &Params::rah_ramp, "Horizon",
       "T: the strength grows as rahA (1 - exp(-(t/T)^2)); 0: full strength from t = 0"},
      {"rah-profile", &Params::rah_profile, "Horizon",
       "f(r), q = r/w: auto (rational with w = 3 max(rah0, M) to stretch, rah0 >= 0.8304 M; gauss "
       "with "
       "w = 1 M to shrink; "
       "--rah-width is then not used) | rational q/(1+q^2) (published) | rational3 "
       "q^3/(1+q^4) | gauss (q/2)exp((1-q^2)/2) | gauss3 (q^3/2)exp(3(1-q^2)/2)"},
      {"rah-normal", &Params::rah_normal, "Horizon",
       "s^r: conformal 1/sqrt(a) (smooth at the puncture) | unit sqrt(chi/a) (published; "
       "~|r| at a trumpet's puncture) | smooth sqrt((chi+chi_s)/a)"},
      {"rah-chi-smooth", &Params::rah_chi_smooth, "Horizon",
       "chi_s of --rah-normal smooth: the kink of sqrt(chi) at the puncture is rounded where "
       "chi ~ chi_s"},
      {"rah-hAH-file", &Params::rah_hAH_file, "Horizon",
       "open loop: h_AH(t) from the t and r_ah columns of a horizon.dat (no searches)"},
      {"driver-advection", &Params::driver_advection, "Numerics",
       "stencil of beta_GD d_r Delta^r in B's driver: matched (Delta^r's own term minus beta_H "
       "d_r Delta^r centred: stable at every spacing) | upwind-gd (published; with the horizon "
       "shift it grows at the grid scale at a rate ~ |beta_H|/dr: a blow-up whose onset time "
       "falls with the spacing) | upwind-full | centred"},
      {"delta-advection", &Params::delta_advection, "Numerics",
       "stencil of beta d_r Delta^r in d_t Delta^r: upwind-full | upwind-gd | centred"},
      {"ah-every", &Params::ah_every, "Horizon",
       "horizon search: substage (every RK stage), step, or a number of steps"},
      {"ah-tmin", &Params::ah_tmin, "Horizon", "no horizon searches before this time"},
      {"ah-tmax", &Params::ah_tmax, "Horizon", "no horizon searches after this time"},
      {"ah-tol", &Params::ah_tol, "Horizon",
       "root-finder tolerance of the horizon radius; at most 1e-3 x the smallest cell width"},
      {"rah-variant", &Params::rah_variant, "Horizon",
       "consistent (the method); for the study only: no-shift-derivatives, "
       "no-shift-second-derivatives, delta-rhs-from-gd, driver-full-shift, midstep-update, "
       "box-substage (boxes: each box its own latest h_AH)"},
      {"out", &Params::out, "Output", "output directory (refused if it exists and is not empty)"},
      {"force", &Params::force, "Output", "write into an existing non-empty --out"},
  };
}

/// Every evolve parameter, in the order of --help and config.toml.
const std::vector<ParamSpec>& param_specs() {
  static const std::vector<ParamSpec> specs = [] {
    std::vector<ParamSpec> all = evolution_specs();
    const std::vector<ParamSpec> more = diagnostics_and_shift_specs();
    all.insert(all.end(), more.begin(), more.end());
    return all;
  }();
  return specs;
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

/// The rule a flag's unset value stands for, shown by --help as its default.
const std::map<std::string, std::string>& default_rules() {
  static const std::map<std::string, std::string> rules{
      {"eta", "2/M (1/M: wormhole shrinks)"},
      {"norm-rmax", "min(10 M, rmax/2)"},
      {"ah-tmax", "none"},
      {"rah-taper", "quartic"},
      {"levels", "max(2, 1 + floor(log2(rmax/4M)))"},
      {"box-taper", "0.5 on boxes"}};
  return rules;
}

/// A numeric option bound to `target` (int, double or an optional double) and read by the one
/// number reader (config/numbers.hpp), not by CLI11's, which reads leading zeros as octal; a bad
/// value is a ParamError naming the option's first name. --help shows the target's value (an
/// unset optional shows none).
template <class T>
CLI::Option* number_option(CLI::App& app, const std::string& names, T& target,
                           const std::string& help) {
  using Number = std::conditional_t<std::is_same_v<T, int> || std::is_same_v<T, std::optional<int>>,
                                    int, double>;
  const std::string flag = names.substr(0, names.find(','));
  CLI::Option* opt = app.add_option_function<std::string>(
      names,
      [&target, flag](const std::string& text) { target = parse_number<Number>(flag, text); },
      help);
  if constexpr (std::is_same_v<T, std::optional<double>> || std::is_same_v<T, std::optional<int>>) {
    if (target)
      opt->default_str(fmt::format("{}", *target));
  } else {
    opt->default_str(fmt::format("{}", target));
  }
  return opt->type_name(std::is_same_v<Number, int> ? "INT" : "FLOAT");
}

} // namespace

void add_options(CLI::App& app, Params& p) {
  for (const auto& spec : param_specs()) {
    const std::string flag = std::string("--") + spec.name;
    std::visit(
        [&](auto member) {
          using T = std::decay_t<decltype(p.*member)>;
          CLI::Option* opt;
          if constexpr (std::is_same_v<T, bool>) {
            opt = app.add_flag(flag, p.*member, spec.help);
          } else if constexpr (std::is_same_v<T, std::string>) {
            opt = app.add_option(flag, p.*member, spec.help)->capture_default_str();
          } else if constexpr (ChoiceValue<T>) {
            auto& target = p.*member;
            opt = app.add_option_function<std::string>(
                         flag, [&target](const std::string& text) { target = T::parse(text); },
                         spec.help)
                      ->type_name("TEXT")
                      ->default_str(target.name());
          } else if constexpr (is_optional_choice<T>) {
            auto& target = p.*member;
            opt =
                app.add_option_function<std::string>(
                       flag,
                       [&target](const std::string& text) { target = T::value_type::parse(text); },
                       spec.help)
                    ->type_name("TEXT");
          } else {
            opt = number_option(app, flag, p.*member, spec.help);
          }
          opt->group(spec.group);
          if (const auto rule = default_rules().find(spec.name); rule != default_rules().end())
            opt->default_str(rule->second);
        },
        spec.member);
  }
}

CLI::Option* add_number_option(CLI::App& app, const std::string& names, int& target,
                               const std::string& help) {
  return number_option(app, names, target, help);
}

CLI::Option* add_number_option(CLI::App& app, const std::string& names, double& target,
                               const std::string& help) {
  return number_option(app, names, target, help);
}

/// A string as a TOML basic string: quoted, with '"', '\' and control characters escaped, so
/// that read_config_text() gives it back exactly (a newline or '#' in an --out included).
std::string config_text(const Params& p) {
  std::string text;
  for (const auto& spec : param_specs())
    if (const auto value = value_text(p, spec))
      text += fmt::format("{} = {}\n", spec.name, *value);
  return text;
}

/// Arguments after expanding `--config FILE` (or --config=FILE) of the evolve subcommand into
/// `--key=value` arguments placed before the command line's own, so that flags override the
/// file. CLI11 2.1 does not read config files given to a subcommand, hence this step; the file
/// is parsed by CLI11's own TOML/INI reader. Throws ParamError for a missing file or a key that
/// names no parameter.
std::vector<std::string> expand_config(const std::vector<std::string>& args,
                                       std::map<std::string, std::string>* origins) {
  std::vector<std::string> rest, from_file;
  std::map<std::string, std::string> file_of; // flag -> the file that gave it
  for (std::size_t k = 0; k < args.size(); ++k) {
    std::string path;
    if (args[k] == "--config") {
      if (k + 1 >= args.size())
        throw ParamError("--config", "''", "needs a file name");
      path = args[++k];
    } else if (args[k].rfind("--config=", 0) == 0) {
      path = args[k].substr(9);
    } else {
      rest.push_back(args[k]);
      continue;
    }
    check_input_file("--config", path);
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    if (!file && !file.eof())
      throw ParamError("--config", path, "cannot be read");
    for (const auto& [key, value] : read_config_text(text.str(), path)) {
      const auto spec = std::find_if(param_specs().begin(), param_specs().end(),
                                     [&](const ParamSpec& s) { return key == s.name; });
      if (spec == param_specs().end())
        throw ParamError("--config", path, fmt::format("unknown key '{}'", printable(key)));
      if (std::holds_alternative<bool Params::*>(spec->member) && value != "true"
          && value != "false")
        throw ParamError(
            "--config", path,
            fmt::format("key '{}' must be true or false, not '{}'", key, printable(value)));
      // Writing into an existing folder is asked for on the command line only: a recorded
      // `force = true` (a config.toml of a run made with --force) must not let a rerun with
      // that file overwrite a finished run.
      if (key == "force")
        continue;
      // "--key=" with an empty value would take the next argument as its value: pass the
      // empty value as a separate argument
      file_of["--" + key] = path;
      if (value.empty()) {
        from_file.push_back("--" + key);
        from_file.push_back("");
      } else {
        from_file.push_back(fmt::format("--{}={}", key, value));
      }
    }
  }
  if (origins) {
    // a flag on the command line overrides the file's value: its errors are the command line's
    for (const auto& a : rest)
      file_of.erase(a.substr(0, a.find('=')));
    *origins = std::move(file_of);
  }
  // the subcommand name stays first
  std::vector<std::string> out;
  if (!rest.empty())
    out.push_back(rest.front());
  out.insert(out.end(), from_file.begin(), from_file.end());
  if (rest.size() > 1)
    out.insert(out.end(), rest.begin() + 1, rest.end());
  return out;
}

const std::map<std::string, std::string>& absent_key_values() {
  static const std::map<std::string, std::string> values{{"box-taper", "0"}};
  return values;
}

namespace {

/// The "key = value" lines of a configuration text ('#' lines skipped), but the `ignored` keys.
std::map<std::string, std::string> key_values(const std::string& text,
                                              const std::vector<std::string>& ignored = {}) {
  std::map<std::string, std::string> kv;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const auto eq = line.find(" = ");
    if (line.empty() || line[0] == '#' || eq == std::string::npos)
      continue;
    const std::string key = line.substr(0, eq);
    if (std::find(ignored.begin(), ignored.end(), key) == ignored.end())
      kv[key] = line.substr(eq + 3);
  }
  return kv;
}

} // namespace

std::vector<std::string> absent_key_args(const std::string& text) {
  const auto kv = key_values(text);
  std::vector<std::string> args;
  for (const auto& [key, value] : absent_key_values())
    if (!kv.contains(key))
      args.push_back(fmt::format("--{}={}", key, value));
  return args;
}

std::vector<std::string> config_differences(const std::string& old_text,
                                            const std::string& new_text,
                                            const std::vector<std::string>& ignored) {
  const auto a = key_values(old_text, ignored), b = key_values(new_text, ignored);
  // a key missing from a text written before its parameter existed stands for what runs did
  // then: its absent_key_values() entry, else its default
  static const auto defaults = [] {
    auto d = key_values(config_text(Params{}));
    for (const auto& [key, value] : absent_key_values())
      d[key] = value;
    return d;
  }();
  std::vector<std::string> diff;
  auto value_of = [](const std::map<std::string, std::string>& kv, const std::string& key) {
    if (const auto it = kv.find(key); it != kv.end())
      return it->second;
    const auto d = defaults.find(key);
    return d == defaults.end() ? std::string("(unset)") : d->second;
  };
  std::set<std::string> keys;
  for (const auto* kv : {&a, &b})
    for (const auto& [key, value] : *kv)
      keys.insert(key);
  for (const auto& key : keys)
    if (value_of(a, key) != value_of(b, key))
      diff.push_back(fmt::format("{}: {} -> {}", key, value_of(a, key), value_of(b, key)));
  return diff;
}

bool is_parameter_name(const std::string& name) {
  return std::any_of(param_specs().begin(), param_specs().end(),
                     [&](const ParamSpec& s) { return name == s.name; });
}

Params parse_evolve_args(const std::vector<std::string>& args) {
  std::vector<std::string> expanded{"evolve"};
  expanded.insert(expanded.end(), args.begin(), args.end());
  expanded = expand_config(expanded);
  expanded.erase(expanded.begin());
  CLI::App app{"evolve"};
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  Params p;
  add_options(app, p);
  std::reverse(expanded.begin(), expanded.end());
  try {
    app.parse(expanded);
  } catch (const CLI::ParseError& e) {
    // converge and sweep pass their other flags on to evolve: one that evolve does not know, or
    // a value it cannot take, is invalid input (exit status 2) naming it, as in evolve itself
    for (const auto& a : args)
      if (a.size() > 2 && a.rfind("--", 0) == 0) {
        const std::string name = a.substr(2, a.find('=') - 2);
        if (!is_parameter_name(name) && name != "config")
          throw ParamError("--" + printable(name),
                           "is not an evolve flag (`gbssn1d evolve --help` lists them)");
      }
    std::string what = e.what();
    std::replace(what.begin(), what.end(), '\n', ' ');
    throw ParamError("argument", printable(what));
  }
  return p;
}

} // namespace gbssn1d
