#include "config/same_run.hpp"

#include "config/config_file.hpp"
#include "config/flag_table.hpp"
#include "core/text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <type_traits>

namespace gbssn1d {

namespace {

/// `p` with the value of `spec` as an unset flag would resolve it (resolve(), given the other
/// flags of `p`).
ResolvedParams with_default(const Params& p, const ParamSpec& spec) {
  Params q = p;
  const Params unset;
  std::visit([&](auto member) { q.*member = unset.*member; }, spec.member);
  return resolve(q);
}

/// A value as a user gives it on the command line ("0.6", "gauss", a path; "" for a switch).
std::string shown(const Params& p, const ParamSpec& spec) {
  return std::visit(
      [&](auto member) -> std::string {
        using T = std::decay_t<decltype(p.*member)>;
        if constexpr (std::is_same_v<T, std::string>)
          return printable(p.*member);
        else if constexpr (ChoiceValue<T>)
          return (p.*member).name();
        else if constexpr (is_optional_choice<T>)
          return p.*member ? (p.*member)->name() : "";
        else if constexpr (std::is_same_v<T, bool>)
          return "";
        else if constexpr (std::is_same_v<
                               T, std::optional<double>> || std::is_same_v<T, std::optional<int>>)
          return p.*member ? fmt::format("{}", *(p.*member)) : "";
        else
          return fmt::format("{}", p.*member);
      },
      spec.member);
}

} // namespace

std::vector<IdleFlags> idle_flags(const ResolvedParams& p) {
  std::vector<IdleFlags> groups;
  for (const auto& spec : param_specs()) {
    if (acts(spec.acts, p) || value_text(p, spec) == value_text(with_default(p, spec), spec))
      continue;
    const auto [because, instead] = idle_because(spec.acts, p);
    auto group = std::find_if(groups.begin(), groups.end(),
                              [&](const IdleFlags& g) { return g.because == because; });
    if (group == groups.end())
      group = groups.insert(groups.end(), IdleFlags{because, instead, {}, {}});
    group->flags.push_back(spec.name);
    const std::string value = shown(p, spec);
    group->given.push_back(fmt::format("--{}{}{}", spec.name, value.empty() ? "" : " ", value));
  }
  return groups;
}

namespace {

/// Each rule's key, or keys (auto's profile and width are chosen together).
const std::vector<std::vector<std::string>>& rules() {
  static const std::vector<std::vector<std::string>> r{
      {"eta"},       {"kappa1"},    {"kappa1-hole"},
      {"norm-rmax"}, {"levels"},    {"box-taper"},
      {"rah-rcut"},  {"rah-taper"}, {"rah-profile", "rah-width"}};
  return r;
}

} // namespace

const std::vector<std::string>& rule_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const auto& names : rules())
      k.insert(k.end(), names.begin(), names.end());
    return k;
  }();
  return keys;
}

std::vector<std::string> rule_valued_keys(const Params& p) {
  // each rule's keys reset and resolved again from the others
  std::vector<std::string> keys;
  for (const auto& names : rules()) {
    Params q = p;
    const Params unset;
    std::vector<const ParamSpec*> specs;
    for (const auto& name : names) {
      const auto spec = std::find_if(param_specs().begin(), param_specs().end(),
                                     [&](const ParamSpec& s) { return s.name == name; });
      specs.push_back(&*spec);
      std::visit([&](auto member) { q.*member = unset.*member; }, spec->member);
    }
    try {
      q = resolve(q).flags();
    } catch (const ParamError&) { // (not a rule's value: the rule refuses the others)
      continue;
    }
    // (a rule's value, not the unset flag's own default: a run without the shift keeps auto)
    if (std::all_of(specs.begin(), specs.end(),
                    [&](const ParamSpec* s) {
                      const auto given = value_text(p, *s);
                      return given && given == value_text(q, *s);
                    })
        && std::any_of(specs.begin(), specs.end(), [&](const ParamSpec* s) {
             return value_text(p, *s) != value_text(unset, *s);
           }))
      keys.insert(keys.end(), names.begin(), names.end());
  }
  return keys;
}

std::string rule_values_line(const Params& p) {
  const std::vector<std::string> keys = rule_valued_keys(p);
  return keys.empty() ? std::string()
                      : fmt::format("{}{}\n", rule_values_mark, fmt::join(keys, ", "));
}

std::string IdleFlags::warning() const {
  return fmt::format("{} {} nothing {}: {}", fmt::join(given, ", "),
                     given.size() == 1 ? "does" : "do", because, instead);
}

Params effective(const ResolvedParams& p) {
  Params e = p.flags();
  for (const auto& spec : param_specs())
    if (!acts(spec.acts, p))
      e = with_default(e, spec).flags();
  e.out.clear();
  e.force = false;
  return e;
}

std::string run_key(const ResolvedParams& p) {
  return config_text(effective(p));
}

} // namespace gbssn1d
